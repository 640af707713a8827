// Rotation pairings (thesis Sec. 9.5, where it finds none for the Hurwitz surfaces;
// REGMAP_NOTES.md, last section): Sym+(T) = <S, R S> paired with rotations of M when no three
// reflections pair.
//
// Sym+(T) acts on T's surface with quotient a sphere with four cone points: the junction poles
// P1, P4 (order q_T, fixed by S) and the tube's midpoints P2, P3 (order 2, fixed by R S). Two
// quarter tubes, Q and its mirror c Q across the junction side P4 P1, make a fundamental domain;
// their other sides are paired by rotations: Q's top seam P1 P2 with c Q's by S (about P1), its
// bottom seam P3 P4 with c Q's by S again (about P4), its midpoint side P2 P3 with c Q's by R.
// In M's universal cover the same domain is a hexagon D = Q u cQ with
//   X  = the rotation by 2pi/q_T about P1, a lift of x = phi(S),
//   Y2 = the half-turn about P2, a lift of y = phi(R S),
//   Y3 = the half-turn about P3, another lift of y,
//   X' = X Y2 Y3, which must be a rotation by 2pi/q_T about a point P4 (a lift of x again),
// Q = P1 P2 P3 P4 and c Q = P1 (X P2) (X' P3) P4. When Q is convex and counterclockwise, c Q
// convex and clockwise (so they lie on the two sides of P4 P1), and the angles of D at P1, P4 sum
// to 2pi/q_T and at P2, X P2 and at P3, X' P3 to pi, Poincare's polygon theorem makes D a
// fundamental domain of the group its side pairings generate, a subgroup of the preimage of
// phi(Sym+(T)) of the same area (both orbifolds have the genus-g surface's area over 2E_T), hence
// the whole preimage: quarter tube g carries phi(g) Q and quarter tube g c carries phi(g) c Q.
//
// The search: up to Sym(M), P1 is D0's vertex N0 (q_T divides q_M) or face centre M0 (q_T divides
// p_M) and X turns counterclockwise (a mirror through P1 turns every pairing into one of these).
// P2 runs over the half-turn centres of M's tiling (edge midpoints, vertices and face centres of
// even valence) within a radius of P1 (limits.radius, or by default 1.5 past the distance MN from
// a vertex to a face centre, cosh MN = cot(pi/p) cot(pi/q), within [4.5, 8]: large p and q put
// the corners far out), in one sector of P1's rotations; y is its half-turn,
// and S -> x, R S -> y must extend to an isomorphism onto its image (rotation_images). P3 runs
// over the centres with the same half-turn y; X' and P4 follow and the polygon is checked.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "regmap/pairing.h"

namespace tessera::regmap {

namespace {

// Quadrilaterals kept per pair (x, y).
constexpr std::size_t kQuadrilateralsPerRotation = 3;

struct Centre {
  Point point;
  Element half_turn = 0;  // the element of Sym+(M) turning by pi about the point
};

// The word rotating counterclockwise about D0's corner by 2pi / sectors, to the power k.
Word rotation_word(Corner corner, int k) {
  Word w;
  for (int i = 0; i < k; ++i) {
    if (corner == kM) w.push_back(Letter::R);
    if (corner == kN) w.push_back(Letter::S);
    if (corner == kO) w.insert(w.end(), {Letter::R, Letter::S});
  }
  return w;
}

Isometry about(Geometry g, const Point& centre, double angle) {
  const Isometry to = translation_to(g, to_plane(centre));
  return compose(g, compose(g, to, rotation(angle)), inverse(g, to));
}

// The angle at `v` from the direction to `from` to the direction to `to`, in (-pi, pi].
double turn_angle(Geometry g, const Point& v, const Point& from, const Point& to) {
  const Isometry back = inverse(g, translation_to(g, to_plane(v)));
  return std::arg(to_plane(apply(g, back, to)) / to_plane(apply(g, back, from)));
}

// The interior angles of a quadrilateral, positive when it is counterclockwise.
std::array<double, 4> corner_angles(Geometry g, const std::array<Point, 4>& q) {
  std::array<double, 4> angle{};
  for (std::size_t i = 0; i < 4; ++i)
    angle[i] = turn_angle(g, q[i], q[(i + 1) % 4], q[(i + 3) % 4]);
  return angle;
}

bool same_quadrilateral(Geometry g, const std::array<Point, 4>& u, const std::array<Point, 4>& v) {
  for (std::size_t i = 0; i < 4; ++i)
    if (!same_point(g, u[i], v[i])) return false;
  return true;
}

bool convex(const std::array<double, 4>& angle, double sign) {
  return std::all_of(angle.begin(), angle.end(), [&](double a) {
    return sign * a > kLengthTolerance && sign * a < std::numbers::pi - kLengthTolerance;
  });
}

// The fixed point of an orientation-preserving isometry of the disk, and its rotation angle
// there; false when it is not a rotation.
bool rotation_centre(Geometry g, const Isometry& f, Point& centre, double& angle) {
  if (f.reflects || std::abs(f.a.real()) >= 1.0 - 1e-12) return false;
  // conj(b) z^2 + (conj(a) - a) z - b = 0, the root inside the disk.
  const Complex qa = std::conj(f.b), qb = std::conj(f.a) - f.a, qc = -f.b;
  Complex z = 0;
  if (std::abs(qa) > 1e-15) {
    const Complex root = std::sqrt(qb * qb - 4.0 * qa * qc);
    const Complex z1 = (-qb + root) / (2.0 * qa), z2 = (-qb - root) / (2.0 * qa);
    z = std::abs(z1) < std::abs(z2) ? z1 : z2;
  }
  if (std::abs(z) >= 1.0) return false;
  centre = Point{z, 1.0};
  const Isometry to = translation_to(g, z);
  const Isometry local = compose(g, compose(g, inverse(g, to), f), to);
  angle = std::arg(local.a / std::conj(local.a));
  return true;
}

class RotationFinder {
 public:
  RotationFinder(const FiniteGroup& source, const ElementWords& words, const Presentation& target,
                 const FiniteGroup& target_group, const PairingLimits& limits)
      : source_(source),
        words_(words),
        target_(target),
        target_group_(target_group),
        limits_(limits),
        cover_(source),
        radius_(limits.radius > 0 ? limits.radius : automatic_radius(cover_)) {}

