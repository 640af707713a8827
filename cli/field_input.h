// What the commands that need a cross field share (field, param): the field options, their help
// text, the stderr progress printer, and the call that designs the field or reads it from a file.
#pragma once

#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "base/progress.h"
#include "field/cross_field.h"
#include "stderr_progress.h"
#include "usage.h"

namespace tessera::cli {

// Option names (each takes a value) to merge into a command's parse_args() set.
std::set<std::string> field_input_options();

// Help lines describing those options.
extern const char* const kFieldInputHelp;

// The field given by --field, or designed with --align / --sharp / --curvature-weight.
// Throws UsageError for contradicting or malformed options, the readers' errors for the file.
CrossField field_from_arguments(const Mesh& mesh, const Connectivity& connectivity,
                                const FaceFrames& frames, const ParsedArgs& args,
                                const Progress& progress);

// The mesh as a triangle mesh: polygons are fanned into triangles (with a note on stderr).
Mesh triangles_of(const Mesh& mesh);

// "F faces, S singularities (a of valence 3, b of valence 5, ...); index sum X, Euler
// characteristic Y: Poincare-Hopf holds" and the like.
std::string singularities_text(const Mesh& mesh, const CrossField& field);

}  // namespace tessera::cli
