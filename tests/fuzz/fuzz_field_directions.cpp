// Fuzzes reading a per-face direction file, the plain field format (field_io.h).
#include "field/field_io.h"
#include "fuzz_target.h"

TESSERA_FUZZ_TARGET(tessera::read_field(bytes, "fuzz.field", tessera::fuzz::fuzz_limits()))
