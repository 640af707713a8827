#include "regmap/pairing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <tuple>

#include "base/error.h"

namespace tessera::regmap {

using enum Letter;

namespace {

// Words in M's letters for T's letters R, R^-1, S, S^-1, T under R = b c, S = c a, T = c.
std::array<Word, kLetterCount> letter_images(const ElementWords& words, Element a, Element b,
                                             Element c) {
  const Word wa = words.word(a), wb = words.word(b), wc = words.word(c);
  auto cat = [](const Word& x, const Word& y) {
    Word w = x;
    w.insert(w.end(), y.begin(), y.end());
    return w;
  };
  return {cat(wb, wc), cat(wc, wb), cat(wc, wa), cat(wa, wc), wc};
}

// Whether the quadrilateral's corners turn counterclockwise (it is convex).
bool counterclockwise(const std::array<Point, 4>& q) {
  double area = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Complex u = to_plane(q[i]), v = to_plane(q[(i + 1) % 4]);
    area += u.real() * v.imag() - u.imag() * v.real();
  }
  return area > 0;
}

// The other side of a triangle at its corner c.
Side other_side_at(Side side, Corner c) {
  for (Side s : kSides) {
    const auto corners = side_corners(s);
    if (s != side && (corners[0] == c || corners[1] == c)) return s;
  }
  return side;
}

Corner far_corner(Side side, Corner from) {
  const auto corners = side_corners(side);
  return corners[0] == from ? corners[1] : corners[0];
}

// A ray along a mirror line from a tiling vertex: `side` of `triangle` lies on it, starting at
// corner `from`; the triangle is on the ray's inner side (where hQ is).
struct Ray {
  CoverTriangle triangle;
  Side side = Side::MN;
  Corner from = kN;
  Corner to() const { return far_corner(side, from); }
};

// Turns about corner c of t (whose `side` is on a line through c) by `sectors` triangles, away
// from that line: the ray from c along the line at angle sectors * pi / cover.sectors(c).
Ray turn(Cover& cover, CoverTriangle t, Side side, Corner c, int sectors) {
  Side free = other_side_at(side, c);
  for (int k = 1; k < sectors; ++k) {
    t = cover.across(t, free);
    free = other_side_at(free, c);
  }
  return {t, free, c};
}

// The ray that goes on through the far vertex of `ray`'s side, on the same side of the line.
Ray continued(Cover& cover, const Ray& ray) {
  const Corner c = ray.to();
  return turn(cover, ray.triangle, ray.side, c, cover.sectors(c));
}

// The ray perpendicular to `ray`'s line at its far vertex, into its inner side (towards where the
// ray came from); the vertex must have an even number of sectors.
Ray perpendicular(Cover& cover, const Ray& ray) {
  const Corner c = ray.to();
  return turn(cover, ray.triangle, ray.side, c, cover.sectors(c) / 2);
}

// The leg-to-base relation of a Saccheri quadrilateral with summit angles alpha (see pairing.h);
// 0 where the leg is too short for one.
double saccheri_base(double leg, double alpha) {
  const double c = std::cos(alpha);
  const double d = std::sinh(leg) * std::sinh(leg) - c * c * std::cosh(leg) * std::cosh(leg);
  return d > 0 ? 2 * std::asinh(c / std::sqrt(d)) : 0.0;
}

// The longest leg whose base is at least `base`.
double longest_leg(double base, double alpha) {
  const double c = std::cos(alpha), s = std::sin(alpha);
  const double h = std::sinh(base / 2);
  return std::asinh(std::sqrt((c * c / (h * h) + c * c) / (s * s)));
}

// A quadrilateral that closed in the cover, before the group checks.
struct Candidate {
  Corner apex;
  std::array<Point, 4> corners;
  std::array<CoverTriangle, 4> on_line;  // a triangle with a side on L1..L4
  std::array<Side, 4> line_side;
  double leg = 0, base = 0;
};

class PairingFinder {
 public:
  PairingFinder(const FiniteGroup& source, const ElementWords& words, const Presentation& target,
                std::size_t target_order, const PairingLimits& limits)
      : source_(source),
        words_(words),
        target_(target),
        relators_(defining_relators(target)),
        target_order_(target_order),
        limits_(limits),
        cover_(source),
        alpha_(std::numbers::pi / target.q) {
    const auto& d = cover_.base().corners;
    const Geometry g = cover_.geometry();
    shortest_side_ =
        std::min({distance(g, d[kM], d[kN]), distance(g, d[kN], d[kO]), distance(g, d[kM], d[kO])});
    k_ = source.order() / target_order;
  }

