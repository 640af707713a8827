// tessera_alpha_resolve <mesh> [alphas,...]: the page's alpha slider, natively. The graph of the
// ports is built once (field, parameterization, separatrices, conflicts), then solve_layout() runs
// at each alpha on it with one ResolveCache, as the wasm session does. Prints, per alpha, the
// whole re-solve and its stages (P1 over all loop rounds, arcs and refinement, check), the rounds
// and how many of them reused a matching laid out before, the branch-and-bound nodes and the
// layout's figures (patches, validity, objective, angle RSD), then the median and the largest
// re-solve and how many took 100 ms or more. `slider` for the alphas stands for the page's 41
// positions, 0 to 20 in steps of 0.5 (web/index.html), reached three ways after the first layout:
// stepped through, each in one move, and each in one move after all were presolved
// (presolve_layout(), as the page's worker does when idle).
#include <algorithm>
#include <chrono>
#include <cmath>
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

// The alpha slider's positions in the page: 0 to 20 in steps of 0.5.
std::vector<double> slider_positions() {
  std::vector<double> alphas;
  for (int step = 0; step <= 40; ++step) alphas.push_back(0.5 * step);
  return alphas;
}

constexpr double kFirstAlpha = 5;  // the page's first layout

// The alphas by distance from `from`, the smaller first of two as far (the worker's order).
std::vector<double> nearest_first(std::vector<double> alphas, double from) {
  std::stable_sort(alphas.begin(), alphas.end(), [from](double a, double b) {
    const double da = std::abs(a - from), db = std::abs(b - from);
    return da != db ? da < db : a < b;
  });
  return alphas;
}

void print_summary(std::vector<double> totals) {
  if (totals.empty()) return;
  std::sort(totals.begin(), totals.end());
  const auto slow = std::count_if(totals.begin(), totals.end(), [](double t) { return t >= 100; });
  std::printf("%zu re-solves: median %.1f ms, largest %.1f ms, %lld of %zu took 100 ms or more\n",
              totals.size(), totals[totals.size() / 2], totals.back(), static_cast<long long>(slow),
              totals.size());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help") {
    std::printf("usage: tessera_alpha_resolve <mesh> [alphas,... (default 5,20,1,0,5) | slider]\n");
    return argc < 2 ? 2 : 0;
  }
  try {
    const std::string list = argc > 2 ? argv[2] : "5,20,1,0,5";
    const std::vector<double> alphas =
        list == "slider" ? slider_positions() : bench::number_list(list);
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
    std::printf("%6s %9s %8s %8s %8s %6s %6s %6s %5s %6s %9s %6s\n", "alpha", "total ms", "P1 ms",
                "arcs ms", "check ms", "rounds", "reused", "nodes", "|P|", "valid", "objective",
                "RSD %");
    const auto solve = [&](double alpha, layout::ResolveCache& cache) {
      const Clock::time_point begin = Clock::now();
      const layout::QuadLayout layout = layout::solve_layout(
          charts, graph, alpha, matching::SolverKind::exact, options.limits, Progress(), &cache);
      const double total = ms_since(begin);
      std::printf("%6g %9.1f %8.1f %8.1f %8.1f %6d %6d %6lld %5zu %6s %9.2f %6.2f\n", alpha, total,
                  stage_ms(layout, "P1"), stage_ms(layout, "layout"), stage_ms(layout, "check"),
                  layout.rounds(), layout.reused_rounds,
                  static_cast<long long>(layout.matching.nodes), layout.check.patch_count,
                  layout.check.valid() ? "yes" : "no", layout.matching.objective, layout.angle_rsd);
      return total;
    };
    layout::ResolveCache cache;
    std::vector<double> totals;
    if (list != "slider") {
      for (double alpha : alphas) totals.push_back(solve(alpha, cache));
      print_summary(totals);
      return 0;
    }
    std::printf("first layout:\n");
    solve(kFirstAlpha, cache);
    const layout::ResolveCache after_first = cache;
    std::printf("stepped from 0 to 20:\n");
    for (double alpha : alphas) totals.push_back(solve(alpha, cache));
    print_summary(totals);
    std::printf("each in one move from the first layout:\n");
    totals.clear();
    for (double alpha : alphas) {
      layout::ResolveCache moved = after_first;
      totals.push_back(solve(alpha, moved));
    }
    print_summary(totals);
    std::printf("presolved as the page's worker does when idle, nearest first from alpha %g:\n",
                kFirstAlpha);
    layout::ResolveCache presolved = after_first;
    const Clock::time_point begin = Clock::now();
    for (double alpha : nearest_first(alphas, kFirstAlpha))
      layout::presolve_layout(charts, graph, alpha, matching::SolverKind::exact, options.limits,
                              Progress(), presolved);
    std::printf("%zu positions presolved in %.0f ms; then each in one move:\n", alphas.size(),
                ms_since(begin));
    totals.clear();
    for (double alpha : alphas) {
      layout::ResolveCache moved = presolved;
      totals.push_back(solve(alpha, moved));
    }
    print_summary(totals);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessera_alpha_resolve: %s\n", e.what());
    return 2;
  }
  return 0;
}
