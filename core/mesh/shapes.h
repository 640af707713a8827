// Meshes generated in code: test inputs and the page's sample shapes. All are deterministic and
// counterclockwise-oriented seen from outside; the closed ones are 2-manifolds of the stated genus.
#pragma once

#include "mesh/mesh.h"

namespace tessera {

// The icosahedron subdivided `subdivisions` times (each triangle into four), on the sphere of the
// given radius: genus 0, 20 * 4^subdivisions triangles.
Mesh icosphere(int subdivisions, double radius = 1.0);

// A torus of major radius R and minor radius r around the z axis, as major x minor quads (genus 1).
Mesh quad_torus(double major_radius, double minor_radius, int major_segments, int minor_segments);
// The same, triangulated.
Mesh torus(double major_radius, double minor_radius, int major_segments, int minor_segments);

// Two tori side by side along x, joined by a short neck where a patch of each was cut out: genus 2.
// `resolution` >= 1 scales the number of faces (32 x 16 quads per torus at resolution 4).
Mesh double_torus(int resolution = 4);

// A boxy mechanical part with sharp 90-degree edges: an L-shaped bracket (8 x 6 base plate, 6 high
// upright) with a square hole through each plate: genus 2. Every unit of the bracket is split into
// `resolution` x `resolution` squares, two triangles each.
Mesh mechanical_part(int resolution = 2);

// A cylinder without caps around the z axis: two boundary loops, genus 0.
Mesh open_cylinder(double radius, double height, int segments, int rings);

}  // namespace tessera
