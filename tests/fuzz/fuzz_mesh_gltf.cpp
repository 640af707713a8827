// Fuzzes reading and validating a .gltf (JSON) file; external buffers are never looked up.
#include "fuzz_target.h"
#include "mesh/load.h"

TESSERA_FUZZ_TARGET(tessera::load_mesh(bytes, "fuzz.gltf", tessera::fuzz::fuzz_limits()))