  PairingSearch run() {
    for (Corner apex : {kN, kM}) {
      if (cover_.sectors(apex) % target_.q != 0) continue;
      for (Side l4 : kSides) {
        const auto corners = side_corners(l4);
        if (corners[0] != apex && corners[1] != apex) continue;
        walk_legs(apex, l4);
      }
    }
    std::stable_sort(
        result_.pairings.begin(), result_.pairings.end(),
        [](const Pairing& x, const Pairing& y) { return x.distortion < y.distortion; });
    result_.steps = cover_.steps();
    return std::move(result_);
  }

 private:
  bool out_of_steps() {
    if (cover_.steps() <= limits_.max_steps) return false;
    result_.stopped = true;
    return true;
  }

  // P1 = D0's corner `apex`, L4 through D0's side l4; candidates P2 along L1.
  void walk_legs(Corner apex, Side l4) {
    const CoverTriangle d0;
    const Point p1 = cover_.corner(d0, apex);
    const Geometry g = cover_.geometry();
    const double max_leg = longest_leg(shortest_side_, alpha_) + kLengthTolerance;
    Ray along = turn(cover_, d0, l4, apex, cover_.sectors(apex) / target_.q);
    const Ray first = along;
    for (;; along = continued(cover_, along)) {
      if (out_of_steps()) return;
      const Point p2 = cover_.corner(along.triangle, along.to());
      const double leg = distance(g, p1, p2);
      if (leg > max_leg) return;
      if (cover_.sectors(along.to()) % 2 != 0) continue;
      const double base = saccheri_base(leg, alpha_);
      if (base <= 0) continue;
      Candidate c;
      c.apex = apex;
      c.corners[0] = p1;
      c.corners[1] = p2;
      c.on_line[0] = first.triangle;
      c.line_side[0] = first.side;
      c.on_line[3] = d0;
      c.line_side[3] = l4;
      c.leg = leg;
      c.base = base;
      walk_base(perpendicular(cover_, along), c);
    }
  }

  // Candidates P3 along L2 at the Saccheri base's distance from P2.
  void walk_base(Ray along, Candidate c) {
    const Geometry g = cover_.geometry();
    c.on_line[1] = along.triangle;
    c.line_side[1] = along.side;
    for (;; along = continued(cover_, along)) {
      if (out_of_steps()) return;
      const Point p3 = cover_.corner(along.triangle, along.to());
      const double d = distance(g, c.corners[1], p3);
      if (d > c.base + kLengthTolerance) return;
      if (d < c.base - kLengthTolerance || cover_.sectors(along.to()) % 2 != 0) continue;
      c.corners[2] = p3;
      close_quadrilateral(perpendicular(cover_, along), c);
      return;
    }
  }

  // P4 along L3 at the leg's distance from P3; L4 must pass through it at angle pi/q_T.
  void close_quadrilateral(Ray along, Candidate c) {
    const Geometry g = cover_.geometry();
    c.on_line[2] = along.triangle;
    c.line_side[2] = along.side;
    for (;; along = continued(cover_, along)) {
      if (out_of_steps()) return;
      const Corner corner = along.to();
      const Point p4 = cover_.corner(along.triangle, corner);
      const double d = distance(g, c.corners[2], p4);
      if (d > c.leg + kLengthTolerance) return;
      if (d < c.leg - kLengthTolerance) continue;
      if (cover_.sectors(corner) % target_.q != 0) return;
      const Ray l4 =
          turn(cover_, along.triangle, along.side, corner, cover_.sectors(corner) / target_.q);
      const Isometry l4_mirror = cover_.mirror(l4.triangle, l4.side);
      if (!same_point(g, apply(g, l4_mirror, c.corners[0]), c.corners[0])) return;
      c.corners[3] = p4;
      ++result_.candidates;
      check_in_group(c, l4);
      return;
    }
  }

  Element reflection(const CoverTriangle& t, Side side) const {
    return words_.conjugate(t.element, source_.times(0, side_word(side)));
  }

