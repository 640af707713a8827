// Integer side lengths of a quad layout (thesis Sec. 8.1, (8.1)-(8.3)): the sides of the patches
// are grouped into chains of opposite sides (opposite sides of a patch must get the same number of
// quads, and a side shared by two patches is one side of both, so the relation (8.2) links whole
// strips of patches); each chain gets one positive integer n, minimising sum (l_i - lambda n)^2
// over its sides, l_i the side's length in parameter space.
//
// In:  the sides of the patches (patch_sides.h) with their parametric lengths, and the scale
//      lambda: given, from a target edge length in 3D, or from a target quad count.
// Out: per side its chain, per chain its integer, per patch its n x m, lambda.
// Throws InputError for a non-positive target or a side of zero length (naming it).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "remesh/patch_sides.h"

namespace tessera::remesh {

struct SizeTarget {
  double lambda = 1;       // parameter units per quad edge (Sec. 8.3 takes 1)
  std::size_t quads = 0;   // > 0: lambda chosen so that the quad count comes closest to this
  double edge_length = 0;  // > 0: lambda chosen for quad edges of this 3D length on average
};

struct SideLengths {
  std::vector<double> length;            // per side, parametric
  std::vector<double> length_3d;         // per side, along the surface
  std::vector<std::size_t> chain;        // per side
  std::vector<int> segments;             // per chain: its integer length
  std::vector<std::array<int, 2>> size;  // per patch: quads along its sides 0 (= 2) and 1 (= 3)
  double lambda = 1;
  std::size_t quad_count() const;
};

// The chains of opposite sides (union-find): per side its chain, numbered 0.. in side order.
std::vector<std::size_t> side_chains(const PatchSides& sides, std::size_t& chain_count);

// The sides that their chain squeezes: lambda n above `factor` times their own length (Fig. 8.1:
// a strip of patches whose sides differ much gets a grid too fine on its short sides). A layout
// side of nearly zero length (a patch that is almost a triangle on the surface) shows here, and
// the quads along it are degenerate.
std::vector<std::size_t> compressed_sides(const SideLengths& lengths, double factor = 4);

SideLengths integer_side_lengths(const PatchSides& sides, std::vector<double> length,
                                 std::vector<double> length_3d, const SizeTarget& target);

}  // namespace tessera::remesh
