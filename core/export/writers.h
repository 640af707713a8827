// Mesh writers for the indexed formats: one function per format, one source file per format
// (write_<format>.cpp). The GLB writer, which carries more than a mesh, is in glb.h; write_mesh()
// in write_mesh.h picks the writer by the output file's extension.
//
// In:  a mesh (polygons allowed; face attributes written where the format can hold them).
// Out: the file's bytes. Nothing throws for a valid mesh.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace tessera {

// "v x y z" with enough digits to read back the same doubles, "f a b c ..." (1-based). With
// corner_uv (one per corner, e.g. a seamless parameterization's), also "vt u v" per corner and
// faces as "f v/vt ..."; throws Error if corner_uv is neither empty nor one per corner.
std::vector<std::uint8_t> write_obj(const Mesh& mesh,
                                    std::span<const Eigen::Vector2d> corner_uv = {});
// OFF with polygons as they are.
std::vector<std::uint8_t> write_off(const Mesh& mesh);
// PLY with double coordinates and every face attribute as an "int" face property of its name;
// binary little-endian by default.
std::vector<std::uint8_t> write_ply(const Mesh& mesh, bool binary = true);
// Binary STL; polygons are fanned into triangles.
std::vector<std::uint8_t> write_stl(const Mesh& mesh);

}  // namespace tessera
