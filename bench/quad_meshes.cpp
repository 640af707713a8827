// tessera_quad_meshes <mesh> [alphas,...] [peer.obj ...]: Tessera's quad meshes (thesis Ch. 8)
// beside the peers' quad meshes of the same surface at matched quad counts (issue 39 "Bench").
// Each peer mesh is measured with the same figures (remesh/quad_quality.h; its own vertex
// normals stand in for the surface's in the flip test), then the layout of <mesh> is computed
// once per alpha (default 5,10,20) and remeshed with --quads set to the peer's count. Prints one
// row per mesh: quads, irregular vertices, min and mean scaled Jacobian, quads with a scaled
// Jacobian <= 0, flipped quads, max and mean angle deviation from 90 degrees.
#include <cstdio>
#include <string>
#include <vector>

#include "field/design.h"
#include "layout/charts.h"
#include "layout/quad_layout.h"
#include "mesh/connectivity.h"
#include "mesh/geometry.h"
#include "mesh/load.h"
#include "number_list.h"
#include "param/seamless_param.h"
#include "remesh/remesh.h"

namespace {

using namespace tessera;

void print_header() {
  std::printf("%-34s %7s %6s %7s %7s %6s %6s %7s %7s\n", "mesh", "quads", "irreg", "min SJ",
              "mean SJ", "SJ<=0", "flips", "max dev", "mean dv");
}

void print_row(const std::string& name, std::size_t quads, const remesh::QuadQuality& q) {
  std::printf("%-34s %7zu %6zu %7.3f %7.3f %6zu %6zu %7.1f %7.1f\n", name.c_str(), quads,
              q.irregular_vertices, q.min_scaled_jacobian, q.mean_scaled_jacobian,
              q.nonpositive_jacobian_quads, q.flipped_quads, q.max_angle_deviation,
              q.mean_angle_deviation);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: tessera_quad_meshes <mesh> [alphas,...] [peer.obj ...]\n");
    return 2;
  }
  try {
    const bool has_alphas = argc > 2 && std::string(argv[2]).find(".obj") == std::string::npos;
    const std::vector<double> alphas = bench::number_list(has_alphas ? argv[2] : "5,10,20");
    std::vector<std::string> peers(argv + (has_alphas ? 3 : 2), argv + argc);
    const Mesh mesh = triangulate(load_mesh_file(argv[1]).mesh);
    const Connectivity connectivity = build_connectivity(mesh);
    const FaceFrames frames = face_frames(mesh);
    const CrossField field =
        design_cross_field(mesh, connectivity, frames, FieldOptions{}, Progress());
    const SeamlessParam param =
        seamless_parameterization(mesh, connectivity, frames, field, ParamOptions{}, Progress());
    const layout::Charts charts{mesh, connectivity, param};
    const layout::LayoutOptions options;
    const layout::LayoutGraph graph = layout::build_layout_graph(charts, options, Progress());
    std::vector<layout::QuadLayout> layouts;
    for (double alpha : alphas)
      layouts.push_back(layout::solve_layout(charts, graph, alpha, matching::SolverKind::exact,
                                             options.limits, Progress()));
    print_header();
    for (const std::string& peer : peers) {
      const Mesh quads = load_mesh_file(peer).mesh;
      print_row(peer.substr(peer.find_last_of('/') + 1), quads.face_count(),
                remesh::quad_quality(quads, vertex_normals(quads)));
      remesh::SizeTarget target;
      target.quads = quads.face_count();
      for (std::size_t k = 0; k < alphas.size(); ++k) {
        char name[64];
        std::snprintf(name, sizeof name, "  tessera alpha %g (%zu patches)", alphas[k],
                      layouts[k].check.patch_count);
        if (!layouts[k].check.valid()) {
          std::printf("%-34s layout not valid\n", name);
          continue;
        }
        const remesh::QuadMesh q = remesh::remesh_layout(layouts[k], target);
        print_row(name, q.mesh.face_count(), q.quality);
      }
    }
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "tessera_quad_meshes: %s\n", error.what());
    return 1;
  }
}
