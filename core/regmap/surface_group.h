// The group of a regular surface, read off the built mesh (thesis Sec. 9.5, Fig. 9.15, 9.16).
//
// Each quarter tube is a tile: a disk with four sides a (at the junction), b, c, d (the next
// counterclockwise, seen from outside). Adj_x(Q) is the quarter tube across side x of Q, and
//   A = Adj_a o Adj_c   shifts Q two positions around its hole,
//   B = Adj_d o Adj_a   rotates Q around its junction,
//   C = Adj_b           shifts Q one position down the tube,
// with the relations (CBA)^2 = (BA)^2 = (CB)^2 = C^2 = 1, A^p = B^q = 1 and the extra relators of
// the map with R -> A, S -> B, T -> CB (Sym(S_g) of Sec. 9.5). Products are compositions: "BA"
// applies A first.
//
// Everything here is taken from the mesh's own connectivity and the tile of each face, not from
// the group table, so that a check of the relations is a check of the built surface. The junction
// side a is told from c by its corners: the poles of a junction touch 2q quarter tubes, the
// corners at an edge midpoint four (q >= 3).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/connectivity.h"
#include "mesh/mesh.h"
#include "regmap/presentation.h"

namespace tessera::regmap {

using Permutation = std::vector<std::int32_t>;

struct QuarterTubeAdjacency {
  Permutation a, b, c, d;  // per tile: the tile across that side
};

// Throws TopologyError naming the tile when a tile is not a disk bounded by four sides as above,
// or when `tile` has values outside 0..tiles-1 or a tile without faces.
QuarterTubeAdjacency quarter_tube_adjacency(const Mesh& mesh, const Connectivity& connectivity,
                                            const std::vector<std::int32_t>& tile,
                                            std::size_t tiles);

struct SurfaceGroup {
  Permutation a, b, c;  // A, B, C as maps tile -> tile
};

SurfaceGroup surface_group(const QuarterTubeAdjacency& adjacency);

struct RelationCheck {
  std::size_t relators = 0;           // how many were checked
  std::vector<std::string> failures;  // the relators that do not hold, written over A, B, C
  bool hold() const { return failures.empty(); }
};

// Checks the six relations of Sec. 9.5 (with p, q of the presentation) and the presentation's
// extra relators under R -> A, S -> B, T -> CB, on every tile.
RelationCheck check_relations(const SurfaceGroup& group, const Presentation& presentation);

}  // namespace tessera::regmap
