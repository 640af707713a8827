#include "regmap/isometry.h"

#include <cmath>
#include <numbers>

namespace tessera::regmap {

namespace {

double sigma(Geometry geometry) {
  switch (geometry) {
    case Geometry::Spherical:
      return -1.0;
    case Geometry::Euclidean:
      return 0.0;
    case Geometry::Hyperbolic:
      return 1.0;
  }
  return 0.0;
}

Isometry normalized(Geometry geometry, Complex a, Complex b, bool reflects) {
  const double scale = std::sqrt(std::norm(a) - sigma(geometry) * std::norm(b));
  return {a / scale, b / scale, reflects};
}

// The model radius |z| of a point at distance d from the origin, and back.
double model_radius(Geometry geometry, double d) {
  switch (geometry) {
    case Geometry::Spherical:
      return std::tan(d / 2);
    case Geometry::Euclidean:
      return d;
    case Geometry::Hyperbolic:
      return std::tanh(d / 2);
  }
  return d;
}

double distance_of_radius(Geometry geometry, double r) {
  switch (geometry) {
    case Geometry::Spherical:
      return 2 * std::atan(r);
    case Geometry::Euclidean:
      return r;
    case Geometry::Hyperbolic:
      return 2 * std::atanh(r);
  }
  return r;
}

double dot(const Vec3& u, const Vec3& v) {
  return u.x * v.x + u.y * v.y + u.z * v.z;
}

Vec3 cross(const Vec3& u, const Vec3& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

double length(const Vec3& u) {
  return std::sqrt(dot(u, u));
}

// Stereographic coordinates of a unit vector, homogeneous: (x + iy) / (1 + z), or equivalently
// (1 - z) / (x - iy), whichever is better conditioned (the latter at the south pole).
Point from_sphere(const Vec3& v) {
  if (v.z >= 0) return {Complex(v.x, v.y), Complex(1 + v.z, 0)};
  return {Complex(1 - v.z, 0), Complex(v.x, -v.y)};
}

// Side lengths of the right triangle with angles alpha at M, beta at N (right angle at O):
// cosh|MN| = cot(alpha) cot(beta) and cosh|MO| = cos(beta) / sin(alpha) in the hyperbolic plane,
// the same with cos for the sphere; the Euclidean one is scaled to |MN| = 1.
std::array<double, 2> side_lengths(Geometry geometry, double alpha, double beta) {
  const double mn = 1.0 / (std::tan(alpha) * std::tan(beta));
  const double mo = std::cos(beta) / std::sin(alpha);
  switch (geometry) {
    case Geometry::Spherical:
      return {std::acos(mn), std::acos(mo)};
    case Geometry::Euclidean:
      return {1.0, std::cos(alpha)};
    case Geometry::Hyperbolic:
      return {std::acosh(mn), std::acosh(mo)};
  }
  return {1.0, 1.0};
}

}  // namespace

Geometry geometry_of_type(int p, int q) {
  // Compare 1/p + 1/q with 1/2 in integers: 2(p + q) against pq.
  const long long lhs = 2LL * (p + q), rhs = 1LL * p * q;
  if (lhs > rhs) return Geometry::Spherical;
  if (lhs == rhs) return Geometry::Euclidean;
  return Geometry::Hyperbolic;
}

const char* to_string(Geometry geometry) {
  switch (geometry) {
    case Geometry::Spherical:
      return "spherical";
    case Geometry::Euclidean:
      return "euclidean";
    case Geometry::Hyperbolic:
      return "hyperbolic";
  }
  return "?";
}

Isometry compose(Geometry geometry, const Isometry& f, const Isometry& g) {
  // A reflection f conjugates what follows it: f(g(z)) = M_f conj(M_g) conj(w).
  const Complex a2 = f.reflects ? std::conj(g.a) : g.a;
  const Complex b2 = f.reflects ? std::conj(g.b) : g.b;
  const double s = sigma(geometry);
  const Complex a = f.a * a2 + s * f.b * std::conj(b2);
  const Complex b = f.a * b2 + f.b * std::conj(a2);
  return normalized(geometry, a, b, f.reflects != g.reflects);
}

Isometry inverse(Geometry geometry, const Isometry& f) {
  if (f.reflects) return normalized(geometry, f.a, -std::conj(f.b), true);
  return normalized(geometry, std::conj(f.a), -f.b, false);
}

Point apply(Geometry geometry, const Isometry& f, const Point& z) {
  const Complex num = f.reflects ? std::conj(z.num) : z.num;
  const Complex den = f.reflects ? std::conj(z.den) : z.den;
  return {f.a * num + f.b * den, sigma(geometry) * std::conj(f.b) * num + std::conj(f.a) * den};
}

Isometry translation_to(Geometry geometry, Complex c) {
  return normalized(geometry, Complex(1.0, 0.0), c, false);
}

Isometry rotation(double angle) {
  return {std::polar(1.0, angle / 2), Complex(0.0, 0.0), false};
}

Isometry conjugation() {
  return {Complex(1.0, 0.0), Complex(0.0, 0.0), true};
}

Complex to_plane(const Point& z) {
  return z.num / z.den;
}

Vec3 to_sphere(const Point& z) {
  const double n = std::norm(z.num), d = std::norm(z.den);
  const Complex cross_term = z.num * std::conj(z.den);
  const double scale = n + d;
  return {2 * cross_term.real() / scale, 2 * cross_term.imag() / scale, (d - n) / scale};
}

double distance(Geometry geometry, const Point& z, const Point& w) {
  if (geometry == Geometry::Spherical) {
    const Vec3 u = to_sphere(z), v = to_sphere(w);
    return std::atan2(length(cross(u, v)), dot(u, v));
  }
  const Complex a = to_plane(z), b = to_plane(w);
  const double rho = std::abs(a - b) / std::abs(1.0 - sigma(geometry) * std::conj(b) * a);
  return distance_of_radius(geometry, rho);
}

Point geodesic_point(Geometry geometry, const Point& z, const Point& w, double t) {
  if (geometry == Geometry::Spherical) {
    // Slerp on the unit sphere.
    const Vec3 u = to_sphere(z), v = to_sphere(w);
    const double angle = std::atan2(length(cross(u, v)), dot(u, v));
    if (angle < 1e-15) return z;
    const double cu = std::sin((1 - t) * angle) / std::sin(angle);
    const double cv = std::sin(t * angle) / std::sin(angle);
    return from_sphere({cu * u.x + cv * v.x, cu * u.y + cv * v.y, cu * u.z + cv * v.z});
  }
  // Move z to the origin, where the geodesic to w is a straight ray, step along it, move back.
  const Isometry to_z = translation_to(geometry, to_plane(z));
  const Complex end = to_plane(apply(geometry, inverse(geometry, to_z), w));
  const double r = std::abs(end);
  if (r < 1e-300) return z;
  const double d = distance_of_radius(geometry, r);
  const Complex step = end / r * model_radius(geometry, t * d);
  return apply(geometry, to_z, Point{step, Complex(1.0, 0.0)});
}

FundamentalTriangle fundamental_triangle(int p, int q) {
  FundamentalTriangle d;
  d.geometry = geometry_of_type(p, q);
  const double alpha = std::numbers::pi / p, beta = std::numbers::pi / q;
  const auto [mn, mo] = side_lengths(d.geometry, alpha, beta);
  const Complex n0(model_radius(d.geometry, mn), 0.0);
  const Complex o0 = std::polar(model_radius(d.geometry, mo), alpha);
  d.corners = {Point{}, Point{n0, 1.0}, Point{o0, 1.0}};
  d.r = rotation(2 * alpha);
  const Isometry to_n0 = translation_to(d.geometry, n0);
  d.s = compose(d.geometry, to_n0,
                compose(d.geometry, rotation(2 * beta), inverse(d.geometry, to_n0)));
  d.t = conjugation();
  return d;
}

}  // namespace tessera::regmap