  PairingSearch run() {
    for (Corner apex : {kN, kM}) {
      if (cover_.sectors(apex) % target_.q != 0) continue;
      search_from(apex);
    }
    std::stable_sort(
        result_.pairings.begin(), result_.pairings.end(),
        [](const Pairing& u, const Pairing& v) { return u.distortion < v.distortion; });
    result_.steps = cover_.steps();
    return std::move(result_);
  }

 private:
  static double automatic_radius(const Cover& cover) {
    const CoverTriangle d0;
    const double mn = distance(cover.geometry(), cover.corner(d0, kM), cover.corner(d0, kN));
    return std::clamp(mn + 1.5, 4.5, 8.0);
  }

  // The half-turn centres within radius_ of p1, by a flood fill of the cover.
  std::vector<Centre> centres_near(const Point& p1) {
    const Geometry g = cover_.geometry();
    auto key = [](const Point& z) {
      const Complex w = to_plane(z);
      return std::pair<long long, long long>(std::llround(w.real() * 1e8),
                                             std::llround(w.imag() * 1e8));
    };
    std::map<std::pair<long long, long long>, bool> placed;
    std::map<std::pair<long long, long long>, Centre> centres;
    // A point inside each triangle names it: its corners' mean in the disk.
    auto inside = [&](const CoverTriangle& t) {
      Complex z = 0;
      for (Corner c : {kM, kN, kO}) z += to_plane(cover_.corner(t, c)) / 3.0;
      return Point{z, 1.0};
    };
    std::vector<CoverTriangle> queue = {CoverTriangle{}};
    placed[key(inside(queue[0]))] = true;
    for (std::size_t i = 0; i < queue.size(); ++i) {
      if (cover_.steps() > limits_.max_steps) {
        result_.stopped = true;
        break;
      }
      const CoverTriangle t = queue[i];
      for (Corner c : {kM, kN, kO}) {
        const int n = cover_.sectors(c);
        if (n % 2 != 0) continue;
        const Point z = cover_.corner(t, c);
        if (distance(g, p1, z) > radius_) continue;
        auto [it, added] = centres.try_emplace(key(z));
        if (added)
          it->second = {z, words_.conjugate(t.element, source_.times(0, rotation_word(c, n / 2)))};
      }
      for (Side side : kSides) {
        const CoverTriangle next = cover_.across(t, side);
        if (distance(g, p1, cover_.corner(next, kO)) > radius_ + 1.0) continue;
        if (placed.emplace(key(inside(next)), true).second) queue.push_back(next);
      }
    }
    std::vector<Centre> out;
    for (auto& [k, centre] : centres) out.push_back(centre);
    return out;
  }

