#include "regmap/realization.h"

#include <algorithm>
#include <cmath>

#include "base/error.h"

namespace tessera::regmap {

double realization_score(const TargetMap& target, const Pairing& pairing) {
  const double hosohedron = target.kind == TargetKind::Hosohedron ? 100.0 : 0.0;
  const double rotations = pairing.kind == PairingKind::Rotations ? 10.0 : 0.0;
  const double junctions = 1.0 / (1.0 + static_cast<double>(target.vertices));
  return hosohedron + rotations + std::min(pairing.distortion, 9.0) + junctions;
}

const FiniteGroup& TargetGroups::group(const TargetMap& target) {
  auto found = groups_.find(target.name);
  if (found == groups_.end())
    found = groups_.emplace(target.name, enumerate_group(target.presentation, limits_)).first;
  return found->second;
}

const RegularSurface& TargetSurfaces::surface(const TargetMap& target, TargetGroups& groups) {
  auto found = surfaces_.find(target.name);
  if (found == surfaces_.end())
    found = surfaces_
                .emplace(target.name, build_regular_surface(target.presentation,
                                                            groups.group(target), {}, limits_))
                .first;
  return found->second;
}

RealizationSearch find_realizations(const FiniteGroup& source, const ElementWords& words, int genus,
                                    const std::vector<TargetMap>& targets,
                                    const PairingLimits& pairing_limits, TargetGroups& groups) {
  RealizationSearch result;
  for (const TargetMap& t : targets) {
    if (t.surface_genus() != genus) continue;
    result.tried.push_back(t.name);
    const PairingSearch search =
        find_pairings(source, words, t.presentation, groups.group(t), pairing_limits);
    result.stopped = result.stopped || search.stopped;
    for (std::size_t k = 0; k < std::min(search.pairings.size(), kPairingsPerTarget); ++k)
      result.found.push_back({t, search.pairings[k], realization_score(t, search.pairings[k])});
  }
  std::stable_sort(result.found.begin(), result.found.end(),
                   [](const Realization& a, const Realization& b) { return a.score < b.score; });
  return result;
}

namespace {

nlohmann::ordered_json corners_json(const std::array<Point, 4>& corners) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Point& c : corners) {
    const Complex z = to_plane(c);
    out.push_back({z.real(), z.imag()});
  }
  return out;
}

const nlohmann::json& member(const nlohmann::json& json, const char* key) {
  if (!json.is_object() || !json.contains(key))
    throw InputError(std::string("a pairing needs '") + key + "'");
  return json.at(key);
}

Element element_of(const nlohmann::json& json, const char* key, std::size_t order) {
  const nlohmann::json& v = member(json, key);
  if (!v.is_number_integer() || v.get<long long>() < 0 ||
      v.get<long long>() >= static_cast<long long>(order))
    throw InputError(std::string("a pairing's '") + key + "' must be an element 0.." +
                     std::to_string(order - 1) + " of the map's group");
  return static_cast<Element>(v.get<long long>());
}

std::array<Point, 4> corners_of(const nlohmann::json& json, const char* key) {
  const nlohmann::json& v = member(json, key);
  if (!v.is_array() || v.size() != 4)
    throw InputError(std::string("a pairing's '") + key + "' must be four [re, im] points");
  std::array<Point, 4> out;
  for (std::size_t i = 0; i < 4; ++i) {
    const nlohmann::json& z = v[i];
    if (!z.is_array() || z.size() != 2 || !z[0].is_number() || !z[1].is_number())
      throw InputError(std::string("a pairing's '") + key + "' must be four [re, im] points");
    const Complex c(z[0].get<double>(), z[1].get<double>());
    if (!std::isfinite(c.real()) || !std::isfinite(c.imag()) || std::abs(c) >= 1.0)
      throw InputError(std::string("a pairing's '") + key + "' must lie inside the Poincare disk");
    out[i] = Point{c, 1.0};
  }
  return out;
}

}  // namespace

nlohmann::ordered_json pairing_json(const Pairing& p) {
  nlohmann::ordered_json out = {
      {"target", p.target}, {"kind", to_string(p.kind)}, {"x", p.x}, {"y", p.y}};
  if (p.kind == PairingKind::Reflections) {
    out["a"] = p.a;
    out["b"] = p.b;
    out["c"] = p.c;
  }
  out["apex"] = p.apex == kN ? "vertex" : "face";
  out["distortion"] = p.distortion;
  out["corners"] = corners_json(p.corners);
  out["mirrored"] = corners_json(p.mirrored);
  return out;
}

Pairing pairing_from_json(const nlohmann::json& json, std::size_t source_order) {
  Pairing p;
  const nlohmann::json& target = member(json, "target");
  if (!target.is_string()) throw InputError("a pairing's 'target' must be a name");
  p.target = target.get<std::string>();
  const nlohmann::json& kind = member(json, "kind");
  if (kind != "reflections" && kind != "rotations")
    throw InputError("a pairing's 'kind' must be 'reflections' or 'rotations'");
  p.kind = kind == "reflections" ? PairingKind::Reflections : PairingKind::Rotations;
  p.x = element_of(json, "x", source_order);
  p.y = element_of(json, "y", source_order);
  if (p.kind == PairingKind::Reflections) {
    p.a = element_of(json, "a", source_order);
    p.b = element_of(json, "b", source_order);
    p.c = element_of(json, "c", source_order);
  }
  const nlohmann::json& apex = member(json, "apex");
  if (apex != "vertex" && apex != "face")
    throw InputError("a pairing's 'apex' must be 'vertex' or 'face'");
  p.apex = apex == "vertex" ? kN : kM;
  const nlohmann::json& distortion = member(json, "distortion");
  if (!distortion.is_number()) throw InputError("a pairing's 'distortion' must be a number");
  p.distortion = distortion.get<double>();
  p.corners = corners_of(json, "corners");
  p.mirrored = corners_of(json, "mirrored");
  return p;
}

}  // namespace tessera::regmap
