// Fuzzes catalog rows (the tab-separated catalog format, catalog.h).
#include <string_view>

#include "fuzz_target.h"
#include "regmap/catalog.h"

TESSERA_FUZZ_TARGET(tessera::regmap::parse_catalog(
    std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), "fuzz.tsv"))
