// Isometries of the three model planes of a triangle group (thesis Sec. 9.1: "Euclidean motions,
// special orthogonal matrices (for spherical) or Moebius transformations (for hyperbolic)"), all
// written as one kind of 2x2 complex matrix acting on the complex plane:
//
//   z -> (a w + b) / (sigma conj(b) w + conj(a)),   w = z, or conj(z) for a reflection,
//   normalized so that |a|^2 - sigma |b|^2 = 1,
//
// with sigma = +1 for the Poincare disk (hyperbolic), 0 for the Euclidean plane and -1 for the
// sphere in stereographic coordinates (rotations of SU(2)). Geodesics through the origin are
// straight lines in all three models.
//
// Points are kept homogeneous (num : den) so that the sphere's pole, the image of infinity, stays
// finite; on the plane models den never vanishes.
#pragma once

#include <array>
#include <complex>

namespace tessera::regmap {

using Complex = std::complex<double>;

enum class Geometry { Spherical, Euclidean, Hyperbolic };

// The geometry of the triangle (pi/p, pi/q, pi/2): the sign of 1/2 - 1/p - 1/q.
Geometry geometry_of_type(int p, int q);
const char* to_string(Geometry geometry);

struct Point {
  Complex num{0.0, 0.0};
  Complex den{1.0, 0.0};
};

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

struct Isometry {
  Complex a{1.0, 0.0};
  Complex b{0.0, 0.0};
  bool reflects = false;
};

// f after g, renormalized.
Isometry compose(Geometry geometry, const Isometry& f, const Isometry& g);
Isometry inverse(Geometry geometry, const Isometry& f);
Point apply(Geometry geometry, const Isometry& f, const Point& z);

// The orientation-preserving isometry that moves the origin to c along the geodesic through both.
Isometry translation_to(Geometry geometry, Complex c);
// Rotation about the origin by `angle` (counterclockwise).
Isometry rotation(double angle);
// Reflection in the real axis.
Isometry conjugation();

// The point of the plane models (num / den).
Complex to_plane(const Point& z);
// Inverse stereographic projection from the south pole: the sphere itself for the spherical
// model, and the Jemisphere (thesis Sec. 9.3, Fig. 9.9: the upper hemisphere, conformal, the
// boundary circle on the equator) for the Poincare disk.
Vec3 to_sphere(const Point& z);

// Geodesic distance in the model (curvature +1, 0 or -1).
double distance(Geometry geometry, const Point& z, const Point& w);

// The point a fraction t of the way from z to w along their geodesic.
Point geodesic_point(Geometry geometry, const Point& z, const Point& w, double t);

// The fundamental triangle D0 = M0 N0 O0 with angles pi/p at M0 (the origin), pi/q at N0 (on the
// positive real axis) and pi/2 at O0 (at angle pi/p), and the generators acting on it: R rotates by
// 2pi/p about M0, S by 2pi/q about N0 (both counterclockwise), T reflects in M0N0.
struct FundamentalTriangle {
  Geometry geometry = Geometry::Hyperbolic;
  std::array<Point, 3> corners;  // M0, N0, O0
  Isometry r, s, t;
};
FundamentalTriangle fundamental_triangle(int p, int q);

}  // namespace tessera::regmap
