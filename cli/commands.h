// The `tessera` commands. Each takes its arguments (after the command name) and returns the exit
// code: 0 ok, 1 internal error, 2 bad input or usage. Errors are thrown as tessera::Error and
// turned into exit codes by main(); commands only parse arguments and call core.
#pragma once

#include <string>
#include <vector>

namespace tessera::cli {

using Args = std::vector<std::string>;

int info_command(const Args& args);
int convert_command(const Args& args);
int regmap_command(const Args& args);
int field_command(const Args& args);
int param_command(const Args& args);
int solve_command(const Args& args);
int reduce_command(const Args& args);
int layout_command(const Args& args);
int remesh_command(const Args& args);
int optimize_quads_command(const Args& args);

}  // namespace tessera::cli
