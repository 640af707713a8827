// Fuzzes reading a .rawfield cross-field file (field_io.h).
#include "field/field_io.h"
#include "fuzz_target.h"

TESSERA_FUZZ_TARGET(tessera::read_field(bytes, "fuzz.rawfield", tessera::fuzz::fuzz_limits()))
