// The seamless Poisson parameterization M_f (Sec. 6.6, (6.5), (6.6); App. A) of a triangle mesh
// with a cross field: per-corner (u, v) minimizing
//   E_f = sum_T A_T (|h grad u - u_T|^2 + |h grad v - v_T|^2)
// subject to the transitions uv_g = J^r uv_f + t across the cut graph, r the combed period jump
// and t free (the "open" parameterization: translations are not rounded to integers). Steps:
//  1. cut graph: dual spanning tree, combing, cut edges, wedges (cut_graph.h, wedges.h);
//  2. assembly: energy (poisson.h), transition constraints eliminated into a basis P (seams.h);
//  3. solve: P^T Q P y = P^T b, one sparse LDLT factorization;
//  4. injectivity: bisector constraints around singularities and on flipped triangles, with GLPK
//     (injectivity.h).
//
// In:  a triangle mesh, its connectivity and face frames, a cross field of it, the options.
// Out: the SeamlessParam value. Throws InputError for bad options or a field that admits no
//      seamless parameterization (a singularity-free field turning around a loop of a torus),
//      CancelledError when cancelled, Error if the sparse factorization fails.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "base/progress.h"
#include "field/cross_field.h"
#include "param/injectivity.h"

namespace tessera {

struct ParamOptions {
  double h_relative = 1e-2;  // h = h_relative * bounding-box diagonal (Sec. 6.9 default)
  InjectivityOptions injectivity;
};

struct StepTime {
  std::string step;
  double seconds = 0;
};

struct SeamlessParam {
  double h = 0;                              // absolute sizing: one parameter unit on the surface
  std::vector<Eigen::Vector2d> uv;           // per corner, in parameter units
  std::vector<std::uint8_t> rotation;        // per halfedge h: r_h in Z4 (LAYOUT_NOTES, seams.h):
  std::vector<Eigen::Vector2d> translation;  //   uv in face(twin h) = J^r_h uv in face(h) + t_h
  std::vector<std::uint8_t> cut;             // per edge, 1 on the cut graph
  std::vector<Singularity> singularities;    // of the field (cross_field.h)
  std::size_t flipped_before_injectivity = 0;
  std::size_t flipped_triangles = 0;
  std::size_t flipped_outside_singular_rings = 0;  // flipped, with no singular vertex
  double energy = 0;          // E_f / total area: mean squared deviation of h grad from the frame
  double max_seam_error = 0;  // over cut edges, relative to the uv bounding-box diagonal
  InjectivityReport injectivity;
  std::vector<StepTime> seconds;  // per step, in order
};

SeamlessParam seamless_parameterization(const Mesh& mesh, const Connectivity& connectivity,
                                        const FaceFrames& frames, const CrossField& field,
                                        const ParamOptions& options, const Progress& progress);

}  // namespace tessera
