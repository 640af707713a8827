#include "mesh/validate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "base/disjoint_sets.h"
#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/describe.h"
#include "mesh/edge_table.h"
#include "mesh/geometry.h"
#include "mesh/topology.h"
#include "mesh/vertex_fans.h"
#include "mesh/weld.h"

namespace tessera {
namespace {

std::string format_number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// The flat arrays must describe faces at all before anything else can be checked.
void check_arrays(const Mesh& mesh) {
  if (mesh.face_offsets.empty() || mesh.face_offsets.front() != 0 ||
      mesh.face_offsets.back() != mesh.face_vertices.size() ||
      !std::is_sorted(mesh.face_offsets.begin(), mesh.face_offsets.end()))
    throw TopologyError(
        "the face offsets do not describe the face vertex list (they must start at "
        "0, grow, and end at its size)");
  for (const auto& [name, values] : mesh.face_attributes)
    if (values.size() != mesh.face_count())
      throw TopologyError("face attribute '" + name + "' has " + std::to_string(values.size()) +
                          " values for " + std::to_string(mesh.face_count()) + " faces");
  if (mesh.face_count() == 0)
    throw TopologyError(
        "the mesh has no faces; Tessera needs a surface mesh (is this a point cloud?)");
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_size(f) < 3)
      throw TopologyError("face " + std::to_string(f) + " has " +
                          std::to_string(mesh.face_size(f)) + " corners; a face needs at least 3");
    for (Index v : mesh.face(f))
      if (v >= mesh.vertex_count())
        throw TopologyError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                            ", but the mesh has " + std::to_string(mesh.vertex_count()) +
                            " vertices (numbered from 0)");
  }
}

void check_finite(const Mesh& mesh) {
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (!mesh.positions[v].allFinite())
      throw GeometryError("vertex " + std::to_string(v) +
                          " has a non-finite coordinate (NaN or infinity); fix or remove it in the "
                          "program that wrote the mesh");
}

bool has_repeated_vertex(std::span<const Index> face) {
  if (face.size() > 8) {  // large polygons: sorting, not comparing all pairs
    std::vector<Index> sorted(face.begin(), face.end());
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
  }
  for (std::size_t i = 0; i < face.size(); ++i)
    for (std::size_t j = i + 1; j < face.size(); ++j)
      if (face[i] == face[j]) return true;
  return false;
}

// Collapses repeated consecutive corners; drops faces left with fewer than three corners or with a
// vertex repeated elsewhere (a pinched polygon has no sensible surface).
void repair_faces(Mesh& mesh, ValidationReport& report) {
  bool clean = true;
  for (std::size_t f = 0; f < mesh.face_count() && clean; ++f)
    clean = !has_repeated_vertex(mesh.face(f));
  if (clean) return;  // the common case: nothing to copy
  Mesh repaired;
  repaired.positions = std::move(mesh.positions);
  std::vector<Index> kept_faces;
  std::vector<Index> corners;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    corners.clear();
    for (Index v : mesh.face(f))
      if (corners.empty() || corners.back() != v) corners.push_back(v);
    while (corners.size() > 1 && corners.back() == corners.front()) corners.pop_back();
    if (corners.size() < 3 || has_repeated_vertex(corners)) {
      ++report.dropped_faces;
      continue;
    }
    report.collapsed_faces += corners.size() != mesh.face_size(f);
    repaired.add_face(corners);
    kept_faces.push_back(f);
  }
  for (const auto& [name, values] : mesh.face_attributes) {
    auto& kept = repaired.face_attributes[name];
    for (Index f : kept_faces) kept.push_back(values[f]);
  }
  mesh = std::move(repaired);
}

// Counts zero-area faces; a mesh of nothing else has no surface to work on.
std::size_t count_zero_area_faces(const Mesh& mesh, double tolerance, Index& first) {
  const double diagonal = bounding_box(mesh).diagonal();
  const double threshold = tolerance * diagonal * diagonal;
  std::size_t count = 0;
  first = kNoIndex;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (face_area(mesh, f) > threshold) continue;
    if (count++ == 0) first = f;
  }
  if (count == mesh.face_count())
    throw GeometryError("all " + std::to_string(count) +
                        " faces have zero area (the vertices of each are collinear or coincide); "
                        "the mesh has no surface");
  return count;
}

