// Topological figures of a manifold mesh: boundary loops, connected components, Euler
// characteristic and genus. For a connected orientable surface with b boundary loops,
// chi = V - E + F = 2 - 2g - b; the genus of a mesh is the sum over its components.
//
// In:  a mesh and its connectivity (build_connectivity()).
// Out: plain values; nothing throws.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera {

// Each loop as its boundary halfedges in order (next() of one is the following one).
std::vector<std::vector<Index>> boundary_loops(const Connectivity& connectivity);

struct Components {
  std::size_t count = 0;
  std::vector<Index> face_component;    // per face
  std::vector<Index> vertex_component;  // per vertex, kNoIndex for a vertex in no face
};

// Faces sharing an edge are in one component (on a manifold, sharing a vertex implies that too).
Components connected_components(const Mesh& mesh, const Connectivity& connectivity);

struct SurfaceTopology {
  std::size_t vertices = 0;  // vertices in at least one face
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::size_t boundary_loops = 0;
  long euler_characteristic = 0;  // V - E + F
  long genus = 0;                 // (2 - chi - b) / 2, summed over the components
  std::size_t components = 0;
};

// The figures of one connected component, of every component, and of the whole mesh.
std::vector<SurfaceTopology> component_topology(const Mesh& mesh, const Connectivity& connectivity);
SurfaceTopology surface_topology(const Mesh& mesh, const Connectivity& connectivity);

}  // namespace tessera
