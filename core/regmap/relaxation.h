// The constrained spring relaxation of the edge graph (thesis Sec. 9.4, Fig. 9.12).
//
// "Each vertex of the graph [is] a charge particle attracted by its neighbors and repulsed by the
// other vertices", with the ordering of the darts at every junction kept as a constraint. Here the
// constraint is built in: a junction is a rigid star (its node, its frame and its q darts at the
// fixed angles 2 pi k / q in the frame's plane, see embedded_graph.h), so the order can never
// degenerate (Fig. 9.13a) whatever the forces do. The particles are the junctions and the edge
// midpoints; the forces are
//   - a spring (Hooke, rest length 1) from the end of every dart (the junction's reach along it) to
//     its edge's midpoint,
//   - an alignment spring pulling every midpoint towards the point one unit further along the
//     dart's direction (so tubes leave their junctions straight),
//   - Coulomb repulsion between all junctions and midpoints (O(n^2): the graphs of the census up
//     to genus 101 have at most a few thousand),
//   - in the second half, contact springs between the tubes' centrelines, modelled as two
//     segments per dart (junction reach to tip, rigid; tip to midpoint), between every two that
//     come closer than the clearance (found through a uniform grid), stiffening linearly: they
//     push tubes that pass too close apart along their common perpendicular.
// Junctions move and turn as rigid bodies (force and torque), midpoints as points, by gradient
// descent preconditioned by each body's stiffness (its springs and the contacts on it) with a step
// that decays linearly over a fixed number of iterations, then, while tubes still overlap, settle
// with full contacts for at most a second fixed number. Deterministic; the symmetric start is left
// by a fixed nudge of the midpoints, so that rounding differences between platforms (native, wasm)
// do not decide the result.
//
// In:  an edge graph, its junction order, an embedding (e.g. the Jemisphere one) whose edge paths
//      are single midpoints.
// Out: the embedding moved in place; a report with the convergence measures.
// Throws CancelledError through `progress`; Error for a path of more than one point.
#pragma once

#include <cstddef>

#include "base/progress.h"
#include "regmap/embedded_graph.h"

namespace tessera::regmap {

struct RelaxOptions {
  int iterations = 400;
  int settle_iterations = 400;  // at most this many more while tubes overlap
  double charge = 0.15;         // Coulomb constant (the springs have stiffness 1)
  double node_charge = 8.0;     // a junction's charge, in midpoint charges
  double alignment = 1.0;       // stiffness of the alignment springs
  double contact = 200.0;       // final stiffness of the contact springs between tubes
  double clearance = 0.6;       // distance below which two tubes' centrelines are in contact
  double step = 0.4;            // the first step; it decays linearly to a twentieth of it
};

struct RelaxReport {
  int iterations = 0;           // with the settling steps
  double energy = 0.0;          // at the end
  double energy_change = 0.0;   // relative change over the last tenth of the main iterations
  double rms_motion = 0.0;      // root mean square of the last main step's motions
  double max_dart_angle = 0.0;  // largest angle (radians) between a dart and its tube's chord
  std::size_t overlaps = 0;     // pieces of tubes still closer than 0.6 clearances
};

RelaxReport relax_embedding(EmbeddedGraph& embedded, const EdgeGraph& graph,
                            const JunctionOrder& order, const RelaxOptions& options = {},
                            const Progress& progress = Progress());

// The largest angle between a dart's direction and the chord from its end to its edge's midpoint.
double max_dart_angle(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                      const JunctionOrder& order);

}  // namespace tessera::regmap
