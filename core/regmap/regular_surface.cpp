#include "regmap/regular_surface.h"

#include <algorithm>
#include <chrono>
#include <set>

#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/edge_table.h"
#include "mesh/self_intersection.h"
#include "mesh/symmetry.h"
#include "mesh/topology.h"
#include "regmap/embedded_graph.h"
#include "regmap/line_graph.h"
#include "regmap/spine_base.h"
#include "regmap/symmetric_base.h"
#include "regmap/triangle_tiling.h"

namespace tessera::regmap {

namespace {

struct Placement {
  EmbeddedGraph embedded;
  std::string base;
  std::vector<Eigen::Matrix3d> symmetries;
  RelaxReport relaxation;
};

// Sec. 9.6: the symmetric base when the map has one (and it is wanted), else Sec. 9.4's
// relaxation from the Jemisphere.
Placement place_graph(const LineGraph& line, const JunctionOrder& order, Geometry geometry,
                      const TubeShape& shape, const SurfaceOptions& options,
                      const std::string& map_name, const Progress& progress) {
  Placement placement;
  if (options.base != SurfaceBase::Relax) {
    if (auto symmetric = symmetric_placement(line.graph, order, shape)) {
      placement.embedded = std::move(symmetric->embedded);
      placement.base = symmetric->name;
      placement.symmetries = std::move(symmetric->symmetries);
      return placement;
    }
    if (options.base == SurfaceBase::Platonic)
      throw InputError(map_name +
                       " has no symmetric base (a double cover of a Platonic solid: {6,3}, "
                       "{8,3}, {6,4}, {10,3}, {6,5}; or one or two junctions); use --base relax");
  }
  placement.base = "relaxation";
  placement.embedded = jemisphere_embedding(line.graph, order, geometry, shape.reach, shape.arm);
  RelaxOptions relax = options.relax;
  relax.clearance = shape.clearance;
  placement.relaxation = relax_embedding(placement.embedded, line.graph, order, relax, progress);
  return placement;
}

// A relaxation that ends crossing itself has often stopped before its tubes moved apart (its
// step decays over the iterations it is given): R15.3' and R25.5' cross themselves after 400
// iterations (13,888 and 68,512 triangle pairs) and not after 800 and 1,500. This many times the
// iterations are tried once.
constexpr int kLongerRelaxation = 4;

// When the relaxed surface crosses itself, the relaxation run again from the Jemisphere with
// kLongerRelaxation times the iterations replaces it if its surface crosses itself less.
void try_longer_relaxation(const LineGraph& line, const JunctionOrder& order, Geometry geometry,
                           const TubeShape& shape, const SurfaceOptions& options,
                           const Limits& limits, const Progress& progress, Placement& chosen,
                           TubifiedSurface& surface, std::size_t& self_intersections) {
  if (chosen.base != "relaxation") return;
  SurfaceOptions longer = options;
  longer.base = SurfaceBase::Relax;
  longer.relax.iterations *= kLongerRelaxation;
  Placement placement = place_graph(line, order, geometry, shape, longer, "", progress);
  TubifiedSurface other = tubify(placement.embedded, line, order, shape, limits.max_faces);
  const std::size_t crossings = find_self_intersections(other.mesh, progress).triangle_pairs;
  if (crossings >= self_intersections) return;
  chosen = std::move(placement);
  surface = std::move(other);
  self_intersections = crossings;
}

// The spine is tried on graphs up to this many junctions, the range where it is built to be free of
// crossings (spine_base.h). Beyond it its tubes run the whole height past many levels: on the
// catalog up to genus 29 it never crossed itself less than the relaxation there (the largest graph
// it won on has 54 junctions), while its mesh is ten times larger (R14.1, 156 junctions: 4.9
// million triangles) and placing it and searching it for crossings took most of the build time.
constexpr std::size_t kSpineMaxJunctions = 64;

// When the relaxed surface crosses itself, the spine placement replaces it if the graph has one and
// its surface crosses itself less.
void try_spine(const LineGraph& line, const JunctionOrder& order, const TubeShape& shape,
               const Limits& limits, const Progress& progress, Placement& chosen,
               TubifiedSurface& surface, std::size_t& self_intersections) {
  if (line.graph.node_count > kSpineMaxJunctions) return;
  std::optional<SymmetricPlacement> spine = spine_placement(line.graph, order, shape);
  if (!spine) return;
  TubifiedSurface other = tubify(spine->embedded, line, order, shape, limits.max_faces);
  const std::size_t crossings = find_self_intersections(other.mesh, progress).triangle_pairs;
  if (crossings >= self_intersections) return;
  chosen.embedded = std::move(spine->embedded);
  chosen.base = spine->name;
  chosen.symmetries = std::move(spine->symmetries);
  surface = std::move(other);
  self_intersections = crossings;
}

void check_closed_and_oriented(const Mesh& mesh, SurfaceStats& stats) {
  const Closure c = closure(mesh);
  stats.closed = c.closed;
  stats.oriented = c.oriented;
}

// The topology and the group of the surface, from its mesh.
void check_surface(const Mesh& mesh, const Presentation& presentation, std::size_t tiles,
                   RegularSurface& surface) {
  SurfaceStats& stats = surface.stats;
  const std::vector<std::int32_t>& tile = mesh.face_attributes.at(kTileAttribute);
  stats.quarter_tubes = std::set<std::int32_t>(tile.begin(), tile.end()).size();
  check_closed_and_oriented(mesh, stats);
  if (!stats.closed || !stats.oriented) return;
  Connectivity connectivity;
  try {
    connectivity = build_connectivity(mesh);
  } catch (const TopologyError& e) {
    throw Error(std::string("the tubified surface is not a manifold (a bug): ") + e.what());
  }
  const SurfaceTopology topology = surface_topology(mesh, connectivity);
  stats.euler_characteristic = topology.euler_characteristic;
  stats.genus = topology.genus;
  stats.components = topology.components;
  surface.group = surface_group(quarter_tube_adjacency(mesh, connectivity, tile, tiles));
  const RelationCheck relations = check_relations(surface.group, presentation);
  stats.relations_checked = relations.relators;
  stats.failed_relations = relations.failures;
  stats.relations_hold = relations.hold();
}

}  // namespace

RegularSurface build_regular_surface(const Presentation& presentation, const FiniteGroup& group,
                                     const SurfaceOptions& options, const Limits& limits,
                                     const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const TubeShape shape = tube_shape(options.tube, group.q);
  const std::size_t faces = group.order() * static_cast<std::size_t>(shape.across) *
                            static_cast<std::size_t>(shape.junction + shape.along);
  // The fewest faces the mesh can have: refuse a map that is too large before placing it.
  check_limit(faces, limits.max_faces, "the regular surface's mesh (faces)", "--max-faces");
  const TriangleTiling tiling = build_tiling(group, limits, progress);
  const LineGraph line = build_line_graph(group, tiling);
  const JunctionOrder order = junction_order(line.graph);
  const Placement placement =
      place_graph(line, order, tiling.geometry(), shape, options, presentation.name, progress);

  RegularSurface surface;
  Placement chosen = placement;
  progress.step("tubification", 0.0);
  TubifiedSurface tubified = tubify(placement.embedded, line, order, shape, limits.max_faces);
  SurfaceStats& stats = surface.stats;
  if (options.find_self_intersections) {
    stats.self_intersections = find_self_intersections(tubified.mesh, progress).triangle_pairs;
    stats.self_intersections_searched = true;
    if (stats.self_intersections > 0 && options.base == SurfaceBase::Automatic) {
      try_longer_relaxation(line, order, tiling.geometry(), shape, options, limits, progress,
                            chosen, tubified, stats.self_intersections);
      try_spine(line, order, shape, limits, progress, chosen, tubified, stats.self_intersections);
    }
  }
  surface.mesh = std::move(tubified.mesh);
  surface.grids = std::move(tubified.grids);
  stats.base = chosen.base;
  stats.relaxation = chosen.relaxation;
  stats.junctions = line.graph.node_count;
  stats.tubes = line.graph.edge_count;
  stats.vertices = surface.mesh.vertex_count();
  stats.faces = surface.mesh.face_count();
  stats.tube_radius = shape.radius;
  stats.symmetries = chosen.symmetries.size();
  const std::vector<bool> kept = keeps_vertex_set(surface.mesh, chosen.symmetries);
  stats.symmetries_verified = static_cast<std::size_t>(std::count(kept.begin(), kept.end(), true));
  check_surface(surface.mesh, presentation, group.order(), surface);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return surface;
}

}  // namespace tessera::regmap