void check_manifold_edges(const Mesh& mesh, const EdgeTable& table,
                          const std::vector<Index>& corner_face) {
  for (Index e = 0; e < table.edge_count(); ++e) {
    const auto corners = table.corners(e);
    if (corners.size() <= 2) continue;
    std::string faces;
    for (std::size_t i = 0; i < corners.size() && i < 4; ++i)
      faces += (i ? ", " : "") + std::to_string(corner_face[corners[i]]);
    if (corners.size() > 4) faces += ", ...";
    throw TopologyError("non-manifold " +
                        describe_edge(mesh, table.edge_vertices[e][0], table.edge_vertices[e][1]) +
                        ": it is shared by " + std::to_string(corners.size()) + " faces (" + faces +
                        "), a surface edge has at most 2; remove the extra sheets or duplicate "
                        "faces in a mesh editor");
  }
}

void reverse_face(Mesh& mesh, Index f) {
  std::reverse(mesh.face_vertices.begin() + mesh.face_offsets[f] + 1,
               mesh.face_vertices.begin() + mesh.face_offsets[f + 1]);
}

// How to orient the faces: per face whether to reverse it, or where orienting failed.
struct Orientation {
  std::vector<std::uint8_t> flip;  // per face
  // A contradiction: the face reached with both orientations, from the first face of its component,
  // across the edge of `corner`; kNoIndex when the surface is orientable.
  Index face = kNoIndex, seed = kNoIndex, corner = kNoIndex;
};

// Breadth-first over the faces of each component: a neighbour across an edge must run along it in
// the opposite direction. A contradiction means the surface is non-orientable. Within a component
// the orientation of the majority of faces wins, so that few faces are flipped.
Orientation orientation_of(const Mesh& mesh, const EdgeTable& table,
                           const std::vector<Index>& corner_face) {
  Orientation result;
  result.flip.assign(mesh.face_count(), 0);
  std::vector<signed char> flip(mesh.face_count(), -1);  // -1 unvisited, 0 keep, 1 flip
  std::vector<Index> component;
  for (Index seed = 0; seed < mesh.face_count(); ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    component.assign(1, seed);
    for (std::size_t i = 0; i < component.size(); ++i) {
      const Index f = component[i];
      for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
        const auto corners = table.corners(table.corner_edge[c]);
        if (corners.size() != 2) continue;
        const Index d = corners[0] == c ? corners[1] : corners[0];
        const Index g = corner_face[d];
        const bool same_direction = mesh.face_vertices[c] == mesh.face_vertices[d];
        const signed char wanted = static_cast<signed char>(flip[f] ^ same_direction);
        if (flip[g] < 0) {
          flip[g] = wanted;
          component.push_back(g);
        } else if (flip[g] != wanted) {
          result.face = g;
          result.seed = seed;
          result.corner = c;
          return result;
        }
      }
    }
    std::size_t to_flip = 0;
    for (Index f : component) to_flip += flip[f];
    const bool invert = 2 * to_flip > component.size();
    for (Index f : component) result.flip[f] = static_cast<bool>(flip[f]) != invert;
  }
  return result;
}

std::size_t orient_faces(Mesh& mesh, const EdgeTable& table,
                         const std::vector<Index>& corner_face) {
  const Orientation orientation = orientation_of(mesh, table, corner_face);
  if (orientation.face != kNoIndex)
    throw TopologyError(
        "the surface is not orientable (like a Moebius strip or a Klein bottle): going around "
        "from face " +
        std::to_string(orientation.seed) + " to " + describe_face(mesh, orientation.face) +
        " gives it both orientations; Tessera needs an orientable surface, cut it open or "
        "rebuild it");
  std::size_t flipped = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (!orientation.flip[f]) continue;
    reverse_face(mesh, f);
    ++flipped;
  }
  return flipped;
}

// Welding (validate.h) closes cracks: only vertices on the boundary of the mesh as given are
// welded, so that a weld never collapses the interior (a short edge, a thin closed part). Even so
// a weld can join what should stay apart (two sheets along an edge, two parts at a point): every
// group of vertices welded into one whose weld breaks the surface is kept apart, and the mesh
// stays as it was there. A repair never turns a valid mesh into an invalid one.
enum class WeldBreak { non_manifold_edge, pinched_vertex, non_orientable };
constexpr std::size_t kWeldBreaks = 3;

struct BreakAt {
  Index vertex = kNoIndex;
  WeldBreak reason = WeldBreak::non_manifold_edge;
};

struct Welds {
  std::vector<Index> target;   // per vertex: the vertex it is welded into, or itself
  std::size_t kept_apart = 0;  // groups of vertices left unwelded
  std::array<std::size_t, kWeldBreaks> kept_apart_for{};  // per WeldBreak
  std::string example;  // one of them, as describe_vertex() names it in the mesh as given
};

