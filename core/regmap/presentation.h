// The symmetry group of a reflexible orientable regular map as a presentation (thesis Def. 9.2):
//
//   Sym = < R, S, T | R^p, S^q, T^2, (RS)^2, (RT)^2, (ST)^2, extra relators >
//
// R rotates about a face centre (order p), S about a vertex (order q), T is a reflection. Words are
// over five letters, R, R^-1, S, S^-1, T: T is its own inverse (T^2 is always a relator), so T^-1
// is written T.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::regmap {

enum class Letter : std::uint8_t { R, Ri, S, Si, T };
inline constexpr int kLetterCount = 5;

Letter inverse(Letter x);
// "R", "R^-1", ...
std::string to_string(Letter x);

using Word = std::vector<Letter>;

// "R * S^-1 * T"; "1" for the empty word.
std::string to_string(const Word& w);
Word inverse(const Word& w);
Word power(const Word& w, int exponent);
// Cancels adjacent inverse pairs (x x^-1, and T T), also cyclically: the relator it returns
// defines the same normal closure.
Word cyclically_reduced(const Word& w);

struct Presentation {
  std::string name;            // "R3.1", "R2.4'", or a file name; may be empty
  int p = 0;                   // face size: the order of R
  int q = 0;                   // vertex valence: the order of S
  std::vector<Word> relators;  // the extra relators (the standard ones may be repeated here)
  // Figures the source states, 0 when it states none; checked against the enumeration.
  std::size_t stated_order = 0;
  int stated_petrie = 0;
};

// The largest p or q Tessera accepts: a regular map of genus g has p, q <= 4g + 2, so this covers
// every genus the census lists with room to spare, and keeps relators like S^q short.
inline constexpr int kMaxValence = 10'000;

// Every relator of Def. 9.2: R^p, S^q, (RS)^2, (RT)^2, (ST)^2, then the extra ones, cyclically
// reduced, without empty words. T^2 reduces to the empty word: it holds by construction, since the
// coset table's T column is its own inverse. Throws InputError for p or q outside 2..kMaxValence.
std::vector<Word> defining_relators(const Presentation& presentation);

// The dual map: the same group with the roles of R and S exchanged (faces become vertices), so p
// and q swap and every relator has R and S swapped. The standard relations go to standard ones
// ((RS)^2 to (SR)^2, a conjugate of it; (RT)^2 and (ST)^2 to each other), and reflexibility (T
// conjugates R to R^-1 and S to S^-1) makes the mirror image of the swapped triangle the same map.
// The name gains a prime ("R2.4" -> "R2.4'") or loses it.
Presentation dual(const Presentation& presentation);

// "R2.4'" -> true. A dual name is a catalog name with one trailing prime.
bool is_dual_name(const std::string& name);

}  // namespace tessera::regmap
