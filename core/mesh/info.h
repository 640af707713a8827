// The figures `tessera info` and the page's info panel show for a validated mesh.
//
// In:  a mesh that validate_mesh() accepted, and its report.
// Out: MeshInfo; to_json() gives the fixed machine-readable form (keys vertices, faces, edges,
//      components, boundary_loops, genus, euler_characteristic, manifold, oriented, bbox_diagonal,
//      warnings, plus face_sizes, bbox_min, bbox_max).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "mesh/geometry.h"
#include "mesh/mesh.h"
#include "mesh/validate.h"

namespace tessera {

struct MeshInfo {
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::map<std::size_t, std::size_t> face_sizes;  // corners per face -> number of such faces
  std::size_t components = 0;
  std::size_t boundary_loops = 0;
  long genus = 0;  // summed over the components
  long euler_characteristic = 0;
  bool manifold = true;  // a validated mesh always is; non-manifold input is refused
  bool oriented = true;  // the faces as given were consistently oriented (else some were flipped)
  BoundingBox bbox;
  std::vector<std::string> warnings;
};

MeshInfo mesh_info(const Mesh& mesh, const ValidationReport& report);

nlohmann::json to_json(const MeshInfo& info);

// Several lines for people, as `tessera info` prints them.
std::string to_text(const MeshInfo& info);

}  // namespace tessera
