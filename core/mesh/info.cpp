#include "mesh/info.h"

#include <sstream>

#include <nlohmann/json.hpp>

#include "mesh/connectivity.h"
#include "mesh/topology.h"

namespace tessera {

MeshInfo mesh_info(const Mesh& mesh, const ValidationReport& report) {
  const Connectivity connectivity = build_connectivity(mesh);
  const SurfaceTopology topology = surface_topology(mesh, connectivity);
  MeshInfo info;
  info.vertices = mesh.vertex_count();
  info.edges = connectivity.edge_count();
  info.faces = mesh.face_count();
  for (std::size_t f = 0; f < mesh.face_count(); ++f) ++info.face_sizes[mesh.face_size(f)];
  info.components = topology.components;
  info.boundary_loops = topology.boundary_loops;
  info.genus = topology.genus;
  info.euler_characteristic = topology.euler_characteristic;
  info.oriented = report.oriented_as_given();
  info.bbox = bounding_box(mesh);
  info.warnings = report.warnings;
  return info;
}

nlohmann::json to_json(const MeshInfo& info) {
  nlohmann::json sizes = nlohmann::json::object();
  for (const auto& [corners, count] : info.face_sizes) sizes[std::to_string(corners)] = count;
  const auto& lo = info.bbox.min;
  const auto& hi = info.bbox.max;
  return {{"vertices", info.vertices},
          {"faces", info.faces},
          {"edges", info.edges},
          {"face_sizes", sizes},
          {"components", info.components},
          {"boundary_loops", info.boundary_loops},
          {"genus", info.genus},
          {"euler_characteristic", info.euler_characteristic},
          {"manifold", info.manifold},
          {"oriented", info.oriented},
          {"bbox_min", {lo.x(), lo.y(), lo.z()}},
          {"bbox_max", {hi.x(), hi.y(), hi.z()}},
          {"bbox_diagonal", info.bbox.diagonal()},
          {"warnings", info.warnings}};
}

std::string to_text(const MeshInfo& info) {
  std::ostringstream out;
  out.precision(6);
  out << "vertices              " << info.vertices << '\n'
      << "edges                 " << info.edges << '\n'
      << "faces                 " << info.faces << " (";
  const char* separator = "";
  for (const auto& [corners, count] : info.face_sizes) {
    out << separator << count << " with " << corners << " corners";
    separator = ", ";
  }
  out << ")\n"
      << "components            " << info.components << '\n'
      << "boundary loops        " << info.boundary_loops << '\n'
      << "genus                 " << info.genus << '\n'
      << "euler characteristic  " << info.euler_characteristic << '\n'
      << "manifold              " << (info.manifold ? "yes" : "no") << '\n'
      << "oriented              "
      << (info.oriented ? "yes" : "no (faces were flipped to make it so)") << '\n'
      << "bounding box          (" << info.bbox.min.x() << ", " << info.bbox.min.y() << ", "
      << info.bbox.min.z() << ") - (" << info.bbox.max.x() << ", " << info.bbox.max.y() << ", "
      << info.bbox.max.z() << ")\n"
      << "bbox diagonal         " << info.bbox.diagonal() << '\n';
  for (const std::string& warning : info.warnings) out << "warning: " << warning << '\n';
  return out.str();
}

}  // namespace tessera
