// Fuzzes reading and validating a .ply file (readers.h, validate.h).
#include "fuzz_target.h"
#include "mesh/load.h"

TESSERA_FUZZ_TARGET(tessera::load_mesh(bytes, "fuzz.ply", tessera::fuzz::fuzz_limits()))
