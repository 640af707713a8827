// Pairing a source map M with a target map T (thesis Sec. 9.5 "Matching Symmetry Groups",
// Fig. 9.17; REGMAP_NOTES.md, last section): where T's regular surface can carry M's tiling.
//
// T's surface is tiled by 4E_T quarter tubes, permuted simply transitively by Sym(T) = <a, b, c>,
// the reflections in a quarter tube's sides: a in its two seams (the tube's ridge mirror), b in the
// half ring at the edge's midpoint, c in its side at the junction. In T's generators a = T*S,
// b = R*T, c = T, so R = b*c, S = c*a, T = c. The same tiling on M's surface is a quadrilateral hQ
// of M's triangle tiling in the universal cover with its sides on mirror lines
//   L1 (top seam), L2 (midpoint), L3 (bottom seam), L4 (junction),
// corners P1 = L4 L1 and P4 = L3 L4 of angle pi/q_T, P2 = L1 L2 and P3 = L2 L3 of angle pi/2, where
// the reflections of Sym(M) in L1 and L3 are one element a', and a', b' (in L2), c' (in L4) satisfy
// T's relators and generate a subgroup of order exactly 4E_T. Then Sym(T) -> <a', b', c'> is an
// isomorphism phi, hQ is a fundamental domain of its image (its area is that of k = E_M / E_T flag
// triangles when the genera agree), and quarter tube g of T's surface carries phi(g) hQ.
//
// The search walks mirror lines in the cover (van Wijk's construction). Up to Sym(M), P1 is a
// corner of the fundamental triangle D0: its vertex N0 when q_T divides q_M, its face centre M0
// when q_T divides p_M; L4 is one of D0's two sides there and L1 the line pi/q_T further round
// P1 through D0. Along L1 every tiling vertex with a perpendicular mirror is a candidate P2 at
// distance x; hQ is then a Saccheri quadrilateral (equal angles at P1 and P4 make equal legs), so
// P3 lies on the perpendicular L2 at the distance y with sinh(y / 2) = cos(pi / q_T) /
// sqrt(sinh^2 x - cos^2(pi / q_T) cosh^2 x), P4 at distance x along the perpendicular L3 at P3,
// and L4 must pass through P4 at angle pi/q_T. The walk along L1 ends where y would be shorter
// than any side of D0. Every candidate is then checked in the group, and the flag triangles of hQ
// are collected by a flood fill from D0 that does not cross L1..L4.
//
// Where no three reflections pair (the Hurwitz maps, and the thesis's showcase pairs R9.3' on
// R2.1', R5.8 on R2.4, R13.2' on R3.4'), rotations may: rotation_pairing.cpp pairs Sym+(T) with
// rotations of M, Q and c Q then being geodesic quadrilaterals whose sides need not lie on M's
// mirrors (the drawing cuts M's tiling along them).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "regmap/cover.h"
#include "regmap/element_words.h"
#include "regmap/finite_group.h"
#include "regmap/isometry.h"
#include "regmap/presentation.h"
#include "regmap/triangle_tiling.h"

namespace tessera::regmap {

enum class PairingKind { Reflections, Rotations };
const char* to_string(PairingKind kind);

// A pairing in the form the drawing uses: the images x = phi(S) (the rotation by 2pi/q_T about the
// junction pole P1) and y = phi(R S) (the half-turn about P2 on the tube's midpoint) of Sym+(T)'s
// generators, and the quadrilaterals of quarter tube Q and of its mirror image c Q across the
// junction side, which share the side P4 P1. Reflection pairings also keep a', b', c' (then
// x = c' a', y = b' a', and c Q = c' hQ).
struct Pairing {
  std::string target;
  PairingKind kind = PairingKind::Reflections;
  Element x = 0, y = 0;           // the images of S and R S in Sym+(M)
  Element a = 0, b = 0, c = 0;    // Reflections: the images of T's a, b, c in Sym(M)
  std::array<Point, 4> corners;   // Q: P1..P4 in the Poincare disk (counterclockwise)
  std::array<Point, 4> mirrored;  // c Q: P1, X P2, X' P3, P4 (clockwise)
  Corner apex = kN;               // what P1 is: a vertex (kN) or a face centre (kM) of M
  // Q's shape: its longest side over its shortest (hyperbolic lengths), times one plus how far
  // its angles are from halving the cone angles at its corners; 1 is best.
  double distortion = 0.0;
};

struct PairingLimits {
  std::size_t max_steps = 2'000'000;  // triangles visited, over all candidates
  // Rotation pairings: P2, P3 within this distance of P1; 0 picks it from M's type
  // (rotation_pairing.cpp).
  double radius = 0.0;
};

struct PairingSearch {
  std::vector<Pairing> pairings;  // reflections first, least distorted first
  std::size_t candidates = 0;     // quadrilaterals that closed geometrically
  std::size_t steps = 0;          // triangles the walks visited
  bool stopped = false;           // the walks hit limits.max_steps
};

// Reflection pairings (see above), then rotation pairings (rotation_pairing.cpp) where no
// reflection pairing has the same (x, y). Throws InputError when M is not hyperbolic (its genus
// is below 2). `target` is T's presentation, `target_group` Sym(T) enumerated.
PairingSearch find_pairings(const FiniteGroup& source, const ElementWords& words,
                            const Presentation& target, const FiniteGroup& target_group,
                            const PairingLimits& limits = {});
PairingSearch find_reflection_pairings(const FiniteGroup& source, const ElementWords& words,
                                       const Presentation& target, std::size_t target_order,
                                       const PairingLimits& limits = {});
PairingSearch find_rotation_pairings(const FiniteGroup& source, const ElementWords& words,
                                     const Presentation& target, const FiniteGroup& target_group,
                                     const PairingLimits& limits = {});

// Throws InputError naming M's type when M is not hyperbolic.
void check_hyperbolic(const FiniteGroup& source);

// phi(g) for every g of Sym+(T) (T's own coset table; -1 for T's orientation-reversing
// elements), by phi(g R) = phi(g) y x^-1 and phi(g S) = phi(g) x; empty when that does not define
// a homomorphism or when it is not one to one.
std::vector<Element> rotation_images(const FiniteGroup& target, const ElementWords& source_words,
                                     Element x, Element y);

}  // namespace tessera::regmap
