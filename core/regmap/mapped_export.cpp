#include "regmap/mapped_export.h"

#include <algorithm>

#include "base/error.h"
#include "regmap/surface_export.h"

namespace tessera::regmap {

DrawnMap draw_realization(const FiniteGroup& source, const ElementWords& words,
                          const Realization& realization, const MappedMapOptions& options,
                          const Limits& limits, const Progress& progress) {
  const Presentation& target = realization.target.presentation;
  const FiniteGroup target_group = enumerate_group(target, limits);
  // The same surface as 'tessera regmap surface' builds: searched for crossings, so that one that
  // crosses itself is replaced by a longer relaxation or the spine.
  const RegularSurface surface = build_regular_surface(target, target_group, {}, limits, progress);
  return {realization, surface.stats,
          map_onto_surface(source, words, realization.pairing, surface, options, progress)};
}

std::optional<DrawnMap> draw_first_right(RealizationSearch& search, const FiniteGroup& source,
                                         const ElementWords& words, const MapFigures& figures,
                                         const MappedMapOptions& options, TargetSurfaces& surfaces,
                                         TargetGroups& groups, const Progress& progress) {
  auto& found = search.found;
  for (const bool crossing_free : {true, false}) {
    for (std::size_t k = 0; k < found.size();) {
      const RegularSurface& surface = surfaces.surface(found[k].target, groups);
      if ((surface.stats.self_intersections == 0) != crossing_free) {
        ++k;
        continue;
      }
      try {
        MappedMap drawn =
            map_onto_surface(source, words, found[k].pairing, surface, options, progress);
        if (drawn_right(drawn.stats, figures)) {
          std::rotate(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(k),
                      found.begin() + static_cast<std::ptrdiff_t>(k) + 1);
          return DrawnMap{found.front(), surface.stats, std::move(drawn)};
        }
      } catch (const CancelledError&) {
        throw;
      } catch (const LimitError&) {
        throw;
      } catch (const Error&) {
        // the pairing does not glue on the surface's quarter tubes: the next one
      }
      found.erase(found.begin() + static_cast<std::ptrdiff_t>(k));
      ++search.drawn_wrong;
    }
  }
  return std::nullopt;
}

namespace {

std::vector<TargetMap> targets_to_try(const Catalog& catalog, const std::string& on, int genus,
                                      const std::string& name) {
  if (on.empty()) return all_targets(catalog, genus);
  TargetMap target = find_target(catalog, on);
  if (target.surface_genus() != genus)
    throw InputError("the surface of " + on + " has genus " +
                     std::to_string(target.surface_genus()) + ", " + name + " genus " +
                     std::to_string(genus) + "; pick a target of genus " + std::to_string(genus) +
                     " or leave out --on");
  return {std::move(target)};
}

}  // namespace

DrawnMap draw_on_best_target(const FiniteGroup& source, const ElementWords& words,
                             const MapFigures& figures, const std::string& name,
                             const Catalog& catalog, const std::string& on,
                             const PairingLimits& pairing_limits, const MappedMapOptions& options,
                             const Limits& limits, const Progress& progress,
                             std::vector<std::string>* others) {
  const int genus = figures.genus;
  const std::vector<TargetMap> targets = targets_to_try(catalog, on, genus, name);
  TargetGroups groups(limits);
  TargetSurfaces surfaces(limits);
  RealizationSearch search =
      find_realizations(source, words, genus, targets, pairing_limits, groups);
  std::optional<DrawnMap> drawn =
      draw_first_right(search, source, words, figures, options, surfaces, groups, progress);
  if (!drawn) {
    std::string tried;
    for (const std::string& t : search.tried) tried += (tried.empty() ? "" : ", ") + t;
    if (search.drawn_wrong > 0)
      throw InputError(name + ": none of the " + std::to_string(search.drawn_wrong) +
                       " pairings found with " + tried +
                       " draws it right (they do not glue into its faces)");
    throw InputError(
        name + " has no pairing, by reflections or by rotations, with " +
        (tried.empty() ? std::string("any target (none of genus ") + std::to_string(genus) + ")"
                       : tried) +
        (search.stopped
             ? " (the search stopped at its step limit on some; raise it with --max-steps)"
             : ""));
  }
  if (others)
    for (const Realization& r : search.found)
      if (r.target.name != drawn->realization.target.name &&
          std::find(others->begin(), others->end(), r.target.name) == others->end())
        others->push_back(r.target.name);
  return std::move(*drawn);
}

nlohmann::ordered_json drawn_map_json(const std::string& source_name, const MapFigures& figures,
                                      const DrawnMap& map, double seconds) {
  const MappedMapStats& s = map.drawn.stats;
  return {{"source", source_name},
          {"target", map.realization.target.name},
          {"target_kind", to_string(map.realization.target.kind)},
          {"genus", s.genus},
          {"V", s.vertices},
          {"E", s.edges},
          {"F", s.faces},
          {"expected", {{"V", figures.vertices}, {"E", figures.edges}, {"F", figures.faces}}},
          {"face_orbits", s.face_orbits},
          {"faces_are_disks", s.faces_are_disks},
          {"covers_once", s.covers_once},
          {"closed", s.closed},
          {"oriented", s.oriented},
          {"self_intersections", s.self_intersections_searched
                                     ? nlohmann::ordered_json(s.self_intersections)
                                     : nlohmann::ordered_json(nullptr)},
          {"symmetries_verified", map.surface.symmetries_verified},
          {"surface_base", map.surface.base},
          {"subdivisions", s.subdivisions},
          {"mesh_vertices", s.mesh_vertices},
          {"mesh_faces", s.mesh_faces},
          {"pairing", pairing_json(map.realization.pairing)},
          {"seconds", seconds}};
}

Scene drawn_map_scene(const DrawnMap& map, const std::string& source_name,
                      const nlohmann::ordered_json& figures) {
  const MappedMap& drawn = map.drawn;
  Scene scene;
  scene.mesh = drawn.mesh;
  for (std::int32_t face : drawn.mesh.face_attributes.at(kFaceAttribute))
    scene.face_colors.push_back(quarter_tube_color(face));
  LineSet edges;
  edges.name = "edges";
  for (const auto& [a, b] : drawn.edge_segments)
    edges.polylines.push_back({drawn.mesh.positions[a], drawn.mesh.positions[b]});
  scene.line_sets.push_back(std::move(edges));
  scene.extras = {{"map", source_name}, {"mapped", figures}};
  return scene;
}

}  // namespace tessera::regmap
