// Names of mesh elements for error messages and warnings, in one style: indices count from 0 and
// positions are printed so that the user can find the spot in a mesh editor.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace tessera {

// "vertex 17 at (0.5, 1, -2)"
std::string describe_vertex(const Mesh& mesh, Index v);
// "face 12 (vertices 3 4 9)"
std::string describe_face(const Mesh& mesh, Index f);
// "edge 3-9 at (0.5, 1, -2)-(0.5, 1, -1)"
std::string describe_edge(const Mesh& mesh, Index a, Index b);

}  // namespace tessera
