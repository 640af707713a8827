// Fuzzes reading and validating a .off file (readers.h, validate.h).
#include "fuzz_target.h"
#include "mesh/load.h"

TESSERA_FUZZ_TARGET(tessera::load_mesh(bytes, "fuzz.off", tessera::fuzz::fuzz_limits()))