  void check_in_group(const Candidate& c, const Ray& l4_at_p4) {
    const Element a = reflection(c.on_line[0], c.line_side[0]);
    const Element b = reflection(c.on_line[1], c.line_side[1]);
    const Element a3 = reflection(c.on_line[2], c.line_side[2]);
    const Element cc = reflection(c.on_line[3], c.line_side[3]);
    if (a != a3) return;
    // The same line from both ends must be the same element: a check of the walks.
    if (reflection(l4_at_p4.triangle, l4_at_p4.side) != cc) return;
    for (const Pairing& found : result_.pairings) {
      if (std::tie(found.a, found.b, found.c) == std::tie(a, b, cc)) return;
    }
    if (!relators_hold(a, b, cc) || generated_order(a, b, cc) != target_order_) return;
    if (!collect_flags(c)) return;
    const Geometry g = cover_.geometry();
    const Isometry l4 = cover_.mirror(c.on_line[3], c.line_side[3]);
    Pairing pairing;
    pairing.target = target_.name;
    pairing.kind = PairingKind::Reflections;
    pairing.x = words_.multiply(cc, a);
    pairing.y = words_.multiply(b, a);
    pairing.a = a;
    pairing.b = b;
    pairing.c = cc;
    pairing.corners = c.corners;
    pairing.mirrored = {c.corners[0], apply(g, l4, c.corners[1]), apply(g, l4, c.corners[2]),
                        c.corners[3]};
    pairing.apex = c.apex;
    pairing.distortion = std::max(c.leg, c.base) / std::min(c.leg, c.base);
    if (!counterclockwise(pairing.corners)) {
      // The mirror image across L4: c' hQ, with a' and b' conjugated by c'.
      std::swap(pairing.corners, pairing.mirrored);
      pairing.a = words_.conjugate(cc, a);
      pairing.b = words_.conjugate(cc, b);
      pairing.x = words_.multiply(cc, pairing.a);
      pairing.y = words_.multiply(pairing.b, pairing.a);
    }
    result_.pairings.push_back(std::move(pairing));
  }

  // T's relators with R = b c, S = c a, T = c (all three are involutions).
  bool relators_hold(Element a, Element b, Element c) const {
    const std::array<Word, kLetterCount> image = letter_images(words_, a, b, c);
    for (const Word& relator : relators_) {
      Element e = 0;
      for (Letter x : relator) e = source_.times(e, image[static_cast<std::size_t>(x)]);
      if (e != 0) return false;
    }
    return true;
  }

  // |<a, b, c>|, or more than target_order_ as soon as it exceeds it.
  std::size_t generated_order(Element a, Element b, Element c) const {
    const std::array<Word, 3> gens = {words_.word(a), words_.word(b), words_.word(c)};
    std::vector<bool> seen(source_.order(), false);
    std::vector<Element> elements = {0};
    seen[0] = true;
    for (std::size_t k = 0; k < elements.size(); ++k) {
      for (const Word& w : gens) {
        const Element h = source_.times(elements[k], w);
        if (seen[static_cast<std::size_t>(h)]) continue;
        seen[static_cast<std::size_t>(h)] = true;
        elements.push_back(h);
        if (elements.size() > target_order_) return elements.size();
      }
    }
    return elements.size();
  }

  // The flag triangles inside hQ, by a flood fill from D0 over sides not on L1..L4; they must
  // number k, all distinct.
  bool collect_flags(const Candidate& c) {
    const Geometry g = cover_.geometry();
    std::array<Isometry, 4> mirrors;
    for (std::size_t i = 0; i < 4; ++i) mirrors[i] = cover_.mirror(c.on_line[i], c.line_side[i]);
    auto on_boundary = [&](const CoverTriangle& t, Side side) {
      const auto [u, v] = side_corners(side);
      const Point pu = cover_.corner(t, u), pv = cover_.corner(t, v);
      for (const Isometry& m : mirrors) {
        if (same_point(g, apply(g, m, pu), pu) && same_point(g, apply(g, m, pv), pv)) return true;
      }
      return false;
    };
    std::set<Element> seen = {0};
    std::vector<CoverTriangle> flags = {CoverTriangle{}};
    for (std::size_t i = 0; i < flags.size(); ++i) {
      for (Side side : kSides) {
        const CoverTriangle t = flags[i];
        if (on_boundary(t, side)) continue;
        const CoverTriangle next = cover_.across(t, side);
        if (seen.count(next.element) > 0) {
          // A triangle met again must be the same triangle of the cover, not another lift.
          const Point centre = cover_.corner(next, kO);
          bool placed = false;
          for (const CoverTriangle& f : flags) {
            if (f.element == next.element && same_point(g, cover_.corner(f, kO), centre))
              placed = true;
          }
          if (!placed) return false;
          continue;
        }
        seen.insert(next.element);
        flags.push_back(next);
        if (flags.size() > k_) return false;
      }
    }
    return flags.size() == k_;
  }

