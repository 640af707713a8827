// Mutated files of every format must be read or refused with a tessera::Error: never a crash, a
// foreign exception or a hang. The mutations are seeded, so a failure reproduces.
#include <gtest/gtest.h>

#include <random>

#include "base/error.h"
#include "export/write_mesh.h"
#include "mesh/load.h"
#include "mesh/shapes.h"

namespace tessera {
namespace {

std::vector<std::uint8_t> mutate(std::vector<std::uint8_t> bytes, std::mt19937& random) {
  std::uniform_int_distribution<int> kind(0, 4);
  const int edits = 1 + static_cast<int>(random() % 4);
  for (int e = 0; e < edits && !bytes.empty(); ++e) {
    const std::size_t at = random() % bytes.size();
    switch (kind(random)) {
      case 0:
        bytes[at] = static_cast<std::uint8_t>(random());
        break;  // any byte
      case 1:
        bytes[at] = static_cast<std::uint8_t>('0' + random() % 10);
        break;  // a digit
      case 2:
        bytes.resize(at);
        break;  // truncation
      case 3:
        bytes.insert(bytes.begin() + at, static_cast<std::uint8_t>('9'));
        break;
      default:
        bytes[at] ^= static_cast<std::uint8_t>(1u << (random() % 8));  // a bit flip
    }
  }
  return bytes;
}

TEST(Fuzz, MutatedFilesAreReadOrRefusedCleanly) {
  Mesh mesh = icosphere(1);
  mesh.face_attributes["patch"].assign(mesh.face_count(), 3);
  Limits limits;
  limits.max_vertices = 100'000;  // keeps an accepted mutation's announced sizes small
  limits.max_faces = 100'000;
  std::mt19937 random(20240521);
  for (const char* name : {"f.obj", "f.off", "f.ply", "f.stl", "f.glb"}) {
    const std::vector<std::uint8_t> valid = encode_mesh(mesh, name);
    std::size_t accepted = 0;
    for (int trial = 0; trial < 400; ++trial) {
      const std::vector<std::uint8_t> bytes = mutate(valid, random);
      try {
        load_mesh(bytes, name, limits);
        ++accepted;
      } catch (const Error&) {
        // refused with a typed error: what we want
      } catch (const std::exception& e) {
        ADD_FAILURE() << name << " trial " << trial << ": foreign exception: " << e.what();
      }
    }
    // Some mutations must survive (e.g. a changed digit in a coordinate), or the test checks
    // little.
    EXPECT_GT(accepted, 0u) << name;
  }
  const std::vector<std::uint8_t> ascii = encode_mesh(mesh, "a.ply", {.ply_binary = false});
  for (int trial = 0; trial < 400; ++trial) {
    try {
      load_mesh(mutate(ascii, random), "a.ply", limits);
    } catch (const Error&) {
    }
  }
}

}  // namespace
}  // namespace tessera
