// Cancellation of adjacent valence-3/5 pairs by rematching one edge (field/dipoles.h): a dipole
// planted into the smoothest field of a generated mesh, by raising one period jump, is removed
// again, and the indices the rematching assumes agree with field_topology's.
#include <gtest/gtest.h>

#include <numbers>

#include "field/design.h"
#include "field/dipoles.h"
#include "field/field_topology.h"
#include "mesh/shapes.h"
#include "mesh/connectivity.h"

namespace tessera {
namespace {

struct Planted {
  Mesh mesh;
  Connectivity connectivity;
  CrossField field;   // the smoothest field
  CrossField dipole;  // the same with p_h raised on one edge between regular vertices
  Index edge = kNoIndex;
};

// Whether v and its neighbours all have index 0.
bool regular_around(const Connectivity& c, const CrossField& field, Index v) {
  if (field.vertex_index[v] != 0) return false;
  for (Index h : outgoing_halfedges(c, v))
    if (field.vertex_index[c.to_vertex[h]] != 0) return false;
  return true;
}

Planted plant_dipole(Mesh mesh) {
  Planted r{std::move(mesh), {}, {}, {}};
  r.connectivity = build_connectivity(r.mesh);
  const Connectivity& c = r.connectivity;
  const FaceFrames frames = face_frames(r.mesh);
  r.field = design_cross_field(r.mesh, c, frames, FieldOptions{}, Progress());
  Index h = 0;
  while (c.is_boundary_edge(c.edge[h]) || !regular_around(c, r.field, c.from_vertex(h)) ||
         !regular_around(c, r.field, c.to_vertex[h]))
    ++h;
  r.edge = c.edge[h];
  // The indices after the change, from field_topology with the turn raised by a quarter.
  Matching matching = principal_matching(c, r.field.angle, r.field.kappa);
  matching.turn[h] += std::numbers::pi / 2;
  matching.turn[c.twin[h]] -= std::numbers::pi / 2;
  r.dipole = r.field;
  r.dipole.period_jump[h] = static_cast<std::uint8_t>((r.field.period_jump[h] + 1) % 4);
  r.dipole.period_jump[c.twin[h]] = static_cast<std::uint8_t>((4 - r.dipole.period_jump[h]) % 4);
  r.dipole.vertex_index = vertex_indices(r.mesh, c, frames, r.field.angle, matching.turn);
  r.dipole.singularities = singularities(c, r.dipole.vertex_index);
  return r;
}

std::vector<std::uint8_t> only_edge(const Connectivity& c, Index edge) {
  std::vector<std::uint8_t> edges(c.edge_count(), 0);
  edges[edge] = 1;
  return edges;
}

TEST(FieldDipoles, PlantedDipoleOnASphereIsCancelled) {
  const Planted r = plant_dipole(icosphere(3));
  const Connectivity& c = r.connectivity;
  ASSERT_EQ(r.dipole.singularities.size(), r.field.singularities.size() + 2);
  const Index h = c.edge_halfedge[r.edge];
  EXPECT_EQ(r.dipole.vertex_index[c.from_vertex(h)] * r.dipole.vertex_index[c.to_vertex[h]], -1);

  const DipoleRematching result = cancel_adjacent_dipoles(c, r.dipole, only_edge(c, r.edge));
  EXPECT_EQ(result.cancelled, 1u);
  EXPECT_EQ(result.field.period_jump, r.field.period_jump);
  EXPECT_EQ(result.field.vertex_index, r.field.vertex_index);
  ASSERT_EQ(result.field.singularities.size(), r.field.singularities.size());
  double sum = 0;
  for (const Singularity& s : result.field.singularities) sum += s.index;
  EXPECT_EQ(sum, 2.0);
}

TEST(FieldDipoles, UnmarkedEdgesAndRegularEdgesAreLeftAlone) {
  const Planted r = plant_dipole(icosphere(3));
  const Connectivity& c = r.connectivity;
  std::vector<std::uint8_t> others(c.edge_count(), 1);
  others[r.edge] = 0;
  const DipoleRematching result = cancel_adjacent_dipoles(c, r.dipole, others);
  // Every other edge is marked, but the smoothest field has no adjacent valence-3/5 pair.
  EXPECT_EQ(result.cancelled, 0u);
  EXPECT_EQ(result.field.period_jump, r.dipole.period_jump);
  EXPECT_EQ(result.field.singularities.size(), r.dipole.singularities.size());
}

TEST(FieldDipoles, TheLastPairOfATorusFieldIsKept) {
  const Planted r = plant_dipole(torus(1.0, 0.4, 48, 16));
  ASSERT_TRUE(r.field.singularities.empty());
  ASSERT_EQ(r.dipole.singularities.size(), 2u);
  const DipoleRematching result =
      cancel_adjacent_dipoles(r.connectivity, r.dipole, only_edge(r.connectivity, r.edge));
  EXPECT_EQ(result.cancelled, 0u);
  EXPECT_EQ(result.field.singularities.size(), 2u);
}

}  // namespace
}  // namespace tessera
