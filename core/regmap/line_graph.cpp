#include "regmap/line_graph.h"

#include <algorithm>
#include <limits>

#include "base/error.h"

namespace tessera::regmap {

using enum Letter;

namespace {

// The 3D starting position of a polygon point: the Jemisphere for the Poincare disk, the sphere
// for spherical maps, the plane z = 0 for torus maps.
Vec3 lift(Geometry geometry, const Point& z) {
  if (geometry == Geometry::Euclidean) {
    const Complex w = to_plane(z);
    return {w.real(), w.imag(), 0.0};
  }
  return to_sphere(z);
}

// Sec. 9.3's identification: every class of segment ends takes the position of its copy nearest
// the centre of the polygon. Copies related by a symmetry of the polygon (e.g. the two ends of a
// pair of boundary sides) are equally near; their computed distances differ in the last bits, and
// differently on each platform's sin, cos and cosh, so that a strict minimum would place the
// native and wasm surfaces differently. Distances within kTie of the least count as equal, and the
// first such copy in the tiling's (combinatorial) order is taken.
std::vector<Vec3> identify(const TriangleTiling& tiling, const Orbits& classes, Corner corner) {
  constexpr double kTie = 1e-9;
  const Geometry geometry = tiling.geometry();
  std::vector<double> distances(tiling.size());
  std::vector<double> least(classes.count, std::numeric_limits<double>::infinity());
  for (std::size_t g = 0; g < tiling.size(); ++g) {
    const auto c = static_cast<std::size_t>(classes.label[g]);
    distances[g] = distance(geometry, Point{}, tiling.corners[g][corner]);
    least[c] = std::min(least[c], distances[g]);
  }
  std::vector<Vec3> position(classes.count);
  std::vector<bool> placed(classes.count, false);
  for (std::size_t g = 0; g < tiling.size(); ++g) {
    const auto c = static_cast<std::size_t>(classes.label[g]);
    if (placed[c] || distances[g] > least[c] + kTie) continue;
    position[c] = lift(geometry, tiling.corners[g][corner]);
    placed[c] = true;
  }
  return position;
}

}  // namespace

LineGraph build_line_graph(const FiniteGroup& group, const TriangleTiling& tiling) {
  const Orbits orientation = orbits(group, {{R}, {S}});
  if (orientation.count != 2)
    throw InputError("the map is not orientable, so its edge graph has no rotation system");
  const std::size_t n = group.order();
  const Orbits vertices = vertex_orbits(group), edges = edge_orbits(group);

  LineGraph line;
  line.partner.resize(n);
  line.node_of = vertices.label;
  line.edge_of = edges.label;
  line.dart_of.assign(n, -1);
  EdgeGraph& graph = line.graph;
  graph.node_count = vertices.count;
  graph.edge_count = edges.count;
  for (std::size_t g = 0; g < n; ++g) {
    const auto e = static_cast<Element>(g);
    line.partner[g] = group.times(e, Word{Si, T});
    if (orientation.label[g] != 0) continue;  // label 0: the orientation-preserving elements
    const auto dart = static_cast<std::int32_t>(graph.dart_element.size());
    line.dart_of[g] = dart;
    line.dart_of[static_cast<std::size_t>(group.times(e, T))] = dart;
    graph.dart_element.push_back(e);
    graph.dart_node.push_back(vertices.label[g]);
    graph.dart_edge.push_back(edges.label[g]);
  }
  for (Element g : graph.dart_element) {
    graph.next_around.push_back(line.dart_of[static_cast<std::size_t>(group.times(g, S))]);
    graph.opposite.push_back(line.dart_of[static_cast<std::size_t>(group.times(g, Word{R, S}))]);
  }
  graph.node_position = identify(tiling, vertices, kN);
  graph.edge_position = identify(tiling, edges, kO);
  return line;
}

std::size_t rotation_system_faces(const EdgeGraph& graph) {
  std::vector<bool> seen(graph.dart_element.size(), false);
  std::size_t faces = 0;
  for (std::size_t start = 0; start < seen.size(); ++start) {
    if (seen[start]) continue;
    ++faces;
    for (auto d = static_cast<std::int32_t>(start); !seen[static_cast<std::size_t>(d)];) {
      seen[static_cast<std::size_t>(d)] = true;
      d = graph.next_around[static_cast<std::size_t>(graph.opposite[static_cast<std::size_t>(d)])];
    }
  }
  return faces;
}

}  // namespace tessera::regmap
