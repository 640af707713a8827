// The machine-readable form of a map's figures and of a catalog row: one definition shared by
// `tessera regmap --json` and the wasm module.
#pragma once

#include <nlohmann/json.hpp>

#include "regmap/catalog.h"
#include "regmap/finite_group.h"
#include "regmap/presentation.h"

namespace tessera::regmap {

// name, p, q, order, vertices, edges, faces, genus (null when non-orientable), orientable, euler,
// petrie, seconds (the enumeration's).
nlohmann::ordered_json map_info_json(const Presentation& presentation, const MapFigures& figures,
                                     double seconds);

// name, genus, p, q, petrie, order, vertices, edges, faces.
nlohmann::ordered_json catalog_row_json(const CatalogEntry& entry);

}  // namespace tessera::regmap