  const FiniteGroup& source_;
  const ElementWords& words_;
  const Presentation& target_;
  std::vector<Word> relators_;  // T's defining relators
  std::size_t target_order_;
  PairingLimits limits_;
  Cover cover_;
  double alpha_;
  double shortest_side_ = 0;
  std::size_t k_ = 0;
  PairingSearch result_;
};

}  // namespace

const char* to_string(PairingKind kind) {
  return kind == PairingKind::Reflections ? "reflections" : "rotations";
}

void check_hyperbolic(const FiniteGroup& source) {
  if (geometry_of_type(source.p, source.q) != Geometry::Hyperbolic)
    throw InputError(
        "a map is drawn on another map's surface only when it is hyperbolic (genus "
        "2 or more); {" +
        std::to_string(source.p) + "," + std::to_string(source.q) + "} is not");
}

PairingSearch find_reflection_pairings(const FiniteGroup& source, const ElementWords& words,
                                       const Presentation& target, std::size_t target_order,
                                       const PairingLimits& limits) {
  check_hyperbolic(source);
  if (target.q < 3 || target_order == 0 || source.order() % target_order != 0) return {};
  return PairingFinder(source, words, target, target_order, limits).run();
}

PairingSearch find_pairings(const FiniteGroup& source, const ElementWords& words,
                            const Presentation& target, const FiniteGroup& target_group,
                            const PairingLimits& limits) {
  PairingSearch result =
      find_reflection_pairings(source, words, target, target_group.order(), limits);
  PairingLimits rest = limits;
  rest.max_steps = limits.max_steps > result.steps ? limits.max_steps - result.steps : 0;
  PairingSearch rotations = find_rotation_pairings(source, words, target, target_group, rest);
  const std::size_t reflections = result.pairings.size();
  for (Pairing& p : rotations.pairings) {
    const auto by_reflections = result.pairings.begin() + static_cast<std::ptrdiff_t>(reflections);
    const bool known = std::any_of(result.pairings.begin(), by_reflections,
                                   [&](const Pairing& r) { return r.x == p.x && r.y == p.y; });
    if (!known) result.pairings.push_back(std::move(p));
  }
  result.candidates += rotations.candidates;
  result.steps += rotations.steps;
  result.stopped = result.stopped || rotations.stopped;
  return result;
}

std::vector<Element> rotation_images(const FiniteGroup& target, const ElementWords& source_words,
                                     Element x, Element y) {
  const FiniteGroup& source = source_words.group();
  const Word wx = source_words.word(x);
  const Word wr = source_words.word(source_words.multiply(y, source_words.inverse(x)));
  const std::array<std::pair<Letter, const Word*>, 2> steps = {{{R, &wr}, {S, &wx}}};
  std::vector<Element> phi(target.order(), -1);
  phi[0] = 0;
  std::vector<Element> queue = {0};
  std::vector<bool> hit(source.order(), false);
  hit[0] = true;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const Element g = queue[k];
    for (const auto& [letter, image] : steps) {
      const Element h = target.times(g, letter);
      const Element e = source.times(phi[static_cast<std::size_t>(g)], *image);
      Element& known = phi[static_cast<std::size_t>(h)];
      if (known >= 0) {
        if (known != e) return {};
        continue;
      }
      if (hit[static_cast<std::size_t>(e)]) return {};
      hit[static_cast<std::size_t>(e)] = true;
      known = e;
      queue.push_back(h);
    }
  }
  return phi;
}

}  // namespace tessera::regmap
