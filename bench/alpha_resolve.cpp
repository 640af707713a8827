// tessera_alpha_resolve <mesh> [alphas,...]: the page's alpha slider, natively. The graph of the
// ports is built once (field, parameterization, separatrices, conflicts), then solve_layout() runs
// at each alpha on it with one ExactSolverCache, as the wasm session does. Prints, per alpha, the
// whole re-solve and its stages (P1 over all loop rounds, arcs and refinement, check), the rounds,
// the branch-and-bound nodes and the layout's figures (patches, validity, objective, angle RSD).
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "field/design.h"
#include "layout/charts.h"
#include "layout/quad_layout.h"
#include "mesh/connectivity.h"
#include "mesh/load.h"
#include "number_list.h"
#include "param/seamless_param.h"

namespace {

using namespace tessera;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return 1000 * std::chrono::duration<double>(Clock::now() - start).count();
}

double stage_ms(const layout::QuadLayout& layout, const std::string& stage) {
  for (const layout::StageSeconds& s : layout.seconds)
    if (s.stage == stage) return 1000 * s.seconds;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help") {
    std::printf("usage: tessera_alpha_resolve <mesh> [alphas,... (default 5,20,1,0,5)]\n");
    return argc < 2 ? 2 : 0;
  }
  const std::vector<double> alphas = bench::number_list(argc > 2 ? argv[2] : "5,20,1,0,5");
  try {
    const Mesh mesh = triangulate(load_mesh_file(argv[1]).mesh);
    const Connectivity connectivity = build_connectivity(mesh);
    const FaceFrames frames = face_frames(mesh);
    Clock::time_point start = Clock::now();
    const CrossField field =
        design_cross_field(mesh, connectivity, frames, FieldOptions{}, Progress());
    const SeamlessParam param =
        seamless_parameterization(mesh, connectivity, frames, field, ParamOptions{}, Progress());
    const layout::Charts charts{mesh, connectivity, param};
    const layout::LayoutOptions options;
    const layout::LayoutGraph graph = layout::build_layout_graph(charts, options, Progress());
    std::printf("%s: |S| %zu, |E_G| %zu, |I| %zu; field to graph %.0f ms\n", argv[1],
                param.singularities.size(), graph.graph.edges.size(), graph.graph.conflicts.size(),
                ms_since(start));
    std::printf("%6s %9s %8s %8s %8s %6s %6s %5s %6s %9s %6s\n", "alpha", "total ms", "P1 ms",
                "arcs ms", "check ms", "rounds", "nodes", "|P|", "valid", "objective", "RSD %");
    matching::ExactSolverCache cache;
    for (double alpha : alphas) {
      start = Clock::now();
      const layout::QuadLayout layout = layout::solve_layout(
          charts, graph, alpha, matching::SolverKind::exact, options.limits, Progress(), &cache);
      const double total = ms_since(start);
      std::printf("%6g %9.1f %8.1f %8.1f %8.1f %6d %6lld %5zu %6s %9.2f %6.2f\n", alpha, total,
                  stage_ms(layout, "P1"), stage_ms(layout, "layout"), stage_ms(layout, "check"),
                  layout.rounds, static_cast<long long>(layout.matching.nodes),
                  layout.check.patch_count, layout.check.valid() ? "yes" : "no",
                  layout.matching.objective, layout.angle_rsd);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessera_alpha_resolve: %s\n", e.what());
    return 2;
  }
  return 0;
}
