#include "field/cross_field.h"

#include <cmath>
#include <string>

#include "base/error.h"
#include "field/field_topology.h"
#include "mesh/topology.h"

namespace tessera {

CrossField cross_field_from_angles(const Mesh& mesh, const Connectivity& connectivity,
                                   const FaceFrames& frames, std::vector<double> angle) {
  CrossField field;
  field.direction.resize(angle.size());
  for (Index f = 0; f < angle.size(); ++f) {
    angle[f] = wrap_angle(angle[f]);
    field.direction[f] = frames.direction(f, angle[f]);
  }
  field.kappa = connection_angles(mesh, connectivity, frames);
  Matching matching = principal_matching(connectivity, angle, field.kappa);
  field.vertex_index = vertex_indices(mesh, connectivity, frames, angle, matching.turn);
  split_merged_singularities(connectivity, matching, field.vertex_index);
  field.period_jump = std::move(matching.period_jump);
  field.singularities = singularities(connectivity, field.vertex_index);
  field.euler_characteristic = surface_topology(mesh, connectivity).euler_characteristic;
  long quarter_sum = 0;
  for (int k : field.vertex_index) quarter_sum += k;
  field.index_sum = quarter_sum / 4.0;
  field.angle = std::move(angle);
  return field;
}

CrossField cross_field_from_directions(const Mesh& mesh, const Connectivity& connectivity,
                                       const FaceFrames& frames,
                                       const std::vector<Eigen::Vector3d>& directions) {
  if (directions.size() != mesh.face_count())
    throw InputError("the field has " + std::to_string(directions.size()) +
                     " face directions but the mesh has " + std::to_string(mesh.face_count()) +
                     " faces; use a field made for this mesh (same faces, same order)");
  std::vector<double> angle(directions.size());
  for (Index f = 0; f < directions.size(); ++f) {
    const Eigen::Vector2d local = frames.local(f, directions[f]);
    // A direction almost along the normal has no meaningful tangent part.
    if (!(local.norm() > 1e-6 * directions[f].norm()))
      throw InputError("the field direction of face " + std::to_string(f) +
                       " is zero or normal to the face; every face needs a tangent direction");
    angle[f] = std::atan2(local.y(), local.x());
  }
  return cross_field_from_angles(mesh, connectivity, frames, std::move(angle));
}

}  // namespace tessera
