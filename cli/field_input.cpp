#include "field_input.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "field/design.h"
#include "field/field_io.h"
#include "mesh/readers.h"

namespace tessera::cli {

std::set<std::string> field_input_options() {
  return {"--align", "--sharp", "--curvature-weight", "--field"};
}

const char* const kFieldInputHelp =
    "  --align MODE         smooth (default): the smoothest cross field; curvature: blended\n"
    "                       with the principal curvature directions\n"
    "  --sharp DEG          edges with a dihedral angle above DEG degrees are hard constraints\n"
    "                       (default 35; 180 turns them off); boundary edges always are\n"
    "  --curvature-weight W blend weight of the curvature directions (default 10)\n"
    "  --field FILE         read the field instead: .rawfield (N F, then N 3D vectors per face)\n"
    "                       or one 'x y z' line per face\n";

CrossField field_from_arguments(const Mesh& mesh, const Connectivity& connectivity,
                                const FaceFrames& frames, const ParsedArgs& args,
                                const Progress& progress) {
  if (args.has("--field")) {
    for (const char* option : {"--align", "--sharp", "--curvature-weight"})
      if (args.has(option))
        throw UsageError(std::string(option) +
                         " designs a field and cannot be combined with --field");
    const Limits limits;
    const std::string path = args.value("--field");
    progress.step("field", 0);
    return cross_field_from_directions(mesh, connectivity, frames,
                                       read_field(read_file_bytes(path, limits), path, limits));
  }
  FieldOptions options;
  const std::string align = args.value("--align", "smooth");
  if (align == "curvature")
    options.align = FieldAlignment::curvature;
  else if (align != "smooth")
    throw UsageError("--align expects smooth or curvature, got '" + align + "'");
  options.sharp_degrees = args.number("--sharp", options.sharp_degrees);
  options.curvature_weight = args.number("--curvature-weight", options.curvature_weight);
  return design_cross_field(mesh, connectivity, frames, options, progress);
}

Mesh triangles_of(const Mesh& mesh) {
  if (mesh.is_triangle_mesh()) return mesh;
  std::fprintf(stderr, "tessera: note: polygons were split into triangles for the cross field\n");
  return triangulate(mesh);
}

std::string singularities_text(const Mesh& mesh, const CrossField& field) {
  std::map<int, int> by_valence;
  for (const Singularity& s : field.singularities) ++by_valence[s.valence];
  std::string text = std::to_string(mesh.face_count()) + " faces, " +
                     std::to_string(field.singularities.size()) + " singularities";
  std::string separator = " (";
  for (const auto& [valence, count] : by_valence) {
    text += separator + std::to_string(count) + " of valence " + std::to_string(valence);
    separator = ", ";
  }
  if (!by_valence.empty()) text += ")";
  char sums[160];
  std::snprintf(sums, sizeof sums, "\nindex sum %g, Euler characteristic %ld: Poincare-Hopf %s\n",
                field.index_sum, field.euler_characteristic,
                field.index_sum == field.euler_characteristic ? "holds" : "FAILS");
  return text + sums;
}

}  // namespace tessera::cli
