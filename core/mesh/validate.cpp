#include "mesh/validate.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/describe.h"
#include "mesh/edge_table.h"
#include "mesh/geometry.h"
#include "mesh/topology.h"
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

std::size_t weld_vertices(Mesh& mesh, double tolerance) {
  const std::vector<Index> target = weld_targets(mesh.positions, tolerance);
  std::size_t welded = 0;
  for (Index v = 0; v < target.size(); ++v) welded += target[v] != v;
  if (welded > 0)
    for (Index& v : mesh.face_vertices) v = target[v];
  return welded;
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
  if (mesh.face_count() == 0)
    throw GeometryError("every face is degenerate (fewer than three distinct vertices" +
                        std::string(report.welded_vertices ? ", after welding duplicates" : "") +
                        "); the mesh has no surface");
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

// Breadth-first over the faces of each component: a neighbour across an edge must run along it in
// the opposite direction. A contradiction means the surface is non-orientable. Within a component
// the orientation of the majority of faces wins, so that few faces are flipped.
std::size_t orient_faces(Mesh& mesh, const EdgeTable& table,
                         const std::vector<Index>& corner_face) {
  std::vector<signed char> flip(mesh.face_count(), -1);  // -1 unvisited, 0 keep, 1 flip
  std::vector<Index> component;
  std::size_t flipped = 0;
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
          throw TopologyError(
              "the surface is not orientable (like a Moebius strip or a Klein bottle): going "
              "around "
              "from face " +
              std::to_string(seed) + " to " + describe_face(mesh, g) +
              " gives it both orientations; Tessera needs an orientable "
              "surface, cut it open or rebuild it");
        }
      }
    }
    std::size_t to_flip = 0;
    for (Index f : component) to_flip += flip[f];
    const bool invert = 2 * to_flip > component.size();
    for (Index f : component) {
      if (static_cast<bool>(flip[f]) != invert) {
        reverse_face(mesh, f);
        ++flipped;
      }
    }
  }
  return flipped;
}

void add_warnings(const Mesh& mesh, const ValidationOptions& options, Index first_zero_area,
                  ValidationReport& r) {
  auto add = [&](std::size_t count, const std::string& sentence) {
    if (count > 0) r.warnings.push_back(std::to_string(count) + " " + sentence);
  };
  add(r.welded_vertices, "duplicate vertices welded (closer than " +
                             format_number(options.weld_tolerance) +
                             " x the bounding-box diagonal)");
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
  if (options.weld_tolerance >= 0)
    report.welded_vertices =
        weld_vertices(mesh, options.weld_tolerance * bounding_box(mesh).diagonal());
  repair_faces(mesh, report);
  report.unreferenced_vertices = remove_unreferenced_vertices(mesh) - report.welded_vertices;
  Index first_zero_area = kNoIndex;
  report.zero_area_faces =
      count_zero_area_faces(mesh, options.zero_area_tolerance, first_zero_area);

  Connectivity connectivity;
  try {
    const std::vector<Index> corner_face = corner_faces(mesh);
    const EdgeTable table = build_edge_table(mesh);
    check_manifold_edges(mesh, table, corner_face);
    report.flipped_faces = orient_faces(mesh, table, corner_face);
    // Non-manifold vertices are the last thing to find; build_connectivity() names them.
    connectivity = build_connectivity(mesh);
  } catch (const TopologyError& e) {
    // Welding joins what was apart; the user should know it may be the cause.
    if (report.welded_vertices == 0) throw;
    throw TopologyError(std::string(e.what()) + " (this is after welding " +
                        std::to_string(report.welded_vertices) +
                        " near-duplicate vertices; welding can be turned off with a negative "
                        "weld tolerance, --weld-tolerance -1)");
  }
  report.components = connected_components(mesh, connectivity).count;
  add_warnings(mesh, options, first_zero_area, report);
  return report;
}

}  // namespace tessera
