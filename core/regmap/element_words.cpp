#include "regmap/element_words.h"

#include <algorithm>
#include <cstddef>

namespace tessera::regmap {

ElementWords::ElementWords(const FiniteGroup& group) : group_(group) {
  const std::size_t n = group.order();
  parent_.assign(n, -1);
  letter_.assign(n, Letter::T);
  std::vector<bool> seen(n, false);
  std::vector<Element> queue = {0};
  seen[0] = true;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const Element g = queue[k];
    for (int x = 0; x < kLetterCount; ++x) {
      const auto letter = static_cast<Letter>(x);
      const Element h = group.times(g, letter);
      if (seen[static_cast<std::size_t>(h)]) continue;
      seen[static_cast<std::size_t>(h)] = true;
      parent_[static_cast<std::size_t>(h)] = g;
      letter_[static_cast<std::size_t>(h)] = letter;
      queue.push_back(h);
    }
  }
}

Word ElementWords::word(Element g) const {
  Word w;
  for (Element e = g; e != 0; e = parent_[static_cast<std::size_t>(e)])
    w.push_back(letter_[static_cast<std::size_t>(e)]);
  std::reverse(w.begin(), w.end());
  return w;
}

}  // namespace tessera::regmap