std::vector<std::uint8_t> boundary_vertices(const Mesh& mesh) {
  const EdgeTable table = build_edge_table(mesh);
  std::vector<std::uint8_t> on_boundary(mesh.vertex_count(), 0);
  for (Index e = 0; e < table.edge_count(); ++e) {
    const auto [a, b] = table.edge_vertices[e];
    if (table.corners(e).size() == 1 && a != b) on_boundary[a] = on_boundary[b] = 1;
  }
  return on_boundary;
}

// weld_targets() among the boundary vertices.
std::vector<Index> boundary_weld_targets(const Mesh& mesh, double tolerance) {
  const std::vector<std::uint8_t> on_boundary = boundary_vertices(mesh);
  std::vector<Index> candidates;
  std::vector<Eigen::Vector3d> positions;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (!on_boundary[v]) continue;
    candidates.push_back(v);
    positions.push_back(mesh.positions[v]);
  }
  std::vector<Index> target(mesh.vertex_count());
  for (Index v = 0; v < target.size(); ++v) target[v] = v;
  const std::vector<Index> local = weld_targets(positions, tolerance);
  for (Index k = 0; k < local.size(); ++k) target[candidates[k]] = candidates[local[k]];
  return target;
}

void apply_welds(Mesh& mesh, const std::vector<Index>& target) {
  for (Index& v : mesh.face_vertices) v = target[v];
}

// The vertices where `mesh` (repaired, not renumbered) is no surface: both ends of non-manifold
// edges, pinched vertices and, on a manifold, the edge where orienting it fails.
std::vector<BreakAt> surface_breaks(const Mesh& mesh) {
  std::vector<BreakAt> breaks;
  const EdgeTable table = build_edge_table(mesh);
  for (Index e = 0; e < table.edge_count(); ++e)
    if (table.corners(e).size() > 2)
      for (Index v : table.edge_vertices[e]) breaks.push_back({v, WeldBreak::non_manifold_edge});
  const std::vector<Index> fans = vertex_fan_counts(mesh, table);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (fans[v] > 1) breaks.push_back({v, WeldBreak::pinched_vertex});
  if (!breaks.empty()) return breaks;
  const std::vector<Index> corner_face = corner_faces(mesh);
  const Orientation orientation = orientation_of(mesh, table, corner_face);
  if (orientation.face == kNoIndex) return breaks;
  const Index c = orientation.corner;
  for (Index v : {mesh.face_vertices[c], mesh.face_vertices[mesh.next_corner(c, corner_face[c])]})
    breaks.push_back({v, WeldBreak::non_orientable});
  return breaks;
}

