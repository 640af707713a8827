// `tessera regmap info|catalog|tiling|surface`: regular maps from Conder's census (thesis Ch. 9).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "base/error.h"
#include "base/file_name.h"
#include "base/limits.h"
#include "commands.h"
#include "export/print_check.h"
#include "export/write_mesh.h"
#include "mesh/readers.h"
#include "regmap/catalog.h"
#include "regmap/conder_format.h"
#include "regmap/finite_group.h"
#include "regmap/map_json.h"
#include "regmap/mapped_export.h"
#include "regmap/mapped_map.h"
#include "regmap/pairing.h"
#include "regmap/realization.h"
#include "regmap/regular_surface.h"
#include "regmap/surface_export.h"
#include "regmap/target_maps.h"
#include "regmap/tiling_svg.h"
#include "regmap/triangle_tiling.h"
#include "stderr_progress.h"
#include "usage.h"

namespace tessera::cli {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr const char* kPrintHelp =
    "  -o FILE.stl      the surface as a solid for 3D printing, in millimetres: scaled to\n"
    "                   --print-size MM (the largest side, default 100), outward facing, on\n"
    "                   z = 0; checked for holes, self-intersections and walls thinner than\n"
    "                   --wall MM (default 1; the solid's thickness at every vertex)\n";

// Print size and wall of `parsed` (export/print_check.h); refused unless the output is an STL.
PrintOptions print_options(const ParsedArgs& parsed, const std::string& output) {
  PrintOptions options;
  const bool stl = lowercase_extension(output) == "stl";
  if (!stl && (parsed.has("--print-size") || parsed.has("--wall")))
    throw UsageError("--print-size and --wall are for an STL file to print (-o FILE.stl)");
  options.size_mm = parsed.number("--print-size", options.size_mm);
  options.wall_mm = parsed.number("--wall", options.wall_mm);
  return options;
}

// Writes the scene to `output` (an STL as the checked solid to print); returns the print check
// as JSON, null for the other formats.
Json write_scene(const std::string& output, const Scene& scene, const PrintOptions& print) {
  if (lowercase_extension(output) != "stl") {
    write_file_bytes(output, encode_scene(scene, output));
    return nullptr;
  }
  const PrintCheck check = check_print(scene.mesh, print, stderr_progress());
  write_file_bytes(output, encode_mesh(print_mesh(scene.mesh, check), output));
  return print_check_json(check);
}

// The print check in words, for the terminal.
void print_print_check(const Json& check) {
  if (check.is_null()) return;
  const auto& extent = check["extent_mm"];
  std::printf("  printed %.1f x %.1f x %.1f mm; thinnest wall %.2f mm (at least %.2f asked)\n",
              extent[0].get<double>(), extent[1].get<double>(), extent[2].get<double>(),
              check["thinnest_mm"].get<double>(), check["wall_mm"].get<double>());
  if (check["printable"].get<bool>())
    std::printf("  printable: closed, oriented, no self-intersections, no thinner wall\n");
  for (const auto& problem : check["problems"])
    std::printf("  not printable: %s\n", problem.get<std::string>().c_str());
}

constexpr const char* kCatalogFile = "regmaps/catalog_g2-101.tsv";

constexpr const char* kRegmapHelp =
    "usage: tessera regmap <subcommand> [options]\n"
    "\n"
    "Regular maps: the symmetry group <R, S, T | R^p, S^q, T^2, (RS)^2, (RT)^2, (ST)^2, ...> of a\n"
    "map from Conder's census (genus 2-101 shipped), enumerated into its flags.\n"
    "\n"
    "  info <map>      |G|, V, E, F, genus, type, Petrie length and the time it took\n"
    "  catalog         list the shipped maps, filtered by genus or type\n"
    "  tiling <map>    draw the map's fundamental polygon Tri(G) with its boundary pairs as SVG\n"
    "  surface <map>   build the map's regular surface: its edge graph tubified (GLB, PLY, OBJ)\n"
    "  map <map>       draw the map on the regular surface of a target map of its genus\n"
    "  realize         pair every catalog map (and dual) with its best target: the manifest\n"
    "\n"
    "<map> is a catalog name (R3.1, or R3.1' for the dual) or a file holding one entry in "
    "Conder's\n"
    "text format ('R3.1 : Type {3,7}_8 Order 336' and the relators '[ T^2, ... ]').\n"
    "The catalog is read from $TESSERA_DATA_DIR/regmaps/, else from data/ next to the binary, "
    "else\n"
    "from the source tree it was built from.\n"
    "'tessera regmap <subcommand> --help' tells more.\n";

constexpr const char* kInfoHelp =
    "usage: tessera regmap info <map> [--json] [--max-cosets N] [--max-seconds S]\n"
    "\n"
    "Enumerates the map's symmetry group (Todd-Coxeter) and prints its figures.\n"
    "  <map>            a catalog name (R3.1, R2.4') or a presentation file in Conder's format\n"
    "  --json           print {name, p, q, order, vertices, edges, faces, genus, petrie, seconds}\n"
    "  --max-cosets N   largest coset table (rows) before giving up (default 4000000)\n"
    "  --max-seconds S  longest enumeration before giving up (default 20)\n"
    "  --max-file-bytes N  largest presentation file read (default 1500000000)\n";

constexpr const char* kCatalogHelp =
    "usage: tessera regmap catalog [--genus G] [--type p,q] [--json]\n"
    "\n"
    "Lists the shipped maps (name, genus, type, Petrie length, |Aut|, V, E, F).\n"
    "  --genus G    only maps of genus G\n"
    "  --type p,q   only maps of type {p,q}; a type with p > q lists the duals (R3.1' for {7,3})\n"
    "  --json       print a JSON array of the rows\n";

constexpr const char* kTilingHelp =
    "usage: tessera regmap tiling <map> -o tiling.svg [--json] [--max-cosets N] [--max-seconds S]\n"
    "\n"
    "Grows the map's fundamental polygon (thesis Sec. 9.3, Fig. 9.8): one triangle (pi/p, pi/q,\n"
    "pi/2) per element of its group, face by face from the centre of the Poincare disk; the\n"
    "polygon's boundary edges are paired by the group. Writes an SVG with the triangles\n"
    "coloured by face and each boundary pair numbered; prints the polygon's figures.\n"
    "Torus maps are drawn in the plane, spherical (Platonic) maps on two hemispheres.\n"
    "  -o FILE          the SVG to write (required)\n"
    "  --json           print {name, geometry, triangles, boundary_pairs, polygon_vertices,\n"
    "                   polygon_edges, polygon_euler, boundary_cycles, seconds}\n"
    "  --max-triangles N  largest group drawn (default 250000)\n"
    "  --max-cosets N, --max-seconds S, --max-file-bytes N   as for 'tessera regmap info'\n";

constexpr const char* kSurfaceHelp =
    "usage: tessera regmap surface <map> [-o surface.glb|.ply|.obj|.stl] [--base platonic|relax]\n"
    "                              [--json] [options]\n"
    "\n"
    "Builds the map's regular surface (thesis Sec. 9.2-9.6): its edge graph placed in space and\n"
    "tubified - tubes for edges, junctions for vertices, holes for faces - a closed surface of\n"
    "genus E - V + 1 tiled by 4E quarter tubes, one per element of the map's group. Checks it:\n"
    "closed, oriented, genus, the relations of the quarter-tube group A, B, C read off the mesh;\n"
    "counts its self-intersections (intersecting triangle pairs).\n"
    "  -o FILE          write the surface: .glb (quarter tubes coloured, per-face _TILE,\n"
    "                   figures in extras), .ply (integer face property 'tile'), .obj, .off\n"
    "  --base B         platonic: the symmetric base (a double cover of a Platonic solid, or\n"
    "                   one or two junctions); relax: the spring relaxation from the Jemisphere\n"
    "                   (Sec. 9.4). Default: the symmetric base when the map has one, else the\n"
    "                   relaxation - replaced by the spine placement (junctions on an axis,\n"
    "                   tubes on cylinders) when the relaxed surface crosses itself and the\n"
    "                   spine's crosses itself less (graphs of up to 64 junctions)\n"
    "  --json           print {genus, euler_characteristic, quarter_tubes, closed, oriented,\n"
    "                   self_intersections, relations_hold, seconds, ...}\n"
    "  --tube-radius R  tube radius, in tube lengths (default: 0.15, thinner for q > 6)\n"
    "  --roundness X    fillet between neighbouring tubes at a junction, in tube radii\n"
    "                   (default 1)\n"
    "  --smoothness N   quads across a quarter tube, 2..32 (default 4)\n"
    "  --iterations N   relaxation iterations (default 400; up to 400 more while tubes touch)\n"
    "  --no-self-intersections   skip the self-intersection count\n"
    "  --max-faces N    largest mesh built (default 8000000)\n"
    "  --max-triangles N, --max-cosets N, --max-seconds S, --max-file-bytes N\n"
    "                   as for 'tessera regmap tiling'\n";

constexpr const char* kMapHelp =
    "usage: tessera regmap map <map> [--on <target>] [-o map.glb|.ply|.obj|.stl] [--json]\n"
    "                          [options]\n"
    "\n"
    "Draws the map (the source, genus g) on the regular surface of a target map of surface genus\n"
    "g (thesis Sec. 9.5-9.6): Platonic maps (Tetrahedron, Cube, Octahedron, Dodecahedron,\n"
    "Icosahedron), hosohedra {2,n}, torus maps {4,4}_(b,0), {4,4}_(b,b), {3,6}_(b,0), "
    "{3,6}_(b,b),\n"
    "{6,3}_(b,0), {6,3}_(b,b), and the catalog's maps and duals. A pairing maps the target's\n"
    "symmetries to the source's: its reflections a, b, c to reflections whose mirrors bound the\n"
    "quarter tube as a geodesic quadrilateral of the source's tiling, or, where no reflections\n"
    "pair (the Klein quartic), its rotations S and R S to rotations of the source whose centres\n"
    "bound two quarter tubes. The source's faces, edges and vertices are carried into every\n"
    "quarter tube. Checks on the mesh: V, E, F found, every face a disk, the quarter tubes cover\n"
    "the source's flags once, closed, oriented, genus, self-intersections.\n"
    "  --on T           the target (default: every target of the map's genus, the best ranked:\n"
    "                   no hosohedron, reflections before rotations, least distorted). The\n"
    "                   pairings are drawn in that order, surfaces free of self-intersections\n"
    "                   first, until one passes the checks\n"
    "  -o FILE          .glb (faces coloured, per-face _FACE and _TILE, edges as lines, the\n"
    "                   pairing in extras), .ply (integer face properties 'face', 'tile'), .obj\n"
    "  --json           print {source, target, genus, V, E, F, faces_are_disks, covers_once,\n"
    "                   closed, oriented, self_intersections, symmetries_verified, seconds, ...}\n"
    "  --subdivisions N subdivisions of the template's pieces before they are laid over the\n"
    "                   quarter tube's grid (default 2)\n"
    "  --max-steps N    work limit of the pairing search per target, triangles walked\n"
    "                   (default 2000000)\n"
    "  --radius R       rotation pairings: corners within this hyperbolic distance of P1\n"
    "                   (default: 1.5 past the map's vertex-to-face-centre distance, in [4.5, 8])\n"
    "  --no-self-intersections   skip the self-intersection count\n"
    "  --max-cosets N, --max-seconds S, --max-file-bytes N   as for 'tessera regmap info'\n";

constexpr const char* kRealizeHelp =
    "usage: tessera regmap realize [--genus G | --genus G..H] [-o realizations.json] [--json]\n"
    "\n"
    "The automatic realization (thesis Sec. 9.6): every catalog map of the genus range and its\n"
    "dual is paired with every target of its genus (see 'tessera regmap map --help'). The\n"
    "pairings are drawn in ranked order, those on surfaces free of self-intersections first,\n"
    "until one draws the map right (V, E, F found, faces disks, flags covered once, closed,\n"
    "oriented, of its genus); that one is kept, the other targets found are listed, and a map\n"
    "none of whose pairings draws right is unrealized (each surface is built once). Prints the\n"
    "counts; -o writes the manifest\n"
    "{version, counts, maps: [{source, genus, p, q, order, V, E, F, target, target_kind, score,\n"
    "others, surface: {base, self_intersections}, pairing}], unrealized: [{source, genus, p, q,\n"
    "order, V, E, F}]} that the page reads instead of searching, and the gallery its cards from.\n"
    "  --genus G..H    the genus range (default 2..101)\n"
    "  --max-steps N   work limit of each pairing search (default 2000000)\n"
    "  --radius R      rotation pairings: corners within this hyperbolic distance (default: as\n"
    "                  for 'tessera regmap map')\n"
    "  --json          print the counts as JSON\n";

bool wants_help(const Args& args) {
  for (const std::string& a : args) {
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

fs::path executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// $TESSERA_DATA_DIR, then data/ next to the binary (an installed layout), then the source tree.
std::string catalog_path() {
  if (const char* dir = std::getenv("TESSERA_DATA_DIR"); dir && *dir)
    return (fs::path(dir) / kCatalogFile).string();
  const fs::path beside = executable_dir() / "data" / kCatalogFile;
  if (fs::exists(beside)) return beside.string();
  return (fs::path(TESSERA_DATA_DIR) / kCatalogFile).string();
}

Limits limits_from(const ParsedArgs& parsed) {
  Limits limits;
  limits.max_coset_table = parsed.count("--max-cosets", limits.max_coset_table);
  limits.max_coset_seconds = parsed.number("--max-seconds", limits.max_coset_seconds);
  limits.max_file_bytes = parsed.count("--max-file-bytes", limits.max_file_bytes);
  limits.max_tiling_triangles = parsed.count("--max-triangles", limits.max_tiling_triangles);
  if (limits.max_coset_seconds <= 0) throw UsageError("--max-seconds expects a positive number");
  return limits;
}

// A catalog name, or else a presentation file.
regmap::Presentation resolve_map(const std::string& map, const Limits& limits) {
  std::error_code ec;
  if (fs::is_regular_file(map, ec)) {
    const std::vector<std::uint8_t> bytes = read_file_bytes(map, limits);
    return regmap::parse_conder_entry(
        std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), map);
  }
  if (map.empty() || map[0] != 'R')
    throw InputError("'" + map +
                     "' is neither a presentation file nor a catalog name (R3.1, R2.4')");
  return regmap::presentation_of(regmap::find_map(regmap::read_catalog(catalog_path()), map));
}

// The options every command on one map takes, plus `extra` ones with values.
ParsedArgs parse_one_map(const Args& args, const std::string& command,
                         std::set<std::string> extra = {}) {
  extra.insert({"--max-cosets", "--max-seconds", "--max-file-bytes"});
  ParsedArgs parsed = parse_args(args, extra, {"--json"}, command);
  if (parsed.positional.size() != 1)
    throw UsageError("'tessera " + command + "' takes one map (a catalog name or a file); " +
                     "run 'tessera " + command + " --help'");
  return parsed;
}

int info(const Args& args) {
  if (wants_help(args)) {
    std::fputs(kInfoHelp, stdout);
    return 0;
  }
  const ParsedArgs parsed = parse_one_map(args, "regmap info");
  const Limits limits = limits_from(parsed);
  const regmap::Presentation presentation = resolve_map(parsed.positional[0], limits);
  const auto start = std::chrono::steady_clock::now();
  const regmap::FiniteGroup group = regmap::enumerate_group(presentation, limits);
  const regmap::MapFigures f = regmap::map_figures(group);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  regmap::check_stated_figures(presentation, f);
  if (parsed.has("--json")) {
    const Json out = regmap::map_info_json(presentation, f, seconds);
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  std::printf("%s: type {%d,%d}, |G| = %zu\n", presentation.name.c_str(), presentation.p,
              presentation.q, f.order);
  std::printf("  V = %zu, E = %zu, F = %zu, V - E + F = %lld\n", f.vertices, f.edges, f.faces,
              f.euler);
  if (f.orientable) {
    std::printf("  genus %d\n", f.genus);
  } else {
    std::printf("  non-orientable\n");
  }
  std::printf("  Petrie length %zu\n  enumerated in %.3f s\n", f.petrie, seconds);
  return 0;
}

// "7,3" -> {7, 3}
std::pair<int, int> parse_type_option(const std::string& text) {
  int p = 0, q = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d,%d%c", &p, &q, &tail) != 2 || p < 2 || q < 2)
    throw UsageError("--type expects p,q (e.g. --type 3,7), got '" + text + "'");
  return {p, q};
}

int catalog(const Args& args) {
  if (wants_help(args)) {
    std::fputs(kCatalogHelp, stdout);
    return 0;
  }
  const ParsedArgs parsed = parse_args(args, {"--genus", "--type"}, {"--json"}, "regmap catalog");
  if (!parsed.positional.empty())
    throw UsageError(
        "'tessera regmap catalog' takes no positional arguments; run "
        "'tessera regmap catalog --help'");
  const bool by_genus = parsed.has("--genus");
  const auto genus = static_cast<int>(parsed.count("--genus", 0));
  const bool by_type = parsed.has("--type");
  const auto [p, q] = by_type ? parse_type_option(parsed.value("--type")) : std::pair{0, 0};
  std::vector<regmap::CatalogEntry> rows;
  for (const regmap::CatalogEntry& entry : regmap::read_catalog(catalog_path())) {
    if (by_genus && entry.genus != genus) continue;
    if (!by_type) {
      rows.push_back(entry);
    } else if (entry.p == p && entry.q == q) {
      rows.push_back(entry);
    } else if (entry.p == q && entry.q == p) {
      rows.push_back(regmap::dual(entry));
    }
  }
  if (parsed.has("--json")) {
    Json out = Json::array();
    for (const auto& e : rows) out.push_back(regmap::catalog_row_json(e));
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  std::printf("%-10s %5s %-10s %6s %7s %6s %6s %6s\n", "name", "genus", "type", "petrie", "|Aut|",
              "V", "E", "F");
  for (const auto& e : rows) {
    const std::string type = "{" + std::to_string(e.p) + "," + std::to_string(e.q) + "}";
    std::printf("%-10s %5d %-10s %6d %7zu %6zu %6zu %6zu\n", e.name.c_str(), e.genus, type.c_str(),
                e.petrie, e.order, e.vertices, e.edges, e.faces);
  }
  std::fprintf(stderr, "%zu maps\n", rows.size());
  return 0;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int tiling(const Args& args) {
  if (wants_help(args)) {
    std::fputs(kTilingHelp, stdout);
    return 0;
  }
  const ParsedArgs parsed = parse_one_map(args, "regmap tiling", {"-o", "--max-triangles"});
  const std::string output = parsed.value("-o");
  if (output.empty())
    throw UsageError(
        "'tessera regmap tiling' needs -o FILE.svg; run 'tessera regmap tiling --help'");
  const Limits limits = limits_from(parsed);
  const regmap::Presentation presentation = resolve_map(parsed.positional[0], limits);
  const auto start = std::chrono::steady_clock::now();
  const regmap::FiniteGroup group = regmap::enumerate_group(presentation, limits);
  const regmap::MapFigures f = regmap::map_figures(group);
  regmap::check_stated_figures(presentation, f);
  const regmap::TriangleTiling tiling = regmap::build_tiling(group, limits);
  const regmap::PolygonShape shape = regmap::polygon_shape(tiling);
  const double seconds = seconds_since(start);
  const std::string title = presentation.name + " {" + std::to_string(presentation.p) + "," +
                            std::to_string(presentation.q) + "}: " + std::to_string(f.order) +
                            " triangles, " + std::to_string(tiling.pairs.size()) +
                            " boundary pairs";
  const std::string svg = regmap::tiling_svg(group, tiling, title);
  write_file_bytes(output, std::vector<std::uint8_t>(svg.begin(), svg.end()));
  if (parsed.has("--json")) {
    const Json out = {{"name", presentation.name},
                      {"geometry", regmap::to_string(tiling.geometry())},
                      {"triangles", f.order},
                      {"boundary_pairs", tiling.pairs.size()},
                      {"polygon_vertices", shape.vertices},
                      {"polygon_edges", shape.edges},
                      {"polygon_euler", shape.euler},
                      {"boundary_cycles", shape.boundary_cycles},
                      {"seconds", seconds}};
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  std::printf(
      "%s\n  %s geometry; polygon of %zu triangles, V - E + F = %lld, %zu boundary cycle(s)\n"
      "  %zu boundary edge pairs; %.3f s\n  wrote %s\n",
      title.c_str(), regmap::to_string(tiling.geometry()), f.order, shape.euler,
      shape.boundary_cycles, tiling.pairs.size(), seconds, output.c_str());
  return 0;
}

regmap::SurfaceBase parse_base(const ParsedArgs& parsed) {
  if (!parsed.has("--base")) return regmap::SurfaceBase::Automatic;
  const std::string base = parsed.value("--base");
  if (base == "platonic") return regmap::SurfaceBase::Platonic;
  if (base == "relax") return regmap::SurfaceBase::Relax;
  throw UsageError("--base expects platonic or relax, got '" + base + "'");
}

regmap::SurfaceOptions surface_options(const ParsedArgs& parsed) {
  regmap::SurfaceOptions options;
  options.base = parse_base(parsed);
  options.tube.radius = parsed.number("--tube-radius", options.tube.radius);
  options.tube.roundness = parsed.number("--roundness", options.tube.roundness);
  options.tube.smoothness = static_cast<int>(
      parsed.count("--smoothness", static_cast<std::size_t>(options.tube.smoothness)));
  options.relax.iterations = static_cast<int>(
      parsed.count("--iterations", static_cast<std::size_t>(options.relax.iterations)));
  options.find_self_intersections = !parsed.has("--no-self-intersections");
  return options;
}

int surface(const Args& args) {
  if (wants_help(args)) {
    std::fputs(kSurfaceHelp, stdout);
    std::fputs(kPrintHelp, stdout);
    return 0;
  }
  const ParsedArgs parsed =
      parse_args(args,
                 {"-o", "--base", "--tube-radius", "--roundness", "--smoothness", "--iterations",
                  "--max-faces", "--max-triangles", "--max-cosets", "--max-seconds",
                  "--max-file-bytes", "--print-size", "--wall"},
                 {"--json", "--no-self-intersections"}, "regmap surface");
  if (parsed.positional.size() != 1)
    throw UsageError(
        "'tessera regmap surface' takes one map (a catalog name or a file); run "
        "'tessera regmap surface --help'");
  Limits limits = limits_from(parsed);
  limits.max_faces = parsed.count("--max-faces", limits.max_faces);
  const regmap::SurfaceOptions options = surface_options(parsed);
  const std::string output = parsed.value("-o");
  if (!output.empty()) check_mesh_format(output);
  const PrintOptions print = print_options(parsed, output);
  const regmap::Presentation presentation = resolve_map(parsed.positional[0], limits);
  const auto start = std::chrono::steady_clock::now();
  const regmap::FiniteGroup group = regmap::enumerate_group(presentation, limits);
  regmap::check_stated_figures(presentation, regmap::map_figures(group));
  const regmap::RegularSurface result =
      regmap::build_regular_surface(presentation, group, options, limits, stderr_progress());
  const double seconds = seconds_since(start);
  const Json printed =
      output.empty()
          ? Json()
          : write_scene(output, regmap::regular_surface_scene(result, presentation.name), print);
  const regmap::SurfaceStats& s = result.stats;
  if (parsed.has("--json")) {
    Json out = {{"name", presentation.name}};
    const Json stats = regmap::surface_stats_json(s);
    for (const auto& [key, value] : stats.items()) out[key] = value;
    out["seconds"] = seconds;  // with the enumeration
    if (!printed.is_null()) out["print"] = printed;
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  std::printf(
      "%s: regular surface on %s, %zu junctions, %zu tubes\n"
      "  genus %ld (V - E + F = %ld), %zu quarter tubes, %zu vertices, %zu quads\n"
      "  closed %s, oriented %s, relations of A, B, C %s\n",
      presentation.name.c_str(), s.base.c_str(), s.junctions, s.tubes, s.genus,
      s.euler_characteristic, s.quarter_tubes, s.vertices, s.faces, s.closed ? "yes" : "no",
      s.oriented ? "yes" : "no", s.relations_hold ? "hold" : "FAIL");
  for (const std::string& failed : s.failed_relations)
    std::printf("  relation fails: %s\n", failed.c_str());
  if (s.self_intersections_searched)
    std::printf("  %zu self-intersecting triangle pairs\n", s.self_intersections);
  std::printf("  %.3f s\n", seconds);
  print_print_check(printed);
  if (!output.empty()) std::printf("  wrote %s\n", output.c_str());
  return 0;
}

// --radius, or 0 (automatic) when not given.
double radius_from(const ParsedArgs& parsed) {
  if (!parsed.has("--radius")) return 0.0;
  const double r = parsed.number("--radius", 0.0);
  if (!(r > 0.5 && r <= 8.0)) throw UsageError("--radius expects a distance in (0.5, 8]");
  return r;
}

int map_on_target(const Args& args) {
  if (wants_help(args)) {
    std::fputs(kMapHelp, stdout);
    std::fputs(kPrintHelp, stdout);
    return 0;
  }
  const ParsedArgs parsed =
      parse_args(args,
                 {"-o", "--on", "--subdivisions", "--max-steps", "--radius", "--max-cosets",
                  "--max-seconds", "--max-file-bytes", "--print-size", "--wall"},
                 {"--json", "--no-self-intersections"}, "regmap map");
  if (parsed.positional.size() != 1)
    throw UsageError(
        "'tessera regmap map' takes one map (a catalog name or a file); run "
        "'tessera regmap map --help'");
  const Limits limits = limits_from(parsed);
  const std::string output = parsed.value("-o");
  if (!output.empty()) check_mesh_format(output);
  const PrintOptions print = print_options(parsed, output);
  regmap::PairingLimits pairing_limits;
  pairing_limits.max_steps = parsed.count("--max-steps", pairing_limits.max_steps);
  pairing_limits.radius = radius_from(parsed);
  regmap::MappedMapOptions options;
  options.subdivisions = static_cast<int>(parsed.count("--subdivisions", 0));
  if (options.subdivisions > 64) throw UsageError("--subdivisions expects 1..64");
  options.find_self_intersections = !parsed.has("--no-self-intersections");

  const regmap::Presentation presentation = resolve_map(parsed.positional[0], limits);
  const auto start = std::chrono::steady_clock::now();
  const regmap::FiniteGroup group = regmap::enumerate_group(presentation, limits);
  const regmap::MapFigures figures = regmap::map_figures(group);
  regmap::check_stated_figures(presentation, figures);
  if (!figures.orientable)
    throw InputError(presentation.name + " is not orientable: it has no regular surface to lie on");
  const regmap::ElementWords words(group);
  const regmap::DrawnMap map = regmap::draw_on_best_target(
      group, words, figures, presentation.name, regmap::read_catalog(catalog_path()),
      parsed.value("--on"), pairing_limits, options, limits, stderr_progress());
  const regmap::Realization& chosen = map.realization;
  const double seconds = seconds_since(start);
  const regmap::MappedMapStats& s = map.drawn.stats;
  Json out = regmap::drawn_map_json(presentation.name, figures, map, seconds);
  const Json printed =
      output.empty()
          ? Json()
          : write_scene(output, regmap::drawn_map_scene(map, presentation.name, out), print);
  if (!printed.is_null()) out["print"] = printed;
  if (parsed.has("--json")) {
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  std::printf(
      "%s drawn on the surface of %s (%s)\n"
      "  V %zu, E %zu, F %zu found (the map has %zu, %zu, %zu); faces are disks: %s\n"
      "  closed %s, oriented %s, genus %ld, quarter tubes cover the flags once: %s\n",
      presentation.name.c_str(), chosen.target.name.c_str(), map.surface.base.c_str(), s.vertices,
      s.edges, s.faces, figures.vertices, figures.edges, figures.faces,
      s.faces_are_disks ? "yes" : "no", s.closed ? "yes" : "no", s.oriented ? "yes" : "no", s.genus,
      s.covers_once ? "yes" : "no");
  if (s.self_intersections_searched)
    std::printf("  %zu self-intersecting triangle pairs\n", s.self_intersections);
  std::printf("  %.3f s\n", seconds);
  print_print_check(printed);
  if (!output.empty()) std::printf("  wrote %s\n", output.c_str());
  return 0;
}

// "G" or "G..H", within 2..101.
std::pair<int, int> parse_genus_range(const std::string& text) {
  const std::size_t dots = text.find("..");
  auto number = [&](const std::string& part) {
    if (part.empty() || part.size() > 3 ||
        !std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; }))
      throw UsageError("--genus expects G or G..H with 2 <= G <= H <= 101, not '" + text + "'");
    return std::stoi(part);
  };
  const int lo = number(text.substr(0, dots));
  const int hi = dots == std::string::npos ? lo : number(text.substr(dots + 2));
  if (lo < 2 || hi > 101 || lo > hi)
    throw UsageError("--genus expects G or G..H with 2 <= G <= H <= 101, not '" + text + "'");
  return {lo, hi};
}

// A map as the manifest names it: source, genus, p, q, |Aut| and V, E, F (the gallery's cards).
Json map_figures(const regmap::CatalogEntry& entry) {
  return {{"source", entry.name}, {"genus", entry.genus}, {"p", entry.p},     {"q", entry.q},
          {"order", entry.order}, {"V", entry.vertices},  {"E", entry.edges}, {"F", entry.faces}};
}

int realize(const Args& args) {
  if (wants_help(args)) {
    std::fputs(kRealizeHelp, stdout);
    return 0;
  }
  const ParsedArgs parsed = parse_args(
      args, {"--genus", "-o", "--max-steps", "--radius", "--max-cosets", "--max-seconds"},
      {"--json"}, "regmap realize");
  if (!parsed.positional.empty())
    throw UsageError("'tessera regmap realize' takes no map; run 'tessera regmap realize --help'");
  const auto [lo, hi] =
      parse_genus_range(parsed.has("--genus") ? parsed.value("--genus") : "2..101");
  const Limits limits = limits_from(parsed);
  regmap::PairingLimits pairing_limits;
  pairing_limits.max_steps = parsed.count("--max-steps", pairing_limits.max_steps);
  pairing_limits.radius = radius_from(parsed);
  const std::string output = parsed.value("-o");
  const auto start = std::chrono::steady_clock::now();
  const regmap::Catalog catalog = regmap::read_catalog(catalog_path());
  const std::vector<regmap::TargetMap> targets = regmap::all_targets(catalog, hi);
  regmap::TargetGroups groups(limits);
  regmap::TargetSurfaces surfaces(limits);
  Json maps = Json::array(), unrealized = Json::array();
  std::size_t sources = 0, non_hosohedral = 0, crossing_free = 0, by_reflections = 0, errors = 0,
              drawn_wrong = 0;
  regmap::MappedMapOptions drawing;
  drawing.find_self_intersections = false;  // the surface's count (TargetSurfaces)
  int highest = 0;
  std::set<std::string> seen;
  for (const regmap::CatalogEntry& row : catalog) {
    if (row.genus < lo || row.genus > hi) continue;
    for (const regmap::CatalogEntry& entry : {row, regmap::dual(row)}) {
      if (!seen.insert(entry.name).second) continue;
      ++sources;
      try {
        const regmap::FiniteGroup group =
            regmap::enumerate_group(regmap::presentation_of(entry), limits);
        const regmap::ElementWords words(group);
        regmap::RealizationSearch search =
            regmap::find_realizations(group, words, entry.genus, targets, pairing_limits, groups);
        const bool drawn =
            regmap::draw_first_right(search, group, words, regmap::map_figures(group), drawing,
                                     surfaces, groups)
                .has_value();
        drawn_wrong += search.drawn_wrong;
        if (!drawn) {
          unrealized.push_back(map_figures(entry));
          continue;
        }
        const regmap::Realization& best = search.found.front();
        const regmap::SurfaceStats& surface = surfaces.surface(best.target, groups).stats;
        Json others = Json::array();
        std::set<std::string> listed = {best.target.name};
        for (const regmap::Realization& r : search.found)
          if (listed.insert(r.target.name).second) others.push_back(r.target.name);
        Json realized = map_figures(entry);
        realized.update(
            Json{{"target", best.target.name},
                 {"target_kind", regmap::to_string(best.target.kind)},
                 {"score", best.score},
                 {"others", others},
                 {"surface",
                  {{"base", surface.base}, {"self_intersections", surface.self_intersections}}},
                 {"pairing", regmap::pairing_json(best.pairing)}});
        maps.push_back(std::move(realized));
        if (best.target.kind != regmap::TargetKind::Hosohedron) ++non_hosohedral;
        if (surface.self_intersections == 0) ++crossing_free;
        if (best.pairing.kind == regmap::PairingKind::Reflections) ++by_reflections;
        highest = std::max(highest, entry.genus);
      } catch (const Error& e) {
        ++errors;
        unrealized.push_back(map_figures(entry));
        std::fprintf(stderr, "tessera: %s: %s\n", entry.name.c_str(), e.what());
      }
      if (sources % 100 == 0)
        std::fprintf(stderr, "tessera: realize %zu maps, %zu realized, %.0f s\n", sources,
                     maps.size(), seconds_since(start));
    }
  }
  const double seconds = seconds_since(start);
  const Json counts = {{"genus", {lo, hi}},
                       {"maps", sources},
                       {"realized", maps.size()},
                       {"non_hosohedral", non_hosohedral},
                       {"self_intersection_free", crossing_free},
                       {"by_reflections", by_reflections},
                       {"by_rotations", maps.size() - by_reflections},
                       {"errors", errors},
                       {"pairings_drawn_wrong", drawn_wrong},
                       {"highest_genus", highest},
                       {"seconds", seconds}};
  if (!output.empty()) {
    const Json manifest = {{"version", 2},
                           {"generated_by", "tessera regmap realize"},
                           {"counts", counts},
                           {"maps", maps},
                           {"unrealized", unrealized}};
    const std::string text = manifest.dump() + "\n";
    write_file_bytes(output, std::vector<std::uint8_t>(text.begin(), text.end()));
  }
  if (parsed.has("--json")) {
    std::printf("%s\n", counts.dump(2).c_str());
    return 0;
  }
  std::printf(
      "genus %d..%d: %zu maps, %zu realized (%zu on non-hosohedral surfaces, %zu on surfaces free "
      "of self-intersections; %zu by reflections, %zu by rotations), highest genus %d, %.1f s\n",
      lo, hi, sources, maps.size(), non_hosohedral, crossing_free, by_reflections,
      maps.size() - by_reflections, highest, seconds);
  if (!output.empty()) std::printf("  wrote %s\n", output.c_str());
  return 0;
}

}  // namespace

int regmap_command(const Args& args) {
  if (args.empty()) {
    std::fputs(kRegmapHelp, stderr);
    return 2;
  }
  const std::string& sub = args[0];
  const Args rest(args.begin() + 1, args.end());
  if (sub == "--help" || sub == "-h" || sub == "help") {
    std::fputs(kRegmapHelp, stdout);
    return 0;
  }
  if (sub == "info") return info(rest);
  if (sub == "catalog") return catalog(rest);
  if (sub == "tiling") return tiling(rest);
  if (sub == "surface") return surface(rest);
  if (sub == "map") return map_on_target(rest);
  if (sub == "realize") return realize(rest);
  throw UsageError("unknown subcommand 'regmap " + sub + "'; run 'tessera regmap --help'");
}

}  // namespace tessera::cli
