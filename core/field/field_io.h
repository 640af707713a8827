// Cross-field files: the one place that knows their formats.
//  .rawfield (Directional's format, ../shared/meshes/SOURCES.md): first line "N F", then F lines
//     of N 3D vectors (3N numbers) in face order. The first vector of each face is the field's
//     representative direction u_T (the others are its rotations).
//  per-face directions (any other extension): one line "x y z" per face, in face order; blank
//     lines and lines starting with '#' are skipped.
// The directions are projected to their faces by cross_field_from_directions() (cross_field.h).
//
// In:  the file's bytes (not NUL-terminated; nothing is read past them), its name (for messages
//      and the extension), the limits (the face count is checked before allocating).
// Out: one 3D vector per face of the file.
// Throws ParseError "<file>:<line>: ..." for malformed text, LimitError above limits.max_faces.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "base/limits.h"

namespace tessera {

std::vector<Eigen::Vector3d> read_rawfield(std::span<const std::uint8_t> bytes,
                                           const std::string& file_name, const Limits& limits);
std::vector<Eigen::Vector3d> read_face_directions(std::span<const std::uint8_t> bytes,
                                                  const std::string& file_name,
                                                  const Limits& limits);
// By extension: .rawfield (any case) or the per-face format.
std::vector<Eigen::Vector3d> read_field(std::span<const std::uint8_t> bytes,
                                        const std::string& file_name, const Limits& limits);

}  // namespace tessera
