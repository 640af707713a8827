// The input of quad-mesh structure optimization (thesis Ch. 7): a pure quad mesh.
//
// In:  a validated mesh (mesh/validate.h), the name of its source for messages.
// Out: require_quad_mesh() returns nothing and throws TopologyError for a mesh with faces that
//      are not quads, counting the triangles and the larger polygons and naming the first few
//      faces; split_into_quads() makes any polygon mesh all-quad by one Catmull-Clark split of
//      its connectivity (every n-gon into n quads through its edge midpoints and centroid), so
//      that a triangle becomes a valence-3 vertex and a pentagon a valence-5 one;
//      join_triangle_pairs() undoes what saving a quad mesh as triangles did.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace tessera::quadmesh {

void require_quad_mesh(const Mesh& mesh, const std::string& source);

// Face attributes are copied to the quads of each face.
Mesh split_into_quads(const Mesh& mesh);

// A quad mesh saved as triangles (glTF/GLB and STL hold nothing else) back as quads: the
// triangles 2k and 2k + 1 share an edge, as an exporter that splits each quad in two writes them,
// and become the quad they tile. Throws TopologyError naming the first pair that is not two
// halves of one quad (an odd triangle count, no shared edge, or a polygon among the faces).
Mesh join_triangle_pairs(const Mesh& mesh, const std::string& source);

}  // namespace tessera::quadmesh