  void search_from(Corner apex) {
    const Geometry g = cover_.geometry();
    const Point p1 = cover_.corner(CoverTriangle{}, apex);
    const int sectors = cover_.sectors(apex);
    const Element x = source_.times(0, rotation_word(apex, sectors / target_.q));
    const double turn = 2 * std::numbers::pi / target_.q;
    const Isometry rotate = about(g, p1, turn);
    const std::vector<Centre> centres = centres_near(p1);
    std::map<Element, std::vector<const Centre*>> by_half_turn;
    for (const Centre& c : centres) by_half_turn[c.half_turn].push_back(&c);
    const Word wx_inverse = words_.word(words_.inverse(x));
    pairs_with_.clear();
    // A reference direction at P1: towards D0's other corner on the side M0 N0.
    const Point reference = cover_.corner(CoverTriangle{}, apex == kN ? kM : kN);
    for (const Centre& c2 : centres) {
      if (same_point(g, c2.point, p1)) continue;
      double sector = turn_angle(g, p1, reference, c2.point);
      if (sector < 0) sector += 2 * std::numbers::pi;
      if (sector >= 2 * std::numbers::pi / sectors - 1e-9) continue;
      const Element y = c2.half_turn;
      // Whether S -> x, R S -> y extends to an isomorphism depends on y alone: asked once per y
      // (a large disk holds many lifts of each half-turn).
      const auto [known, added] = pairs_with_.try_emplace(y, false);
      if (added)
        known->second = element_order(source_, words_.word(source_.times(y, wx_inverse))) ==
                            static_cast<std::size_t>(target_.p) &&
                        !rotation_images(target_group_, words_, x, y).empty();
      if (!known->second) continue;
      const Isometry y2 = about(g, c2.point, std::numbers::pi);
      for (const Centre* c3 : by_half_turn[y]) {
        if (same_point(g, c3->point, c2.point)) continue;
        const Isometry y3 = about(g, c3->point, std::numbers::pi);
        const Isometry x4 = compose(g, compose(g, rotate, y2), y3);
        Point p4;
        double angle = 0;
        if (!rotation_centre(g, x4, p4, angle)) continue;
        if (std::abs(std::abs(angle) - turn) > 1e-6) continue;
        consider(apex, x, y, {p1, c2.point, c3->point, p4},
                 {p1, apply(g, rotate, c2.point), apply(g, x4, c3->point), p4});
      }
    }
  }

  void consider(Corner apex, Element x, Element y, const std::array<Point, 4>& q,
                const std::array<Point, 4>& mirrored) {
    const Geometry g = cover_.geometry();
    if (same_point(g, q[0], q[3])) return;
    const std::array<double, 4> a = corner_angles(g, q), b = corner_angles(g, mirrored);
    if (!convex(a, 1.0) || !convex(b, -1.0)) return;
    const double pi = std::numbers::pi, cone = 2 * pi / target_.q;
    const std::array<double, 4> sum = {cone, pi, pi, cone};
    double imbalance = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      if (std::abs(a[i] - b[i] - sum[i]) > 1e-6) return;
      imbalance = std::max(imbalance, std::abs(a[i] + b[i]) / sum[i]);
    }
    ++result_.candidates;
    double shortest = 1e300, longest = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      const double d = distance(g, q[i], q[(i + 1) % 4]);
      shortest = std::min(shortest, d);
      longest = std::max(longest, d);
    }
    const double distortion = longest / shortest * (1 + imbalance);
    // The kQuadrilateralsPerRotation least distorted quadrilaterals of each (x, y): the drawing
    // may refuse the least distorted (a long one is drawn from points close to the Klein disk's
    // rim), and the next may draw.
    std::vector<Pairing>& pairings = result_.pairings;
    std::size_t same = 0;
    auto worst = pairings.end();
    for (auto known = pairings.begin(); known != pairings.end(); ++known) {
      if (known->x != x || known->y != y) continue;
      if (same_quadrilateral(g, known->corners, q)) return;  // met again from another lift
      ++same;
      if (worst == pairings.end() || known->distortion > worst->distortion) worst = known;
    }
    if (same >= kQuadrilateralsPerRotation) {
      if (distortion >= worst->distortion) return;
      pairings.erase(worst);
    }
    Pairing p;
    p.target = target_.name;
    p.kind = PairingKind::Rotations;
    p.x = x;
    p.y = y;
    p.corners = q;
    p.mirrored = mirrored;
    p.apex = apex;
    p.distortion = distortion;
    result_.pairings.push_back(std::move(p));
  }

  const FiniteGroup& source_;
  const ElementWords& words_;
  const Presentation& target_;
  const FiniteGroup& target_group_;
  PairingLimits limits_;
  std::map<Element, bool> pairs_with_;  // per half-turn y, for the x of the current apex
  Cover cover_;
  double radius_;  // P2, P3 within this distance of P1
  PairingSearch result_;
};

}  // namespace

PairingSearch find_rotation_pairings(const FiniteGroup& source, const ElementWords& words,
                                     const Presentation& target, const FiniteGroup& target_group,
                                     const PairingLimits& limits) {
  check_hyperbolic(source);
  if (target.q < 3 || target_group.order() == 0 || source.order() % target_group.order() != 0)
    return {};
  return RotationFinder(source, words, target, target_group, limits).run();
}

}  // namespace tessera::regmap