// Per vertex, the smallest vertex of its connected component (faces sharing a vertex).
std::vector<Index> vertex_components(const Mesh& mesh) {
  DisjointSets sets(mesh.vertex_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (Index v : mesh.face(f)) sets.join(v, mesh.face(f)[0]);
  std::vector<Index> component(mesh.vertex_count());
  for (Index v = 0; v < component.size(); ++v) component[v] = static_cast<Index>(sets.find(v));
  return component;
}

// Marks (per group, by its target; WeldBreak + 1, 0 for none) the groups of welded vertices at
// the breaks; if no break is at one, those in the components of the breaks: a part without welds
// is as given there.
std::vector<std::uint8_t> groups_at_breaks(const Mesh& welded, const std::vector<Index>& target,
                                           const std::vector<BreakAt>& breaks) {
  std::vector<Index> size(target.size(), 0);
  for (Index v : target) ++size[v];
  std::vector<std::uint8_t> mark(target.size(), 0);
  bool any = false;
  for (const BreakAt& b : breaks) {
    if (size[b.vertex] < 2 || mark[b.vertex]) continue;
    mark[b.vertex] = static_cast<std::uint8_t>(b.reason) + 1;
    any = true;
  }
  if (any) return mark;
  const std::vector<Index> component = vertex_components(welded);
  std::vector<std::uint8_t> broken(target.size(), 0);  // per component, WeldBreak + 1
  for (const BreakAt& b : breaks)
    if (!broken[component[b.vertex]])
      broken[component[b.vertex]] = static_cast<std::uint8_t>(b.reason) + 1;
  for (Index v = 0; v < target.size(); ++v)
    if (size[v] > 1) mark[v] = broken[component[v]];
  return mark;
}

// Keeps apart the marked groups; false if none is marked.
bool keep_apart(const Mesh& mesh, const std::vector<std::uint8_t>& mark, Welds& welds) {
  bool any = false;
  for (Index v = 0; v < mark.size(); ++v) {
    if (!mark[v]) continue;
    any = true;
    ++welds.kept_apart;
    ++welds.kept_apart_for[mark[v] - 1];
    if (welds.example.empty()) welds.example = describe_vertex(mesh, v);
  }
  for (Index v = 0; v < welds.target.size(); ++v)
    if (mark[welds.target[v]]) welds.target[v] = v;
  return any;
}

// The welds of boundary vertices closer than `tolerance`, without those that break the surface:
// welded and repaired, the mesh is checked, the groups at its breaks are kept apart, and again,
// until it has no break or no group is at one (the mesh's own breaks, which validation reports).
Welds weld_without_breaking(const Mesh& mesh, double tolerance) {
  Welds welds;
  welds.target = boundary_weld_targets(mesh, tolerance);
  while (true) {
    Mesh welded = mesh;
    apply_welds(welded, welds.target);
    ValidationReport ignored;
    repair_faces(welded, ignored);
    const std::vector<BreakAt> breaks = surface_breaks(welded);
    if (breaks.empty() || !keep_apart(mesh, groups_at_breaks(welded, welds.target, breaks), welds))
      return welds;
  }
}

std::string kept_apart_sentence(const Welds& welds) {
  static const char* const kWhat[kWeldBreaks] = {"an edge of more than two faces",
                                                 "a pinched vertex", "a non-orientable surface"};
  std::string why;
  for (std::size_t k = 0; k < kWeldBreaks; ++k) {
    if (!welds.kept_apart_for[k]) continue;
    why += std::string(why.empty() ? "" : ", ") + std::to_string(welds.kept_apart_for[k]) +
           " would make " + kWhat[k];
  }
  return std::to_string(welds.kept_apart) +
         " groups of near-duplicate vertices kept apart, since welding them would break the "
         "surface (" +
         why + "), e.g. at " + welds.example + " as given; the mesh is as given there";
}

void add_warnings(const Mesh& mesh, const ValidationOptions& options, const Welds& welds,
                  Index first_zero_area, ValidationReport& r) {
  auto add = [&](std::size_t count, const std::string& sentence) {
    if (count > 0) r.warnings.push_back(std::to_string(count) + " " + sentence);
  };
  add(r.welded_vertices, "duplicate vertices welded (closer than " +
                             format_number(options.weld_tolerance) +
                             " x the bounding-box diagonal)");
  if (welds.kept_apart > 0) r.warnings.push_back(kept_apart_sentence(welds));
  add(r.dropped_faces, "degenerate faces dropped (fewer than three distinct vertices)");
  add(r.collapsed_faces, "faces with repeated corners collapsed to fewer corners");
  add(r.unreferenced_vertices, "vertices in no face removed");
  if (r.zero_area_faces > 0)
    add(r.zero_area_faces, "faces have zero area, e.g. " + describe_face(mesh, first_zero_area) +
                               "; results near them may be inaccurate");
  add(r.flipped_faces, "faces flipped to agree with the orientation of their neighbours");
  if (r.components > 1)
    r.warnings.push_back("the mesh has " + std::to_string(r.components) +
                         " connected components; each is a separate surface");
}

}  // namespace

ValidationReport validate_mesh(Mesh& mesh, const ValidationOptions& options) {
  ValidationReport report;
  check_arrays(mesh);
  check_finite(mesh);
  Welds welds;
  if (options.weld_tolerance >= 0) {
    welds = weld_without_breaking(mesh, options.weld_tolerance * bounding_box(mesh).diagonal());
    for (Index v = 0; v < welds.target.size(); ++v) report.welded_vertices += welds.target[v] != v;
    report.unwelded_groups = welds.kept_apart;
    apply_welds(mesh, welds.target);
  }
  repair_faces(mesh, report);
  if (mesh.face_count() == 0)
    throw GeometryError("every face is degenerate (fewer than three distinct vertices" +
                        std::string(report.welded_vertices ? ", after welding duplicates" : "") +
                        "); the mesh has no surface");
  report.unreferenced_vertices = remove_unreferenced_vertices(mesh) - report.welded_vertices;
  Index first_zero_area = kNoIndex;
  report.zero_area_faces =
      count_zero_area_faces(mesh, options.zero_area_tolerance, first_zero_area);

  // Welding breaks nothing (weld_without_breaking()): what is refused here is the mesh's own.
  const std::vector<Index> corner_face = corner_faces(mesh);
  const EdgeTable table = build_edge_table(mesh);
  check_manifold_edges(mesh, table, corner_face);
  report.flipped_faces = orient_faces(mesh, table, corner_face);
  // Non-manifold vertices are the last thing to find; build_connectivity() names them.
  const Connectivity connectivity = build_connectivity(mesh);
  report.components = connected_components(mesh, connectivity).count;
  add_warnings(mesh, options, welds, first_zero_area, report);
  return report;
}

}  // namespace tessera
