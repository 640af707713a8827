#include "mesh/topology.h"

namespace tessera {

std::vector<std::vector<Index>> boundary_loops(const Connectivity& c) {
  std::vector<std::vector<Index>> loops;
  std::vector<bool> seen(c.halfedge_count(), false);
  for (Index start = static_cast<Index>(c.corner_count); start < c.halfedge_count(); ++start) {
    if (seen[start]) continue;
    std::vector<Index>& loop = loops.emplace_back();
    for (Index h = start; !seen[h]; h = c.next[h]) {
      seen[h] = true;
      loop.push_back(h);
    }
  }
  return loops;
}

Components connected_components(const Mesh& mesh, const Connectivity& c) {
  Components result;
  result.face_component.assign(mesh.face_count(), kNoIndex);
  std::vector<Index> stack;
  for (Index seed = 0; seed < mesh.face_count(); ++seed) {
    if (result.face_component[seed] != kNoIndex) continue;
    const Index id = static_cast<Index>(result.count++);
    result.face_component[seed] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Index f = stack.back();
      stack.pop_back();
      for (Index h = mesh.face_offsets[f]; h < mesh.face_offsets[f + 1]; ++h) {
        const Index g = c.face[c.twin[h]];
        if (g != kNoIndex && result.face_component[g] == kNoIndex) {
          result.face_component[g] = id;
          stack.push_back(g);
        }
      }
    }
  }
  result.vertex_component.assign(mesh.vertex_count(), kNoIndex);
  for (Index h = 0; h < c.corner_count; ++h)
    result.vertex_component[mesh.face_vertices[h]] = result.face_component[c.face[h]];
  return result;
}

std::vector<SurfaceTopology> component_topology(const Mesh& mesh, const Connectivity& c) {
  const Components components = connected_components(mesh, c);
  std::vector<SurfaceTopology> parts(components.count);
  for (Index f = 0; f < mesh.face_count(); ++f) ++parts[components.face_component[f]].faces;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (components.vertex_component[v] != kNoIndex)
      ++parts[components.vertex_component[v]].vertices;
  for (Index e = 0; e < c.edge_count(); ++e)
    ++parts[components.face_component[c.face[c.edge_halfedge[e]]]].edges;
  for (const auto& loop : boundary_loops(c))
    ++parts[components.face_component[c.face[c.twin[loop.front()]]]].boundary_loops;
  for (SurfaceTopology& part : parts) {
    part.components = 1;
    part.euler_characteristic = static_cast<long>(part.vertices) - static_cast<long>(part.edges) +
                                static_cast<long>(part.faces);
    part.genus = (2 - part.euler_characteristic - static_cast<long>(part.boundary_loops)) / 2;
  }
  return parts;
}

SurfaceTopology surface_topology(const Mesh& mesh, const Connectivity& c) {
  SurfaceTopology total;
  for (const SurfaceTopology& part : component_topology(mesh, c)) {
    total.vertices += part.vertices;
    total.edges += part.edges;
    total.faces += part.faces;
    total.boundary_loops += part.boundary_loops;
    total.euler_characteristic += part.euler_characteristic;
    total.genus += part.genus;
    ++total.components;
  }
  return total;
}

}  // namespace tessera
