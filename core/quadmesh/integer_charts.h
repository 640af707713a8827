// A quad mesh as a closed parameterized surface in the integer metric (thesis Sec. 7.1, 7.2):
// every quad is the unit square of its own chart, neighbouring charts differ by a rotation in Z4
// and an integer translation, and the singularities are the irregular vertices: interior vertices
// of valence (quads around them) other than 4, boundary vertices of valence other than 2 (the
// boundary corners among them). So the layout stage's charts (layout/charts.h) see the quad mesh
// exactly: its isolines run along the mesh edges and parametric lengths count edges.
//
// The charts are triangles, as the layout stage wants them: quad q is split along the diagonal
// from its first corner into the triangles 2q and 2q + 1 (mesh/mesh.h triangulate()).
//
// In:  a pure quad mesh that validate_mesh() accepted (quad_input.h).
// Out: the triangles, their connectivity and the integer parameterization; charts() refers to
//      them (keep the IntegerCharts in place while the charts are used).
#pragma once

#include <vector>

#include "layout/charts.h"
#include "mesh/connectivity.h"
#include "mesh/mesh.h"
#include "param/seamless_param.h"

namespace tessera::quadmesh {

struct IntegerCharts {
  Mesh triangles;
  Connectivity connectivity;
  SeamlessParam param;  // h: the mean edge length of the quads (a parameter unit on the surface)

  layout::Charts charts() const { return {triangles, connectivity, param}; }
};

// The number of quads at every vertex (its valence, Sec. 7.2).
std::vector<int> quad_valences(const Mesh& quads);

// The irregular vertices of a quad mesh with their valences, by vertex number.
std::vector<Singularity> irregular_vertices(const Mesh& quads, const Connectivity& connectivity);

IntegerCharts integer_charts(const Mesh& quads, const Connectivity& connectivity);

}  // namespace tessera::quadmesh
