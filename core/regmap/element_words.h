// Words for the elements of a finite group, so that elements can be multiplied from the left too.
//
// The coset table multiplies on the right by one letter (g * x). The product g * h of two elements
// is g times a word for h; every element gets a shortest word over R, R^-1, S, S^-1, T by a
// breadth-first search from the identity, kept as a tree (parent and last letter per element).
#pragma once

#include <cstdint>
#include <vector>

#include "regmap/finite_group.h"

namespace tessera::regmap {

class ElementWords {
 public:
  explicit ElementWords(const FiniteGroup& group);

  // A shortest word w with 1 * w = g.
  Word word(Element g) const;
  // g * h.
  Element multiply(Element g, Element h) const { return group_.times(g, word(h)); }
  // g^-1.
  Element inverse(Element g) const { return group_.times(0, regmap::inverse(word(g))); }
  // g * h * g^-1.
  Element conjugate(Element g, Element h) const {
    return group_.times(multiply(g, h), regmap::inverse(word(g)));
  }
  const FiniteGroup& group() const { return group_; }

 private:
  const FiniteGroup& group_;
  std::vector<Element> parent_;
  std::vector<Letter> letter_;
};

}  // namespace tessera::regmap
