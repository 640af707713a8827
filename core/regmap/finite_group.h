// The symmetry group of a regular map as a finite group in its regular representation (thesis
// Sec. 9.1, Def. 9.2), and the figures of the map read off it.
//
// Elements are numbered 0..|G|-1, 0 the identity; element g <-> flag <-> triangle g(D0) of the
// barycentric subdivision (REGMAP_NOTES.md). Right multiplication g*x by a letter is one table
// lookup. With D0 = M0 N0 O0 (face centre, vertex, edge midpoint), R rotating about M0 and S about
// N0 (both counterclockwise), the reflections in the sides of D0 are
//   T  in M0N0,    T*S  in N0O0,    R*T  in M0O0,
// so g and g*T, g*T*S, g*R*T are the three neighbours of g's triangle. Hence:
//   vertices = cosets of <S, T>, faces = cosets of <R, T>, edges = cosets of <T*S, R*T> (the
//   order-4 stabiliser of O0), and the orientation-preserving elements are the orbit of 0 under <R,
//   S>.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/limits.h"
#include "base/progress.h"
#include "regmap/coset_table.h"
#include "regmap/presentation.h"

namespace tessera::regmap {

using Element = std::int32_t;

struct FiniteGroup {
  int p = 0;
  int q = 0;
  CosetTable table;  // row g: g*R, g*R^-1, g*S, g*S^-1, g*T

  std::size_t order() const { return table.rows(); }
  Element times(Element g, Letter x) const { return table.at(g, x); }
  Element times(Element g, const Word& w) const;
};

// Enumerates <R, S, T | defining_relators(presentation)> (see coset_table.h for the limits).
FiniteGroup enumerate_group(const Presentation& presentation, const Limits& limits,
                            const Progress& progress = Progress(),
                            EnumerationStats* stats = nullptr);

// The orbits of right multiplication by the words, i.e. the left cosets g<H> of H = <words>.
// Labels are numbered in order of their smallest element, so element 0's orbit is label 0.
struct Orbits {
  std::vector<std::int32_t> label;  // per element
  std::size_t count = 0;
};
Orbits orbits(const FiniteGroup& group, const std::vector<Word>& generators);

Orbits vertex_orbits(const FiniteGroup& group);  // <S, T>
Orbits edge_orbits(const FiniteGroup& group);    // <T*S, R*T>
Orbits face_orbits(const FiniteGroup& group);    // <R, T>

// The smallest k > 0 with w^k = 1.
std::size_t element_order(const FiniteGroup& group, const Word& w);

struct MapFigures {
  std::size_t order = 0;  // |G| = 4E
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  long long euler = 0;     // V - E + F
  bool orientable = true;  // <R, S> has index 2
  int genus = 0;           // (2 - euler) / 2 when orientable
  std::size_t petrie = 0;  // order of R*S*T
};

// V, E, F counted as orbits and checked against |G|/(2q), |G|/4, |G|/(2p). Throws InputError when
// the relators collapse the map (R or S of smaller order than p or q, or a degenerate stabiliser).
MapFigures map_figures(const FiniteGroup& group);

// Throws InputError when the presentation's stated order or Petrie length differs from `figures`.
void check_stated_figures(const Presentation& presentation, const MapFigures& figures);

}  // namespace tessera::regmap
