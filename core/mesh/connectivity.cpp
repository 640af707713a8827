#include "mesh/connectivity.h"

#include "base/error.h"
#include "mesh/describe.h"
#include "mesh/edge_table.h"

namespace tessera {
namespace {

const char* const kRunValidation =
    "; load the mesh through load_mesh()/validate_mesh(), which repairs or explains this";

// The cheap part of the contract, checked so that a mesh that skipped validation fails cleanly
// instead of reading out of bounds.
void check_faces_are_polygons(const Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    if (face.size() < 3)
      throw TopologyError("face " + std::to_string(f) + " has fewer than 3 corners" +
                          kRunValidation);
    for (std::size_t i = 0; i < face.size(); ++i) {
      if (face[i] >= mesh.vertex_count())
        throw TopologyError("face " + std::to_string(f) + " refers to vertex " +
                            std::to_string(face[i]) + ", beyond the last vertex" + kRunValidation);
      if (face[i] == face[(i + 1) % face.size()])
        throw TopologyError(describe_face(mesh, static_cast<Index>(f)) + " repeats a vertex" +
                            kRunValidation);
    }
  }
}

// Pairs the corner halfedges of each edge and adds a boundary halfedge to every edge with one face.
void pair_halfedges(const Mesh& mesh, const EdgeTable& table, Connectivity& c) {
  for (Index e = 0; e < table.edge_count(); ++e) {
    const auto corners = table.corners(e);
    const auto [a, b] = table.edge_vertices[e];
    if (corners.size() > 2)
      throw TopologyError("non-manifold " + describe_edge(mesh, a, b) + ": it is shared by " +
                          std::to_string(corners.size()) + " faces" + kRunValidation);
    const Index h = corners[0];
    c.edge_halfedge[e] = h;
    if (corners.size() == 2) {
      const Index g = corners[1];
      if (mesh.face_vertices[h] == mesh.face_vertices[g])
        throw TopologyError("faces on both sides of " + describe_edge(mesh, a, b) +
                            " run along it in the same direction (inconsistent orientation)" +
                            kRunValidation);
      c.twin[h] = g;
      c.twin[g] = h;
    } else {
      const Index boundary = static_cast<Index>(c.to_vertex.size());
      c.to_vertex.push_back(mesh.face_vertices[h]);
      c.next.push_back(kNoIndex);
      c.prev.push_back(kNoIndex);
      c.twin.push_back(h);
      c.face.push_back(kNoIndex);
      c.edge.push_back(e);
      c.twin[h] = boundary;
    }
  }
}

// Chains the boundary halfedges into loops. A vertex where two boundary stretches meet (a "bowtie")
// would have two outgoing boundary halfedges and no well-defined loop: that is non-manifold.
void link_boundary(const Mesh& mesh, Connectivity& c) {
  for (Index h = static_cast<Index>(c.corner_count); h < c.halfedge_count(); ++h) {
    const Index from = c.from_vertex(h);
    if (c.vertex_halfedge[from] != kNoIndex && c.is_boundary_halfedge(c.vertex_halfedge[from]))
      throw TopologyError(
          "non-manifold " + describe_vertex(mesh, from) +
          ": two separate boundary stretches meet there (the surface is pinched); split the "
          "vertex or fill the gap between the sheets in a mesh editor");
    c.vertex_halfedge[from] = h;
  }
  for (Index h = static_cast<Index>(c.corner_count); h < c.halfedge_count(); ++h) {
    const Index next = c.vertex_halfedge[c.to_vertex[h]];
    c.next[h] = next;
    c.prev[next] = h;
  }
}

// Every halfedge leaving a manifold vertex is reached by rotating around it; if not, the vertex
// joins two or more separate fans of faces.
void check_vertex_fans(const Mesh& mesh, const Connectivity& c) {
  std::vector<Index> outgoing(c.vertex_count(), 0);
  for (Index h = 0; h < c.halfedge_count(); ++h) ++outgoing[c.from_vertex(h)];
  for (Index v = 0; v < c.vertex_count(); ++v) {
    const Index start = c.vertex_halfedge[v];
    if (start == kNoIndex) continue;
    Index reached = 0;
    Index h = start;
    do {
      ++reached;
      h = c.next_outgoing(h);
    } while (h != start && reached <= outgoing[v]);
    if (reached != outgoing[v])
      throw TopologyError(
          "non-manifold " + describe_vertex(mesh, v) +
          ": it joins separate fans of faces (two sheets touch at one point); split the "
          "vertex or separate the sheets in a mesh editor");
  }
}

}  // namespace

Connectivity build_connectivity(const Mesh& mesh) {
  check_faces_are_polygons(mesh);
  const EdgeTable table = build_edge_table(mesh);
  Connectivity c;
  const std::size_t corners = mesh.corner_count();
  c.corner_count = corners;
  c.to_vertex.resize(corners);
  c.next.resize(corners);
  c.prev.resize(corners);
  c.twin.resize(corners);
  c.face.resize(corners);
  c.edge = table.corner_edge;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    for (Index h = mesh.face_offsets[f]; h < mesh.face_offsets[f + 1]; ++h) {
      const Index n = mesh.next_corner(h, f);
      c.to_vertex[h] = mesh.face_vertices[n];
      c.next[h] = n;
      c.prev[n] = h;
      c.face[h] = static_cast<Index>(f);
    }
  }
  c.edge_halfedge.resize(table.edge_count());
  pair_halfedges(mesh, table, c);

  c.vertex_halfedge.assign(mesh.vertex_count(), kNoIndex);
  link_boundary(mesh, c);
  for (Index h = 0; h < corners; ++h) {
    Index& out = c.vertex_halfedge[mesh.face_vertices[h]];
    if (out == kNoIndex) out = h;
  }
  check_vertex_fans(mesh, c);
  return c;
}

std::vector<Index> outgoing_halfedges(const Connectivity& connectivity, Index v) {
  std::vector<Index> out;
  outgoing_halfedges(connectivity, v, out);
  return out;
}

void outgoing_halfedges(const Connectivity& connectivity, Index v, std::vector<Index>& out) {
  out.clear();
  const Index start = connectivity.vertex_halfedge[v];
  if (start == kNoIndex) return;
  Index h = start;
  do {
    out.push_back(h);
    h = connectivity.next_outgoing(h);
  } while (h != start);
}

}  // namespace tessera
