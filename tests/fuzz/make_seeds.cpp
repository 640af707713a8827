// Writes the seed corpora of the fuzz targets: small valid inputs of each kind, generated from the
// core's own shapes, writers and shipped catalog (no data copied in).
//   make_seeds <out-dir> <catalog.tsv>   ->  <out-dir>/<target>/seed-*
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "export/glb.h"
#include "export/writers.h"
#include "matching/generate.h"
#include "matching/instance_json.h"
#include "matching/instance_lp.h"
#include "mesh/shapes.h"
#include "regmap/catalog.h"

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

namespace {

void write_seed(const fs::path& dir, const std::string& name, const Bytes& bytes) {
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

Bytes text_bytes(const std::string& text) {
  return Bytes(text.begin(), text.end());
}

std::string base64(const Bytes& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const bool two = i + 1 < bytes.size(), three = i + 2 < bytes.size();
    const std::uint32_t n =
        bytes[i] << 16 | (two ? bytes[i + 1] << 8 : 0) | (three ? bytes[i + 2] : 0);
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += two ? digits[(n >> 6) & 63] : '=';
    out += three ? digits[n & 63] : '=';
  }
  return out;
}

// A .gltf with one triangle, its buffer embedded as a data URI.
std::string gltf_triangle() {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::uint16_t indices[3] = {0, 1, 2};
  Bytes buffer(sizeof positions + sizeof indices);
  std::memcpy(buffer.data(), positions, sizeof positions);
  std::memcpy(buffer.data() + sizeof positions, indices, sizeof indices);
  std::ostringstream json;
  json << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
       << R"("nodes":[{"mesh":0,"translation":[1,2,3]}],)"
       << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
       << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
       << R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":3,)"
       << R"("type":"SCALAR"}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
       << R"({"buffer":0,"byteOffset":36,"byteLength":6}],)"
       << R"("buffers":[{"byteLength":)" << buffer.size()
       << R"(,"uri":"data:application/octet-stream;base64,)" << base64(buffer) << R"("}]})";
  return json.str();
}

void write_mesh_seeds(const fs::path& out) {
  const std::vector<tessera::Mesh> meshes = {
      tessera::icosphere(0), tessera::quad_torus(1, 0.4, 6, 4), tessera::open_cylinder(1, 1, 5, 1)};
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const std::string n = std::to_string(i);
    write_seed(out / "fuzz_mesh_obj", "seed-" + n, tessera::write_obj(meshes[i]));
    write_seed(out / "fuzz_mesh_off", "seed-" + n, tessera::write_off(meshes[i]));
    write_seed(out / "fuzz_mesh_ply", "seed-binary-" + n, tessera::write_ply(meshes[i], true));
    write_seed(out / "fuzz_mesh_ply", "seed-ascii-" + n, tessera::write_ply(meshes[i], false));
    write_seed(out / "fuzz_mesh_stl", "seed-" + n, tessera::write_stl(meshes[i]));
    tessera::Scene scene;
    scene.mesh = meshes[i];
    write_seed(out / "fuzz_mesh_glb", "seed-" + n, tessera::write_glb(scene));
  }
  write_seed(out / "fuzz_mesh_obj", "seed-negative",
             text_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -2 -3\nf -4 -3 -1\n"
                        "f -4 -1 -2\nf -3 -2 -1\nvt 0 0\nvn 0 0 1\n"));
  write_seed(out / "fuzz_mesh_stl", "seed-ascii",
             text_bytes("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                        "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n"));
  write_seed(out / "fuzz_mesh_gltf", "seed-0", text_bytes(gltf_triangle()));
}

// Field files for the 20 faces of an icosahedron: a .rawfield with its four rotations and the
// per-face format with a comment; the directions need not be tangent, the reader accepts any.
void write_field_seeds(const fs::path& out) {
  const std::size_t faces = tessera::icosphere(0).face_count();
  std::ostringstream raw, plain;
  raw << "4 " << faces << "\n";
  plain << "# one direction per face\n";
  for (std::size_t f = 0; f < faces; ++f) {
    const double x = 1.0 + 0.1 * double(f), y = 0.5 - 0.05 * double(f), z = 0.25;
    raw << x << ' ' << y << ' ' << z << ' ' << -y << ' ' << x << ' ' << z << ' ' << -x << ' ' << -y
        << ' ' << z << ' ' << y << ' ' << -x << ' ' << z << "\n";
    plain << x << ' ' << y << ' ' << z << "\n";
  }
  write_seed(out / "fuzz_field_rawfield", "seed-0", text_bytes(raw.str()));
  write_seed(out / "fuzz_field_directions", "seed-0", text_bytes(plain.str()));
}

// Small P1 instances in both file forms: feasible, with virtual ports, and infeasible.
void write_p1_seeds(const fs::path& out) {
  tessera::matching::PlantedSpec feasible{.ports = 12, .extra_edges = 12, .conflicts = 10};
  tessera::matching::PlantedSpec with_virtual = feasible;
  with_virtual.virtual_ports = 3;
  tessera::matching::PlantedSpec blocked = feasible;
  blocked.blocked_squares = 1;
  const tessera::matching::PlantedSpec specs[] = {feasible, with_virtual, blocked};
  for (std::size_t i = 0; i < std::size(specs); ++i) {
    const auto problem = tessera::matching::planted_instance(specs[i]);
    const std::string n = std::to_string(i);
    write_seed(out / "fuzz_p1_json", "seed-" + n, tessera::matching::write_instance_json(problem));
    write_seed(out / "fuzz_p1_lp", "seed-" + n, tessera::matching::write_instance_lp(problem));
  }
}

std::string conder_entry(const tessera::regmap::CatalogEntry& e) {
  std::ostringstream text;
  text << e.name << " :  Type {" << e.p << "," << e.q << "}_" << e.petrie << "  Order " << e.order
       << "  mV = 1  mF = 1\nDefining relations for automorphism group:\n[ T^2, R^" << e.p << ", S^"
       << e.q << ", (R * S)^2, (R * T)^2, (S * T)^2";
  for (const auto& w : e.relators) text << ", " << tessera::regmap::to_string(w);
  text << " ]\n";
  return text.str();
}

void write_regmap_seeds(const fs::path& out, const fs::path& catalog_path) {
  std::ifstream in(catalog_path);
  std::string line, head;
  for (int i = 0; i < 12 && std::getline(in, line); ++i) head += line + "\n";
  write_seed(out / "fuzz_catalog", "seed-head", text_bytes(head));
  const tessera::regmap::Catalog catalog = tessera::regmap::read_catalog(catalog_path.string());
  int written = 0;
  for (const auto& entry : catalog) {
    if (entry.order > 400) continue;
    write_seed(out / "fuzz_conder", "seed-" + entry.name, text_bytes(conder_entry(entry)));
    if (++written == 12) break;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_seeds <out-dir> <catalog.tsv>\n");
    return 2;
  }
  write_mesh_seeds(argv[1]);
  write_field_seeds(argv[1]);
  write_p1_seeds(argv[1]);
  write_regmap_seeds(argv[1], argv[2]);
  return 0;
}
