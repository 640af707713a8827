#include "regmap/map_json.h"

namespace tessera::regmap {

nlohmann::ordered_json map_info_json(const Presentation& presentation, const MapFigures& f,
                                     double seconds) {
  using json = nlohmann::ordered_json;
  return {{"name", presentation.name},  {"p", presentation.p},
          {"q", presentation.q},        {"order", f.order},
          {"vertices", f.vertices},     {"edges", f.edges},
          {"faces", f.faces},           {"genus", f.orientable ? json(f.genus) : json(nullptr)},
          {"orientable", f.orientable}, {"euler", f.euler},
          {"petrie", f.petrie},         {"seconds", seconds}};
}

nlohmann::ordered_json catalog_row_json(const CatalogEntry& e) {
  return {{"name", e.name},
          {"genus", e.genus},
          {"p", e.p},
          {"q", e.q},
          {"petrie", e.petrie},
          {"order", e.order},
          {"vertices", e.vertices},
          {"edges", e.edges},
          {"faces", e.faces}};
}

}  // namespace tessera::regmap
