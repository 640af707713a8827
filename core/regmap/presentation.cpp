#include "regmap/presentation.h"

#include "base/error.h"

namespace tessera::regmap {

Letter inverse(Letter x) {
  switch (x) {
    case Letter::R:
      return Letter::Ri;
    case Letter::Ri:
      return Letter::R;
    case Letter::S:
      return Letter::Si;
    case Letter::Si:
      return Letter::S;
    case Letter::T:
      return Letter::T;
  }
  return x;
}

std::string to_string(Letter x) {
  switch (x) {
    case Letter::R:
      return "R";
    case Letter::Ri:
      return "R^-1";
    case Letter::S:
      return "S";
    case Letter::Si:
      return "S^-1";
    case Letter::T:
      return "T";
  }
  return "?";
}

std::string to_string(const Word& w) {
  if (w.empty()) return "1";
  std::string text;
  for (Letter x : w) {
    if (!text.empty()) text += " * ";
    text += to_string(x);
  }
  return text;
}

Word inverse(const Word& w) {
  Word result(w.rbegin(), w.rend());
  for (Letter& x : result) x = inverse(x);
  return result;
}

Word power(const Word& w, int exponent) {
  const Word base = exponent < 0 ? inverse(w) : w;
  const long long count = exponent < 0 ? -static_cast<long long>(exponent) : exponent;
  Word result;
  result.reserve(base.size() * static_cast<std::size_t>(count));
  for (long long i = 0; i < count; ++i) result.insert(result.end(), base.begin(), base.end());
  return result;
}

Word cyclically_reduced(const Word& w) {
  Word stack;
  for (Letter x : w) {
    if (!stack.empty() && stack.back() == inverse(x)) {
      stack.pop_back();
    } else {
      stack.push_back(x);
    }
  }
  std::size_t begin = 0, end = stack.size();
  while (end - begin >= 2 && stack[begin] == inverse(stack[end - 1])) {
    ++begin;
    --end;
  }
  return Word(stack.begin() + static_cast<std::ptrdiff_t>(begin),
              stack.begin() + static_cast<std::ptrdiff_t>(end));
}

std::vector<Word> defining_relators(const Presentation& presentation) {
  if (presentation.p < 2 || presentation.q < 2 || presentation.p > kMaxValence ||
      presentation.q > kMaxValence)
    throw InputError("the type {" + std::to_string(presentation.p) + "," +
                     std::to_string(presentation.q) + "} is outside 2.." +
                     std::to_string(kMaxValence) + " for p and q");
  using enum Letter;
  std::vector<Word> relators = {power({R}, presentation.p),
                                power({S}, presentation.q),
                                {T, T},
                                {R, S, R, S},
                                {R, T, R, T},
                                {S, T, S, T}};
  relators.insert(relators.end(), presentation.relators.begin(), presentation.relators.end());
  std::vector<Word> reduced;
  for (const Word& w : relators) {
    Word r = cyclically_reduced(w);
    if (!r.empty()) reduced.push_back(std::move(r));
  }
  return reduced;
}

namespace {

Letter swap_r_and_s(Letter x) {
  switch (x) {
    case Letter::R:
      return Letter::S;
    case Letter::Ri:
      return Letter::Si;
    case Letter::S:
      return Letter::R;
    case Letter::Si:
      return Letter::Ri;
    case Letter::T:
      return Letter::T;
  }
  return x;
}

}  // namespace

bool is_dual_name(const std::string& name) {
  return !name.empty() && name.back() == '\'';
}

Presentation dual(const Presentation& presentation) {
  Presentation result = presentation;
  result.p = presentation.q;
  result.q = presentation.p;
  for (Word& w : result.relators) {
    for (Letter& x : w) x = swap_r_and_s(x);
  }
  if (is_dual_name(presentation.name)) {
    result.name.pop_back();
  } else if (!presentation.name.empty()) {
    result.name += '\'';
  }
  return result;
}

}  // namespace tessera::regmap
