// A closed surface made ready for 3D printing as a solid: scaled to the print size the user picks
// (in millimetres), checked, and written as an STL the slicer can take.
//
// In:  a mesh with indices in range; the print size (the largest side of its bounding box, mm) and
//      the thinnest wall the printer makes (mm).
// Out: the check (PrintCheck): the scale, the printed extent, whether the surface is closed and
//      consistently oriented (watertight), its self-intersecting triangle pairs, and its thinnest
//      part, measured at every vertex as the distance along the inward normal to the surface's
//      other side (the local thickness of the solid; a tube's diameter); and the mesh in
//      millimetres, outward facing, resting on z = 0.
// Throws InputError for a print size or wall thickness that is not a positive number (or a wall
//      not thinner than the print), CancelledError through `progress`.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "base/progress.h"
#include "mesh/mesh.h"

namespace tessera {

struct PrintOptions {
  double size_mm = 100.0;  // the largest side of the printed bounding box
  double wall_mm = 1.0;    // the thinnest wall the printer makes
};

struct PrintCheck {
  PrintOptions options;
  double scale = 1.0;  // millimetres per model unit
  Eigen::Vector3d extent_mm = Eigen::Vector3d::Zero();
  bool closed = false;                 // every edge has two faces
  bool oriented = false;               // running along it in opposite directions
  bool inward = false;                 // the faces as given face inward (the print mesh turns them)
  std::size_t self_intersections = 0;  // intersecting triangle pairs
  double thinnest_mm = 0.0;            // over all vertices; 0 where a ray found no other side
  Eigen::Vector3d thinnest_at_mm = Eigen::Vector3d::Zero();
  std::size_t thin_vertices = 0;  // vertices where the solid is thinner than the wall

  // Watertight, free of self-intersections, nowhere thinner than the wall.
  bool printable() const;
  // One sentence per problem, each saying what to do; empty when printable.
  std::vector<std::string> problems() const;
};

PrintCheck check_print(const Mesh& mesh, const PrintOptions& options,
                       const Progress& progress = Progress());

// {size_mm, wall_mm, scale, extent_mm, closed, oriented, self_intersections, thinnest_mm,
// thinnest_at_mm, thin_vertices, printable, problems}.
nlohmann::ordered_json print_check_json(const PrintCheck& check);

// The mesh in millimetres (scale of `check`), its faces facing outward, its lowest point at z = 0
// and its footprint centred on the origin.
Mesh print_mesh(const Mesh& mesh, const PrintCheck& check);

}  // namespace tessera
