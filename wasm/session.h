// What one worker keeps between requests: the mesh on screen and the products computed from it, so
// that a late parameter reruns only the late stages (SPEC "Data flow"). Loading a mesh clears the
// products; computing a stage clears the ones after it.
#pragma once

#include <memory>
#include <optional>

#include "field/cross_field.h"
#include "field/face_frames.h"
#include "layout/quad_layout.h"
#include "mesh/connectivity.h"
#include "mesh/mesh.h"
#include "param/seamless_param.h"
#include "remesh/hausdorff.h"
#include "remesh/remesh.h"

namespace tessera::wasm {

struct Session {
  // The mesh as triangles (polygons fanned in the order the viewer draws them).
  std::optional<Mesh> mesh;
  std::optional<Connectivity> connectivity;
  std::optional<FaceFrames> frames;
  std::optional<CrossField> field;
  std::optional<SeamlessParam> param;
  // The quad layout: the graph of the ports (alpha-free, kept for re-solving), and what its
  // re-solves keep for the next alpha (layout/quad_layout.h), among it the layout of the last
  // alpha solved (resolve_cache.last), kept for its export.
  std::optional<layout::LayoutGraph> layout_graph;
  layout::ResolveCache resolve_cache;
  // The quad mesh of that layout (Ch. 8): what its size target does not change (made on the first
  // remesh of the layout), and the quad mesh of the last target, kept for its export.
  std::optional<remesh::RemeshPrep> remesh_prep;
  std::optional<remesh::QuadMesh> quad_mesh;
  // The mesh's side of the Hausdorff distance to its quad meshes (it points into `mesh`).
  std::unique_ptr<remesh::HausdorffReference> hausdorff;

  void set_mesh(const Mesh& shown) {
    *this = Session();
    mesh = triangulate(shown);
  }

  // A new field or parameterization makes the layout products stale.
  void clear_param() {
    param.reset();
    layout_graph.reset();
    resolve_cache = {};
    clear_quad_mesh();
  }

  // A new layout makes the quad mesh products stale.
  void clear_quad_mesh() {
    remesh_prep.reset();
    quad_mesh.reset();
  }
};

inline Session& session() {
  static Session the_session;
  return the_session;
}

}  // namespace tessera::wasm
