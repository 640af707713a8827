// Inputs the fuzz targets (tests/fuzz) found, reduced to what each one needed: each is now read or
// refused as it should be.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/error.h"
#include "matching/instance_lp.h"
#include "matching/solver.h"

namespace tessera {
namespace {

std::vector<std::uint8_t> bytes_of(const std::string& text) {
  return {text.begin(), text.end()};
}

// fuzz_p1_lp: a weight of 9.7e13 beside weights near 1 made GLPK's simplex return a matching 30%
// above the optimum as "optimal" (the exact solver was right). Such weights are refused up front.
TEST(FuzzRegression, P1WeightsAboveTheLimitAreRefused) {
  const std::string lp =
      "Minimize\n obj: 1 x0 + 2 x1 + 96790677032342 x2\nSubject To\n p0: x0 + x2 = 1\n"
      " p1: x0 + x1 + x2 = 1\n v2: x1 <= 1\nBinaries\n x0 x1 x2\nEnd\n";
  try {
    matching::read_instance_lp(bytes_of(lp), "huge.lp", Limits());
    FAIL() << "a weight of 9.7e13 was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("huge.lp"), std::string::npos) << message;
    EXPECT_NE(message.find("edge 2"), std::string::npos) << message;
    EXPECT_NE(message.find("1e9"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace tessera
