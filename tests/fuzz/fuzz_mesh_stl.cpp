// Fuzzes reading and validating a .stl file (readers.h, validate.h).
#include "fuzz_target.h"
#include "mesh/load.h"

TESSERA_FUZZ_TARGET(tessera::load_mesh(bytes, "fuzz.stl", tessera::fuzz::fuzz_limits()))
