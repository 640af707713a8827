#include "mesh/describe.h"

#include <sstream>

namespace tessera {
namespace {

std::string format_point(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out.precision(6);
  out << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return out.str();
}

}  // namespace

std::string describe_vertex(const Mesh& mesh, Index v) {
  return "vertex " + std::to_string(v) + " at " + format_point(mesh.positions[v]);
}

std::string describe_face(const Mesh& mesh, Index f) {
  std::string text = "face " + std::to_string(f) + " (vertices";
  for (Index v : mesh.face(f)) text += ' ' + std::to_string(v);
  return text + ')';
}

std::string describe_edge(const Mesh& mesh, Index a, Index b) {
  return "edge " + std::to_string(a) + '-' + std::to_string(b) + " at " +
         format_point(mesh.positions[a]) + '-' + format_point(mesh.positions[b]);
}

}  // namespace tessera
