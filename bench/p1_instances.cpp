// tessera_p1_instances: writes synthetic P1 instances shaped like the thesis' (Appendix B sizes:
// 1,000-2,700 edges, 14,000-81,000 conflict pairs, conflicts in bunches of edges crossing near one
// point) as <dir>/synthetic_<pairs>p_a<alpha>.json and .lp, for bench/solvers.sh. SYNTHETIC: random
// singularities on a flat torus (matching/generate.h), not port graphs of real layouts.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "matching/generate.h"
#include "matching/instance_json.h"
#include "matching/instance_lp.h"
#include "number_list.h"

namespace {

using tessera::matching::SyntheticLayoutSpec;

void write(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help") {
    std::printf(
        "usage: tessera_p1_instances <dir> [pairs,... [alphas,... [noise [mixed [seed]]]]]\n"
        "  pairs   singularity pairs per instance (default 24,30,40,50)\n"
        "  alphas  the weight's height factor (default 0,1,5,20)\n"
        "  noise, mixed, seed   SyntheticLayoutSpec fields (defaults as in generate.h, seed 1)\n");
    return argc < 2 ? 2 : 0;
  }
  try {
    const std::filesystem::path dir = argv[1];
    const std::vector<double> pairs =
        tessera::bench::number_list(argc > 2 ? argv[2] : "24,30,40,50");
    const std::vector<double> alphas = tessera::bench::number_list(argc > 3 ? argv[3] : "0,1,5,20");
    SyntheticLayoutSpec base;
    if (argc > 4) base.weight_noise = tessera::bench::number(argv[4]);
    if (argc > 5) base.mixed_crossing_rate = tessera::bench::number(argv[5]);
    if (argc > 6) base.seed = static_cast<std::uint64_t>(tessera::bench::number(argv[6]));
    std::filesystem::create_directories(dir);
    for (double p : pairs) {
      for (double alpha : alphas) {
        SyntheticLayoutSpec spec = base;
        spec.singularity_pairs = static_cast<std::uint32_t>(p);
        spec.alpha = alpha;
        // Longer separatrices on larger tori, as L_max grows with the surface (Sec. 6.8).
        spec.max_length = p < 30 ? 8.0 : 10.0;
        const auto problem = tessera::matching::synthetic_layout_instance(spec);
        char name[64];
        std::snprintf(name, sizeof name, "synthetic_%up_a%g", spec.singularity_pairs, alpha);
        write(dir / (std::string(name) + ".json"), tessera::matching::write_instance_json(problem));
        write(dir / (std::string(name) + ".lp"), tessera::matching::write_instance_lp(problem));
        std::printf("%s: %zu edges, %zu conflict pairs\n", name, problem.edges.size(),
                    problem.conflicts.size());
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessera_p1_instances: %s\n", e.what());
    return 2;
  }
  return 0;
}
