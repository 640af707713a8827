// Fuzzes reading a P1 instance in its CPLEX LP form (instance_lp.h) and, for small instances, the
// exact solver against plain GLPK (p1_differential.h).
#include "matching/instance_lp.h"
#include "p1_differential.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return tessera::fuzz::fuzz_p1_reader(tessera::matching::read_instance_lp, data, size, "fuzz.lp");
}
