// What the commands that compute a quad layout share (layout, remesh): the layout options, their
// help text, and the options they parse into.
#pragma once

#include <set>
#include <string>

#include "layout/quad_layout.h"
#include "matching/solver.h"
#include "param/seamless_param.h"
#include "usage.h"

namespace tessera::cli {

// Option names (each takes a value) to merge into a command's parse_args() set.
std::set<std::string> layout_input_options();
// Help lines describing those options.
extern const char* const kLayoutInputHelp;

// The options of tracing, growing and P1 (--rho, --length-factor, --max-*).
layout::LayoutOptions layout_options(const ParsedArgs& parsed);
// --alpha (default 5), --h, --solver. Throw UsageError for values out of range.
double layout_alpha(const ParsedArgs& parsed);
ParamOptions layout_param_options(const ParsedArgs& parsed);
matching::SolverKind layout_solver(const ParsedArgs& parsed);

}  // namespace tessera::cli
