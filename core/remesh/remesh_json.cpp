#include "remesh/remesh_json.h"

namespace tessera::remesh {

nlohmann::ordered_json remesh_json(const QuadMesh& q, long input_euler, double hausdorff,
                                   const nlohmann::ordered_json& seconds) {
  const QuadQuality& quality = q.quality;
  nlohmann::ordered_json json;
  json["quads"] = q.mesh.face_count();
  json["vertices"] = q.mesh.vertex_count();
  json["irregular_vertices"] = quality.irregular_vertices;
  json["patches"] = q.patch_count;
  json["layout_valid"] = true;
  json["lambda"] = q.lengths.lambda;
  json["chains"] = q.lengths.segments.size();
  json["compressed_sides"] = compressed_sides(q.lengths).size();
  json["min_scaled_jacobian"] = quality.min_scaled_jacobian;
  json["mean_scaled_jacobian"] = quality.mean_scaled_jacobian;
  json["nonpositive_jacobian_quads"] = quality.nonpositive_jacobian_quads;
  json["nonpositive_corners"] = quality.nonpositive_corners.size();
  json["nonpositive_corners_at_nodes"] = q.nonpositive_corners_at_nodes;
  json["flipped_quads"] = quality.flipped_quads;
  json["max_angle_deviation"] = quality.max_angle_deviation;
  json["mean_angle_deviation"] = quality.mean_angle_deviation;
  json["manifold"] = quality.manifold;
  json["boundary_edges"] = quality.boundary_edges;
  json["euler_characteristic"] = quality.euler_characteristic;
  json["input_euler_characteristic"] = input_euler;
  json["irregular_off_nodes"] = q.irregular_off_nodes;
  json["hausdorff_relative"] = hausdorff;
  json["seconds"] = seconds;
  return json;
}

}  // namespace tessera::remesh
