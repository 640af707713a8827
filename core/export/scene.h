// What a GLB file of Tessera carries: the result, not just the picture (SPEC "Interfaces").
// Later stages (layouts, regular surfaces) fill a Scene and hand it to write_glb().
//
//  - mesh: its faces (polygons are fanned into triangles) and every face attribute, written as a
//    custom per-vertex attribute "_<NAME>" (e.g. "patch" -> "_PATCH", float values);
//  - colours per vertex or per face (COLOR_0, linear RGB in [0, 1]);
//  - line sets (arcs, separatrices) as LINES primitives and point sets (singularities) as POINTS
//    primitives, each a node of its own name with an "_ID" attribute (the polyline's or point's
//    index in its set);
//  - extras: statistics as JSON in the glTF scene's "extras".
// glTF attributes are per vertex: with face attributes or face colours the mesh's vertices are
// split per face, otherwise they stay shared (and the mesh reads back with the same vertices).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "mesh/mesh.h"

namespace tessera {

using Color = Eigen::Vector3f;

struct LineSet {
  std::string name;
  std::vector<std::vector<Eigen::Vector3d>> polylines;
  Color color = Color(0.05f, 0.05f, 0.05f);
};

struct PointSet {
  std::string name;
  std::vector<Eigen::Vector3d> points;
  Color color = Color(0.8f, 0.1f, 0.1f);
};

struct Scene {
  Mesh mesh;
  std::vector<Color> vertex_colors;  // empty, or one per vertex
  std::vector<Color> face_colors;    // empty, or one per face (takes precedence)
  std::vector<LineSet> line_sets;
  std::vector<PointSet> point_sets;
  nlohmann::json extras = nlohmann::json::object();
};

}  // namespace tessera
