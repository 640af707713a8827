// Mesh readers: one function per format, one source file per format (read_<format>.cpp), and
// read_mesh() that picks the format by the file name's extension or, failing that, by the content.
//
// In:  the file's bytes (no NUL termination needed; nothing is read past them), the file name (for
//      messages and the extension) and the resource limits.
// Out: the mesh as the file states it: faces as written, vertices as written (STL and glTF vertices
//      welded where bit-identical, since those formats repeat them per triangle or per attribute),
//      per-face integer properties of PLY files as face attributes. Nothing is repaired here;
//      validate_mesh() (validate.h) does that, and load_mesh() does both.
// Throws ParseError (with line or byte offset) for malformed files, GeometryError for NaN/Inf
// coordinates, LimitError when announced or actual sizes exceed the limits (before allocating).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/limits.h"
#include "base/read_file.h"
#include "mesh/mesh.h"

namespace tessera {

using Bytes = std::span<const std::uint8_t>;

// OBJ: v, f (v, v/vt, v//vn, v/vt/vn forms; negative indices count back from the last vertex);
// polygons kept; vt, vn, l, p, groups, materials and unknown statements ignored.
Mesh read_obj(Bytes bytes, const std::string& file_name, const Limits& limits);
// OFF (also COFF, NOFF, STOFF, ... whose extra per-vertex and per-face values are skipped).
Mesh read_off(Bytes bytes, const std::string& file_name, const Limits& limits);
// PLY: ascii, binary_little_endian, binary_big_endian; any element and property is skipped by its
// declared type; integer face properties become face attributes.
Mesh read_ply(Bytes bytes, const std::string& file_name, const Limits& limits);
// STL: binary (told by its size, even when it starts with "solid") and ascii.
Mesh read_stl(Bytes bytes, const std::string& file_name, const Limits& limits);
// glTF 2.0 (.gltf JSON with embedded or, given base_dir, external buffers) and GLB: every triangle
// primitive (triangles, strips, fans) of the default scene with node transforms applied. With an
// empty base_dir the file system is never touched.
Mesh read_gltf(Bytes bytes, const std::string& file_name, const Limits& limits,
               const std::string& base_dir = "");

enum class MeshFormat { obj, off, ply, stl, gltf };

// By extension (.obj .off .ply .stl .gltf .glb, any case), else by content; throws ParseError if
// neither tells.
MeshFormat detect_mesh_format(Bytes bytes, const std::string& file_name);

// Checks the size limit and refuses empty or blank files, then dispatches on detect_mesh_format().
Mesh read_mesh(Bytes bytes, const std::string& file_name, const Limits& limits,
               const std::string& base_dir = "");

// read_file_bytes() + read_mesh(), with external glTF buffers looked up beside the file.
Mesh read_mesh_file(const std::string& path, const Limits& limits);

}  // namespace tessera
