#include "matching/generate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>

#include "matching/random.h"

namespace tessera::matching {

namespace {

// ---- planted instances ----

std::uint32_t add_node(MatchingProblem& problem, bool is_virtual) {
  problem.is_virtual.push_back(is_virtual ? 1 : 0);
  return static_cast<std::uint32_t>(problem.is_virtual.size() - 1);
}

std::uint32_t add_edge(MatchingProblem& problem, std::uint32_t u, std::uint32_t v, double w) {
  problem.edges.push_back({u, v, w});
  return static_cast<std::uint32_t>(problem.edges.size() - 1);
}

double random_weight(Random& random, double max_weight) {
  return 1.0 + random.unit() * (max_weight - 1.0);
}

// Pairs the nodes in a random order; a virtual node goes last when the count is odd, so that an
// odd count of ports is covered whenever a virtual port exists.
std::vector<std::uint8_t> add_planted_matching(MatchingProblem& problem, Random& random,
                                               double max_weight) {
  std::vector<std::uint32_t> order(problem.node_count());
  for (std::uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[random.below(static_cast<std::uint32_t>(i))]);
  if (order.size() % 2 == 1) {
    const auto it = std::find_if(order.begin(), order.end(),
                                 [&](std::uint32_t v) { return problem.is_virtual[v] != 0; });
    if (it != order.end()) std::iter_swap(it, order.end() - 1);
  }
  std::vector<std::uint8_t> planted;
  for (std::size_t i = 0; i + 1 < order.size(); i += 2) {
    add_edge(problem, order[i], order[i + 1], random_weight(random, max_weight));
    planted.push_back(1);
  }
  return planted;
}

void add_blocked_square(MatchingProblem& problem) {
  std::array<std::uint32_t, 4> n{};
  for (std::uint32_t& v : n) v = add_node(problem, false);
  const std::uint32_t a = add_edge(problem, n[0], n[1], 1.0);
  const std::uint32_t b = add_edge(problem, n[2], n[3], 1.0);
  const std::uint32_t c = add_edge(problem, n[1], n[2], 1.0);
  const std::uint32_t d = add_edge(problem, n[3], n[0], 1.0);
  problem.conflicts.push_back({a, b});
  problem.conflicts.push_back({c, d});
}

// ---- synthetic layout instances ----

struct Point {
  double x = 0.0, y = 0.0;
};

constexpr std::array<Point, 4> kDirections = {{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};

struct Port {
  std::uint32_t singularity = 0;
  Point origin;
  int direction = 0;  // index into kDirections
};

// Valence-3 and valence-5 singularities in pairs: the 3 lacks the direction the 5 has twice, so
// that every direction has as many ports as its opposite (a perfect matching needs that here).
std::vector<Port> synthetic_ports(const SyntheticLayoutSpec& spec, double side, Random& random) {
  constexpr double kTwinOffset = 0.08;  // the 5's second port in one direction starts beside it
  std::vector<Port> ports;
  for (std::uint32_t k = 0; k < spec.singularity_pairs; ++k) {
    const int missing = static_cast<int>(random.below(4));
    const Point three{random.unit() * side, random.unit() * side};
    const Point five{random.unit() * side, random.unit() * side};
    for (int d = 0; d < 4; ++d) {
      if (d != missing) ports.push_back({2 * k, three, d});
      ports.push_back({2 * k + 1, five, d});
    }
    const Point normal = kDirections[(missing + 1) % 4];
    ports.push_back(
        {2 * k + 1, {five.x + kTwinOffset * normal.x, five.y + kTwinOffset * normal.y}, missing});
  }
  return ports;
}

struct Candidate {
  std::uint32_t port = 0;
  Point displacement;  // from a's origin to this image of b's origin
  double along = 0.0, across = 0.0;
};

// The images of b's origin (b translated by multiples of the torus side) ahead of port a within 45
// degrees and L_max: a separatrix may wind around the torus before it meets another.
void add_images(const Port& pa, const Port& pb, std::uint32_t b, double side, double max_length,
                std::vector<Candidate>& ahead) {
  const Point d = kDirections[pa.direction];
  const int reach = static_cast<int>(std::ceil(max_length / side)) + 1;
  for (int i = -reach; i <= reach; ++i) {
    for (int j = -reach; j <= reach; ++j) {
      const Point r{pb.origin.x + i * side - pa.origin.x, pb.origin.y + j * side - pa.origin.y};
      const double along = r.x * d.x + r.y * d.y;
      const double across = -r.x * d.y + r.y * d.x;
      if (along > 0.0 && along <= max_length && std::abs(across) < along)
        ahead.push_back({b, r, along, across});
    }
  }
}

// The ports ahead of `a` within 45 degrees pointing back at it, kept by the window reduction
// (Prop. 4.1): on each side, in order of the base length, a candidate is kept only if its angle
// is below every angle kept before.
std::vector<Candidate> window_candidates(const std::vector<Port>& ports, std::uint32_t a,
                                         double side, double max_length) {
  const Port& pa = ports[a];
  std::vector<Candidate> ahead;
  for (std::uint32_t b = 0; b < ports.size(); ++b) {
    const Port& pb = ports[b];
    if (pb.singularity != pa.singularity && pb.direction == (pa.direction + 2) % 4)
      add_images(pa, pb, b, side, max_length, ahead);
  }
  std::sort(ahead.begin(), ahead.end(),
            [](const Candidate& p, const Candidate& q) { return p.along < q.along; });
  std::vector<Candidate> kept;
  double window[2] = {1.0, 1.0};  // tan of the window angle per side, 45 degrees at first
  for (const Candidate& c : ahead) {
    double& w = window[c.across < 0.0 ? 0 : 1];
    const double slope = std::abs(c.across) / c.along;
    if (slope >= w) continue;
    w = slope;
    kept.push_back(c);
  }
  return kept;
}

struct Arc {
  Point from, to;  // to = from + displacement, unwrapped
  int alignment = 0;
};

double orientation(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// The translates k * side (k integer) of the interval [q0, q1] that overlap [p0, p1].
std::pair<int, int> overlapping_shifts(double p0, double p1, double q0, double q1, double side) {
  return {static_cast<int>(std::ceil((std::min(p0, p1) - std::max(q0, q1)) / side)),
          static_cast<int>(std::floor((std::max(p0, p1) - std::min(q0, q1)) / side))};
}

// Whether the arcs cross on the torus: q is tried at every translate whose box meets p's.
bool arcs_cross(const Arc& p, const Arc& q, double side) {
  const auto [i0, i1] = overlapping_shifts(p.from.x, p.to.x, q.from.x, q.to.x, side);
  const auto [j0, j1] = overlapping_shifts(p.from.y, p.to.y, q.from.y, q.to.y, side);
  for (int i = i0; i <= i1; ++i)
    for (int j = j0; j <= j1; ++j)
      if (segments_cross(p.from, p.to, {q.from.x + i * side, q.from.y + j * side},
                         {q.to.x + i * side, q.to.y + j * side}))
        return true;
  return false;
}

// Same-aligned crossings are illegal (Sec. 4.6); a crossing of differently aligned arcs is made
// illegal with probability `mixed_rate` (Remark 4.1: a frame elsewhere on a self-crossing line can
// see it as illegal).
void add_illegal_crossings(const std::vector<Arc>& arcs, double side, double mixed_rate,
                           Random& random, MatchingProblem& problem) {
  for (std::uint32_t e = 0; e < arcs.size(); ++e)
    for (std::uint32_t f = e + 1; f < arcs.size(); ++f) {
      if (!arcs_cross(arcs[e], arcs[f], side)) continue;
      if (arcs[e].alignment == arcs[f].alignment || random.unit() < mixed_rate)
        problem.conflicts.push_back({e, f});
    }
}

}  // namespace

MatchingProblem planted_instance(const PlantedSpec& spec) {
  Random random(spec.seed);
  MatchingProblem problem;
  for (std::uint32_t i = 0; i < spec.ports; ++i) add_node(problem, false);
  for (std::uint32_t i = 0; i < spec.virtual_ports; ++i) add_node(problem, true);
  std::vector<std::uint8_t> planted = add_planted_matching(problem, random, spec.max_weight);
  const auto n = static_cast<std::uint32_t>(problem.node_count());
  for (std::uint32_t k = 0; k < spec.extra_edges && n >= 2; ++k) {
    const std::uint32_t u = random.below(n);
    const std::uint32_t v = (u + 1 + random.below(n - 1)) % n;
    add_edge(problem, u, v, random_weight(random, spec.max_weight));
  }
  planted.resize(problem.edges.size(), 0);
  const auto m = static_cast<std::uint32_t>(problem.edges.size());
  for (std::uint32_t k = 0; k < spec.conflicts && m >= 2; ++k) {
    const std::uint32_t e = random.below(m);
    const std::uint32_t f = (e + 1 + random.below(m - 1)) % m;
    if (spec.keep_planted_feasible && planted[e] && planted[f]) continue;
    problem.conflicts.push_back({e, f});
  }
  for (std::uint32_t k = 0; k < spec.blocked_squares; ++k) add_blocked_square(problem);
  return problem;
}

MatchingProblem synthetic_layout_instance(const SyntheticLayoutSpec& spec) {
  Random random(spec.seed);
  const double side = std::sqrt(2.0 * spec.singularity_pairs);  // one singularity per unit area
  const std::vector<Port> ports = synthetic_ports(spec, side, random);
  MatchingProblem problem;
  problem.is_virtual.assign(ports.size(), 0);
  // An edge found from both of its ports is added once; two images of one port give two edges.
  std::set<std::tuple<std::uint32_t, std::uint32_t, long long, long long>> seen;
  std::vector<Arc> arcs;
  for (std::uint32_t a = 0; a < ports.size(); ++a) {
    for (const Candidate& c : window_candidates(ports, a, side, spec.max_length)) {
      const double sign = a < c.port ? 1.0 : -1.0;
      const auto key = std::make_tuple(std::min(a, c.port), std::max(a, c.port),
                                       std::llround(sign * c.displacement.x * 1e6),
                                       std::llround(sign * c.displacement.y * 1e6));
      if (!seen.insert(key).second) continue;
      const double distortion = 1.0 + spec.weight_noise * (2.0 * random.unit() - 1.0);
      add_edge(problem, a, c.port, distortion * (c.along + spec.alpha * std::abs(c.across)));
      const Point from = ports[a].origin;
      arcs.push_back(
          {from, {from.x + c.displacement.x, from.y + c.displacement.y}, ports[a].direction % 2});
    }
  }
  add_illegal_crossings(arcs, side, spec.mixed_crossing_rate, random, problem);
  return problem;
}

}  // namespace tessera::matching
