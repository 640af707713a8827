#include "quadmesh/quad_input.h"

#include <map>
#include <utility>

#include "base/error.h"

namespace tessera::quadmesh {
namespace {

constexpr std::size_t kFacesNamed = 5;

}  // namespace

void require_quad_mesh(const Mesh& mesh, const std::string& source) {
  std::size_t triangles = 0, larger = 0;
  std::string named;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::size_t n = mesh.face_size(f);
    if (n == 4) continue;
    (n == 3 ? triangles : larger) += 1;
    if (triangles + larger <= kFacesNamed)
      named += (named.empty() ? "" : ", ") + std::string("face ") + std::to_string(f) + " (" +
               std::to_string(n) + " corners, at vertex " + std::to_string(mesh.face(f)[0]) + ")";
  }
  if (triangles + larger == 0) return;
  // glTF and STL hold triangles only: a quad mesh saved in them arrives as a triangle mesh.
  const std::string all_triangles =
      triangles == mesh.face_count()
          ? " Every face is a triangle: glTF/GLB and STL files hold triangles only, "
            "--join-triangles joins a quad mesh saved so (each quad's two triangles one after "
            "the other) back into quads; a triangle mesh gets its quad layout from 'tessera "
            "layout'."
          : "";
  throw TopologyError(source + ": " + std::to_string(triangles + larger) + " of " +
                      std::to_string(mesh.face_count()) + " faces are not quads (" +
                      std::to_string(triangles) + " triangles, " + std::to_string(larger) +
                      " polygons with more than four corners; first " + named +
                      "; faces count from 0): quad-mesh optimization needs a pure quad mesh; "
                      "--split splits every face into quads first." +
                      all_triangles);
}

Mesh split_into_quads(const Mesh& mesh) {
  Mesh result;
  result.positions = mesh.positions;
  std::map<std::pair<Index, Index>, Index> midpoint;
  const auto midpoint_of = [&](Index a, Index b) {
    const std::pair<Index, Index> key{std::min(a, b), std::max(a, b)};
    auto [it, added] = midpoint.emplace(key, kNoIndex);
    if (added) it->second = result.add_vertex(0.5 * (mesh.positions[a] + mesh.positions[b]));
    return it->second;
  };
  std::vector<Index> parent;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::span<const Index> face = mesh.face(f);
    const std::size_t n = face.size();
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (Index v : face) centroid += mesh.positions[v];
    const Index centre = result.add_vertex(centroid / double(n));
    for (std::size_t k = 0; k < n; ++k) {
      const Index before = face[(k + n - 1) % n], here = face[k], after = face[(k + 1) % n];
      result.add_face({here, midpoint_of(here, after), centre, midpoint_of(before, here)});
      parent.push_back(static_cast<Index>(f));
    }
  }
  for (const auto& [name, values] : mesh.face_attributes) {
    std::vector<std::int32_t>& copied = result.face_attributes[name];
    for (Index f : parent) copied.push_back(values[f]);
  }
  return result;
}

Mesh join_triangle_pairs(const Mesh& mesh, const std::string& source) {
  const auto refuse = [&](std::size_t f, const std::string& why) {
    return TopologyError(source + ": faces " + std::to_string(f) + " and " + std::to_string(f + 1) +
                         " are not the two triangles of one quad (" + why +
                         "); --join-triangles wants a quad mesh saved as triangles, each quad's "
                         "two halves one after the other");
  };
  if (mesh.face_count() % 2 != 0)
    throw TopologyError(source + ": an odd number of faces (" + std::to_string(mesh.face_count()) +
                        ") cannot pair into quads");
  Mesh result;
  result.positions = mesh.positions;
  for (std::size_t f = 0; f < mesh.face_count(); f += 2) {
    if (mesh.face_size(f) != 3 || mesh.face_size(f + 1) != 3) throw refuse(f, "not triangles");
    const std::span<const Index> a = mesh.face(f), b = mesh.face(f + 1);
    bool joined = false;
    // a = (x, y, p) and b = (y, x, q) tile the quad (y, p, x, q).
    for (std::size_t i = 0; i < 3 && !joined; ++i)
      for (std::size_t j = 0; j < 3 && !joined; ++j) {
        const Index x = a[i], y = a[(i + 1) % 3], p = a[(i + 2) % 3];
        if (b[j] != y || b[(j + 1) % 3] != x) continue;
        const Index q = b[(j + 2) % 3];
        if (q == p) throw refuse(f, "the same triangle twice");
        result.add_face({y, p, x, q});
        joined = true;
      }
    if (!joined) throw refuse(f, "they share no edge");
  }
  for (const auto& [name, values] : mesh.face_attributes) {
    std::vector<std::int32_t>& kept = result.face_attributes[name];
    for (std::size_t f = 0; f < values.size(); f += 2) kept.push_back(values[f]);
  }
  return result;
}

}  // namespace tessera::quadmesh
