// Conder's text format for regular maps (his RegularOrientableMaps list), one entry:
//
//   R97.10 :  Type {3,30}_40  Order 2880  mV = 2  mF = 1
//   Defining relations for automorphism group:
//   [ T^2, R^-3, (R * S)^2, (R * T)^2, (S * T)^2, (S^-2 * R * S^-1)^3 ]
//
// The name before ':' is optional; "Type {p,q}" is required; "_r" (the Petrie length), "Order N",
// "mV = a" and "mF = b" are optional; free text may follow the header line up to the '[' of the
// relator list. Relators are products ('*') of R, S, T and parenthesised products, each factor with
// an optional integer exponent ("^3", "^-2"), nested to any depth.
//
// Every malformed input throws ParseError "<source>:<line>:<column>: <what>, <what to do>".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "regmap/presentation.h"

namespace tessera::regmap {

// Where a piece of text starts in its source, for error messages (1-based).
struct TextOrigin {
  std::string source;
  std::size_t line = 1;
  std::size_t column = 1;
};

// Caps that keep a hostile or mistyped relator from expanding without bound.
inline constexpr long long kMaxExponent = 1'000'000;
inline constexpr std::size_t kMaxRelatorLetters = 1'000'000;

// "[ T^2, (R * S)^2, R^-3 ]" -> the words, in order (not reduced).
std::vector<Word> parse_relator_list(std::string_view text, const TextOrigin& origin);

// One entry of Conder's list (see above); `source` names the text in error messages and becomes the
// name when the entry has none.
Presentation parse_conder_entry(std::string_view text, const std::string& source);

}  // namespace tessera::regmap
