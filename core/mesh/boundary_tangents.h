// The direction of a mesh's boundary curves at each boundary edge, as the cross field's alignment
// (field/alignment.h) and the parameterization's boundary iso-lines (param/seams.cpp) read it.
//
// A boundary cut through a triangulation (a scan's hole, a plane section) zigzags: a staircase of
// edges up to 60 degrees off the curve. Read per edge, the constraints of neighbouring faces
// disagree and force singularities all along it (a cut icosphere: 174 instead of 6). The tangent
// of a boundary edge is instead the chord from 4 median boundary edge lengths before it to 4 after
// it along the boundary (points on the polyline, so that a vertex added on an edge moves nothing),
// not past a corner of the boundary curve. A corner is a vertex where
//  - the boundary turns on the surface (pi minus the vertex's surface angle) by more than 45
//    degrees, and
//  - by more than 55 degrees summed over the vertices within the chords' reach, each weighted by
//    1 - distance / reach: a staircase's alternate steps cancel, a corner keeps its turn, a curve
//    turns by less within the reach (the field's boundary index rounds a turn to a quarter from
//    45 degrees on: 55 keeps a margin);
//  - no such vertex within the reach has a larger sum.
// On a straight or evenly curved boundary the chord is the edge's own direction.
//
// In:  a mesh and its connectivity. Out: per edge, a unit tangent (zero on interior edges), and
//      per vertex whether it is a corner of its boundary curve. Nothing throws.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera {

struct BoundaryTangents {
  std::vector<Eigen::Vector3d> edge_tangent;  // per edge, along its boundary halfedge
  std::vector<std::uint8_t> corner;           // per vertex
};

BoundaryTangents boundary_tangents(const Mesh& mesh, const Connectivity& connectivity);

}  // namespace tessera
