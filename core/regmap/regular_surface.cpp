#include "regmap/regular_surface.h"

#include <chrono>
#include <set>

#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/edge_table.h"
#include "mesh/self_intersection.h"
#include "mesh/topology.h"
#include "regmap/embedded_graph.h"
#include "regmap/line_graph.h"
#include "regmap/triangle_tiling.h"

namespace tessera::regmap {

namespace {

struct Placement {
  EmbeddedGraph embedded;
  std::string base;
  RelaxReport relaxation;
};

Placement place_graph(const LineGraph& line, const JunctionOrder& order, Geometry geometry,
                      const TubeShape& shape, const SurfaceOptions& options,
                      const Progress& progress) {
  Placement placement;
  placement.base = "relaxation";
  placement.embedded = jemisphere_embedding(line.graph, order, geometry, shape.reach, shape.arm);
  RelaxOptions relax = options.relax;
  relax.clearance = shape.clearance;
  placement.relaxation = relax_embedding(placement.embedded, line.graph, order, relax, progress);
  return placement;
}

// Closed: every edge has two faces; oriented: they run along it in opposite directions.
void check_closed_and_oriented(const Mesh& mesh, SurfaceStats& stats) {
  const EdgeTable table = build_edge_table(mesh);
  stats.closed = true;
  stats.oriented = true;
  for (Index e = 0; e < table.edge_count(); ++e) {
    const auto corners = table.corners(e);
    if (corners.size() != 2) {
      stats.closed = false;
      continue;
    }
    if (mesh.face_vertices[corners[0]] == mesh.face_vertices[corners[1]]) stats.oriented = false;
  }
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
  check_limit(faces, limits.max_faces, "the regular surface's mesh (faces)", "--max-faces");
  const TriangleTiling tiling = build_tiling(group, limits, progress);
  const LineGraph line = build_line_graph(group, tiling);
  const JunctionOrder order = junction_order(line.graph);
  const Placement placement = place_graph(line, order, tiling.geometry(), shape, options, progress);

  RegularSurface surface;
  progress.step("tubification", 0.0);
  surface.mesh = tubify(placement.embedded, line, order, shape);
  SurfaceStats& stats = surface.stats;
  stats.base = placement.base;
  stats.relaxation = placement.relaxation;
  stats.junctions = line.graph.node_count;
  stats.tubes = line.graph.edge_count;
  stats.vertices = surface.mesh.vertex_count();
  stats.faces = surface.mesh.face_count();
  stats.tube_radius = shape.radius;
  check_surface(surface.mesh, presentation, group.order(), surface);
  if (options.find_self_intersections) {
    stats.self_intersections = find_self_intersections(surface.mesh, progress).triangle_pairs;
    stats.self_intersections_searched = true;
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return surface;
}

}  // namespace tessera::regmap
