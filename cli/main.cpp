// tessera: the native command line. Thin: parses arguments, calls core, prints results.
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "base/error.h"
#include "commands.h"
#include "usage.h"

namespace {

struct Command {
  const char* name;
  int (*run)(const tessera::cli::Args&);
  const char* summary;
};

constexpr Command kCommands[] = {
    {"info", tessera::cli::info_command, "print the figures of a mesh (V, E, F, genus, ...)"},
    {"convert", tessera::cli::convert_command,
     "convert a mesh between OBJ, OFF, PLY, STL, glTF/GLB"},
    {"regmap", tessera::cli::regmap_command, "regular maps: catalog, info, tiling, surface, map"},
    {"field", tessera::cli::field_command, "a cross field: singularities, Poincare-Hopf check"},
    {"param", tessera::cli::param_command, "seamless Poisson parameterization (uv per corner)"},
    {"solve", tessera::cli::solve_command, "program P1: the conflict-free min-weight matching"},
    {"reduce", tessera::cli::reduce_command, "program P1 without the edges a bound rules out"},
    {"layout", tessera::cli::layout_command, "quad layout by a perfect matching of the ports"},
    {"remesh", tessera::cli::remesh_command, "a quad mesh from the quad layout (Ch. 8)"},
    {"optimize-quads", tessera::cli::optimize_quads_command,
     "a coarser base complex of a quad mesh (Ch. 7)"},
};

void print_help() {
  std::printf("tessera: quad layouts and regular maps\n\nusage: tessera <command> [options]\n\n");
  for (const Command& c : kCommands) std::printf("  %-14s %s\n", c.name, c.summary);
  std::printf(
      "\n'tessera <command> --help' tells more. Exit codes: 0 ok, 1 internal error, "
      "2 bad input or usage.\n");
}

int run(int argc, char** argv) {
  if (argc < 2) {
    print_help();
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_help();
    return 0;
  }
  for (const Command& c : kCommands) {
    if (name == c.name) return c.run(tessera::cli::Args(argv + 2, argv + argc));
  }
  throw tessera::cli::UsageError("unknown command '" + name + "'; run 'tessera --help'");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const tessera::InputError& e) {
    std::fprintf(stderr, "tessera: error (%s): %s\n", e.kind(), e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "tessera: error: out of memory; the input is too large for this machine\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessera: internal error: %s\n", e.what());
    return 1;
  }
}
