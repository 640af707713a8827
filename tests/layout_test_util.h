// Helpers for the layout tests: a flat grid whose charts are the plane itself, each face's chart
// turned and shifted at random (so that every edge carries a transition J^r p + t), and the full
// field -> parameterization pipeline on generated shapes.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "field/design.h"
#include "layout/charts.h"
#include "layout/quad_layout.h"
#include "mesh/connectivity.h"
#include "param/poisson.h"
#include "param/seamless_param.h"

namespace tessera::test {

struct Parameterized {
  Mesh mesh;
  Connectivity connectivity;
  SeamlessParam param;
  layout::Charts charts() const { return {mesh, connectivity, param}; }
};

// The n x n unit grid in the plane z = 0, cells split along alternating diagonals.
inline Mesh flat_grid(int n) {
  Mesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.add_vertex({double(i), double(j), 0.0});
  const auto at = [n](int i, int j) { return Index(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        mesh.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        mesh.add_face({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        mesh.add_face({at(i, j), at(i + 1, j), at(i, j + 1)});
        mesh.add_face({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return mesh;
}

// uv = (x, y) turned by a random quarter turn and shifted by a random vector per face; the
// transitions follow. `singular` vertices are declared singularities of valence 4 (so that they
// get four ports on the flat grid).
inline Parameterized flat_parameterized(Mesh mesh, unsigned seed,
                                        const std::vector<Index>& singular) {
  Parameterized p{std::move(mesh), {}, {}};
  p.connectivity = build_connectivity(p.mesh);
  const Connectivity& c = p.connectivity;
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> quarter(0, 3);
  std::uniform_real_distribution<double> shift(-5, 5);
  std::vector<int> turn(p.mesh.face_count());
  std::vector<Eigen::Vector2d> offset(p.mesh.face_count());
  for (std::size_t f = 0; f < p.mesh.face_count(); ++f) {
    turn[f] = seed == 0 ? 0 : quarter(random);
    offset[f] = seed == 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(shift(random), shift(random));
  }
  p.param.h = 1;
  p.param.uv.resize(p.mesh.corner_count());
  for (Index h = 0; h < p.mesh.corner_count(); ++h) {
    const Eigen::Vector3d& x = p.mesh.positions[p.mesh.face_vertices[h]];
    p.param.uv[h] = quarter_turns({x.x(), x.y()}, turn[c.face[h]]) + offset[c.face[h]];
  }
  p.param.rotation.assign(c.halfedge_count(), 0);
  p.param.translation.assign(c.halfedge_count(), Eigen::Vector2d::Zero());
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    if (c.is_boundary_halfedge(t)) continue;
    const int r = ((turn[c.face[t]] - turn[c.face[h]]) % 4 + 4) % 4;
    p.param.rotation[h] = static_cast<std::uint8_t>(r);
    p.param.translation[h] = offset[c.face[t]] - quarter_turns(offset[c.face[h]], r);
  }
  p.param.cut.assign(c.edge_count(), 0);
  for (Index v : singular) p.param.singularities.push_back({v, 0.0, 4});
  return p;
}

// The direction in the plane of a chart direction of face f of a flat_parameterized() grid.
inline Eigen::Vector2d world_direction(const Parameterized& p, Index f, const Eigen::Vector2d& d) {
  const Index c = p.mesh.face_offsets[f];
  const Eigen::Vector2d chart = p.param.uv[c + 1] - p.param.uv[c];
  const Eigen::Vector3d x =
      p.mesh.positions[p.mesh.face_vertices[c + 1]] - p.mesh.positions[p.mesh.face_vertices[c]];
  const double turn = std::atan2(x.y(), x.x()) - std::atan2(chart.y(), chart.x());
  return {std::cos(turn) * d.x() - std::sin(turn) * d.y(),
          std::sin(turn) * d.x() + std::cos(turn) * d.y()};
}

// The parameterization of the mesh with the field that make_field(mesh, connectivity, frames)
// returns.
template <class MakeField>
Parameterized parameterized_with(Mesh mesh, const MakeField& make_field) {
  Parameterized p{std::move(mesh), {}, {}};
  p.connectivity = build_connectivity(p.mesh);
  const FaceFrames frames = face_frames(p.mesh);
  const CrossField cross = make_field(p.mesh, p.connectivity, frames);
  p.param =
      seamless_parameterization(p.mesh, p.connectivity, frames, cross, ParamOptions{}, Progress());
  return p;
}

inline Parameterized parameterized(Mesh mesh, FieldOptions field = {}) {
  return parameterized_with(
      std::move(mesh), [&field](const Mesh& m, const Connectivity& c, const FaceFrames& frames) {
        return design_cross_field(m, c, frames, field, Progress());
      });
}

// A mesh through the whole pipeline: field, parameterization, graph G, layout at alpha.
struct LayoutRun {
  Parameterized input;
  layout::LayoutGraph graph;
  layout::QuadLayout layout;
};

inline LayoutRun run_layout(Parameterized input, double alpha = 5) {
  LayoutRun run{std::move(input), {}, {}};
  const layout::LayoutOptions options;
  run.graph = layout::build_layout_graph(run.input.charts(), options, Progress());
  run.layout = layout::solve_layout(run.input.charts(), run.graph, alpha,
                                    matching::SolverKind::exact, options.limits, Progress());
  return run;
}

inline LayoutRun run_layout(Mesh mesh, double alpha = 5) {
  return run_layout(parameterized(std::move(mesh)), alpha);
}

}  // namespace tessera::test
