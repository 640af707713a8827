#include "regmap/relaxation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Geometry>

#include "base/error.h"
#include "regmap/tube_curve.h"

namespace tessera::regmap {

namespace {

using Eigen::Vector3d;

constexpr double kSoftening = 0.05;  // keeps the Coulomb force finite for coincident particles
constexpr double kMaxMove = 0.1;     // per step, in units of the spring length
constexpr double kMaxTurn = 0.1;     // per step, radians
constexpr int kContactRefresh = 4;   // steps between searches for tubes in contact

// Forces on the bodies of one iteration: the junctions (force and torque about the node) and the
// edge midpoints.
struct Forces {
  std::vector<Vector3d> node_force, node_torque, midpoint_force;
  // The stiffness of the contact springs pulling on each body, added to its own in the step.
  std::vector<double> node_contact, midpoint_contact;
  double energy = 0.0;

  void on_star(const EmbeddedGraph& embedded, std::size_t node, const Vector3d& at,
               const Vector3d& force) {
    node_force[node] += force;
    node_torque[node] += (at - embedded.node_position[node]).cross(force);
  }
};

// Where a dart's tube runs in the model of the relaxation: from its start h (the junction's reach
// along the dart) to its tip c (one arm further, rigid with the junction), then to the midpoint.
struct DartPoints {
  Vector3d direction, start, tip;
};

std::vector<DartPoints> dart_points(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                                    const JunctionOrder& order) {
  std::vector<DartPoints> points;
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d) {
    const Vector3d& x = embedded.node_position[static_cast<std::size_t>(graph.dart_node[d])];
    const Vector3d u = dart_direction(embedded, graph, order, static_cast<std::int32_t>(d));
    points.push_back({u, x + embedded.reach * u, x + (embedded.reach + embedded.arm) * u});
  }
  return points;
}

// Hooke springs (rest length 1) from each dart's tip to its midpoint, and the alignment springs
// towards the point one unit further along the dart.
void add_dart_springs(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                      const std::vector<DartPoints>& darts, double alignment, Forces& f) {
  for (std::size_t d = 0; d < darts.size(); ++d) {
    const auto v = static_cast<std::size_t>(graph.dart_node[d]);
    const auto e = static_cast<std::size_t>(graph.dart_edge[d]);
    const Vector3d delta = embedded.edge_path[e][0] - darts[d].tip;
    const double length = delta.norm();
    if (length > 0.0) {
      const double stretch = length - 1.0;
      const Vector3d pull = stretch * delta / length;
      f.energy += 0.5 * stretch * stretch;
      f.midpoint_force[e] -= pull;
      f.on_star(embedded, v, darts[d].tip, pull);
    }
    const Vector3d aligned = darts[d].tip + darts[d].direction;
    const Vector3d miss = embedded.edge_path[e][0] - aligned;
    f.energy += 0.5 * alignment * miss.squaredNorm();
    f.midpoint_force[e] -= alignment * miss;
    f.on_star(embedded, v, aligned, alignment * miss);
  }
}

// Coulomb repulsion between all pairs of junctions and midpoints, on flat coordinate arrays (the
// inner loop is the relaxation's hot spot).
void add_coulomb(const EmbeddedGraph& embedded, double charge, double node_charge, Forces& f) {
  const std::size_t nodes = embedded.node_position.size();
  const std::size_t n = nodes + embedded.edge_path.size();
  std::vector<double> x(n), y(n), z(n), q(n, std::sqrt(charge)), fx(n, 0.0), fy(n, 0.0), fz(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vector3d& p = i < nodes ? embedded.node_position[i] : embedded.edge_path[i - nodes][0];
    x[i] = p.x();
    y[i] = p.y();
    z[i] = p.z();
    if (i < nodes) q[i] *= node_charge;
  }
  double energy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double gx = 0.0, gy = 0.0, gz = 0.0;
    for (std::size_t j = i + 1; j < n; ++j) {
      const double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j];
      const double inverse = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz + kSoftening * kSoftening);
      const double qq = q[i] * q[j] * inverse;
      const double s = qq * inverse * inverse;
      gx += s * dx;
      gy += s * dy;
      gz += s * dz;
      fx[j] -= s * dx;
      fy[j] -= s * dy;
      fz[j] -= s * dz;
      energy += qq;
    }
    fx[i] += gx;
    fy[i] += gy;
    fz[i] += gz;
  }
  f.energy += energy;
  for (std::size_t i = 0; i < n; ++i) {
    Vector3d& target = i < nodes ? f.node_force[i] : f.midpoint_force[i - nodes];
    target += Vector3d(fx[i], fy[i], fz[i]);
  }
}

// ---- Contact between tubes --------------------------------------------------------------------

// The tubes as the relaxation sees them: each edge's centreline (tube_curve.h) sampled into short
// segments, plus one spoke per dart from its node to its tube start (the junction's plate lies
// within twice the tube radius of its spokes). A sample point of an edge's first arc moves with the
// first dart's junction and the midpoint, weighted by the Bernstein weights of the arc's ends; of
// its second arc, with the midpoint and the second junction.
struct SamplePoint {
  Vector3d p;
  std::int32_t node = -1;  // the junction it moves with, with weight to_node
  double to_node = 0.0;
  std::int32_t edge = -1;  // the midpoint it moves with, with weight to_midpoint
  double to_midpoint = 0.0;
};

struct Segment {
  SamplePoint a, b;
  std::int32_t edge = -1;  // -1 for a spoke
  std::int32_t node = -1;  // a spoke's node, or the node at a curve segment's start (else -1)
};

constexpr int kSamplesPerArc = 4;

std::vector<Segment> tube_segments(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                                   const JunctionOrder& order) {
  std::vector<Segment> segments;
  for (std::size_t d = 0; d < graph.dart_node.size(); ++d) {
    const std::int32_t v = graph.dart_node[d];
    const Vector3d& x = embedded.node_position[static_cast<std::size_t>(v)];
    const Vector3d start =
        x + embedded.reach * dart_direction(embedded, graph, order, static_cast<std::int32_t>(d));
    segments.push_back({{x, v, 1.0, -1, 0.0}, {start, v, 1.0, -1, 0.0}, -1, v});
  }
  for (std::size_t e = 0; e < graph.edge_count; ++e) {
    const std::vector<Bezier> arcs = edge_centreline(embedded, graph, order, e);
    const auto edge = static_cast<std::int32_t>(e);
    for (std::size_t k = 0; k < 2; ++k) {
      const std::int32_t node = graph.dart_node[static_cast<std::size_t>(order.edge_darts[e][k])];
      SamplePoint previous;
      for (int i = 0; i <= kSamplesPerArc; ++i) {
        const double t = static_cast<double>(i) / kSamplesPerArc;
        const double near_start = (1 - t) * (1 - t) * (1 + 2 * t);  // b0 + b1 of the arc
        const double to_node = k == 0 ? near_start : 1 - near_start;
        const SamplePoint point{arcs[k].at(t), node, to_node, edge, 1 - to_node};
        if (i > 0) segments.push_back({previous, point, edge, i == 1 && k == 0 ? node : -1});
        if (i == kSamplesPerArc && k == 1) segments.back().node = node;
        previous = point;
      }
    }
  }
  return segments;
}

// Pieces that meet by construction are not in contact: two pieces of one edge, two spokes of one
// junction, and the pieces at one junction's tube starts (spokes and first curve segments).
bool adjacent(const Segment& s, const Segment& t) {
  if (s.edge >= 0 && s.edge == t.edge) return true;
  return s.node >= 0 && s.node == t.node;
}

// The closest points of segments [p0, p1] and [q0, q1], as parameters (s, t) in [0, 1]
// (the classical clamped solution of the 2x2 normal equations).
std::array<double, 2> closest_parameters(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0,
                                         const Vector3d& q1) {
  const Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double kTiny = 1e-18;
  if (a <= kTiny && e <= kTiny) return {0.0, 0.0};
  if (a <= kTiny) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (e <= kTiny) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = d1.dot(d2), denominator = a * e - b * b;
  double s = denominator > kTiny ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

void push_point(const SamplePoint& point, const Vector3d& force, double stiffness,
                const EmbeddedGraph& embedded, Forces& f) {
  if (point.node >= 0 && point.to_node > 0.0) {
    const auto node = static_cast<std::size_t>(point.node);
    f.on_star(embedded, node, point.p, point.to_node * force);
    f.node_contact[node] += point.to_node * stiffness;
  }
  if (point.edge >= 0 && point.to_midpoint > 0.0) {
    const auto edge = static_cast<std::size_t>(point.edge);
    f.midpoint_force[edge] += point.to_midpoint * force;
    f.midpoint_contact[edge] += point.to_midpoint * stiffness;
  }
}

using CellKey = std::uint64_t;

CellKey cell_key(const Vector3d& p, double cell) {
  constexpr std::int64_t kOffset = 1 << 20;
  auto coordinate = [&](double x) {
    return static_cast<CellKey>(std::clamp<std::int64_t>(
        static_cast<std::int64_t>(std::floor(x / cell)) + kOffset, 0, 2 * kOffset - 1));
  };
  return coordinate(p.x()) | coordinate(p.y()) << 21 | coordinate(p.z()) << 42;
}

using SegmentPair = std::array<std::uint32_t, 2>;

// The pairs of non-adjacent segments whose boxes, grown by `radius`, overlap: found through a
// uniform grid with cells as large as the average box.
std::vector<SegmentPair> contact_candidates(const std::vector<Segment>& segments, double radius) {
  std::vector<std::array<Vector3d, 2>> boxes;
  double extent = 0.0;
  for (const Segment& s : segments) {
    boxes.push_back(
        {s.a.p.cwiseMin(s.b.p).array() - radius / 2, s.a.p.cwiseMax(s.b.p).array() + radius / 2});
    extent += (boxes.back()[1] - boxes.back()[0]).maxCoeff();
  }
  const double cell = std::max(radius, extent / static_cast<double>(segments.size()));
  std::unordered_map<CellKey, std::vector<std::uint32_t>> cells;
  for (std::uint32_t i = 0; i < segments.size(); ++i) {
    const Vector3d first = (boxes[i][0] / cell).array().floor();
    const Vector3d last = (boxes[i][1] / cell).array().floor();
    for (double x = first.x(); x <= last.x(); ++x)
      for (double y = first.y(); y <= last.y(); ++y)
        for (double z = first.z(); z <= last.z(); ++z)
          cells[cell_key(Vector3d(x + 0.5, y + 0.5, z + 0.5) * cell, cell)].push_back(i);
  }
  std::vector<SegmentPair> pairs;
  for (const auto& [key, list] : cells) {
    for (std::size_t m = 0; m < list.size(); ++m) {
      for (std::size_t n = m + 1; n < list.size(); ++n) {
        const std::uint32_t i = list[m], j = list[n];
        const Vector3d lo = boxes[i][0].cwiseMax(boxes[j][0]);
        const Vector3d hi = boxes[i][1].cwiseMin(boxes[j][1]);
        // Each pair once: in the cell where the overlap of the boxes begins.
        if ((lo.array() > hi.array()).any() || cell_key(lo, cell) != key) continue;
        if (!adjacent(segments[i], segments[j])) pairs.push_back({std::min(i, j), std::max(i, j)});
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());  // a fixed order: the same sums on every platform
  return pairs;
}

// A linear penalty spring between the segments of every candidate pair closer than `clearance`.
void add_contacts(const EmbeddedGraph& embedded, const std::vector<Segment>& segments,
                  const std::vector<SegmentPair>& pairs, double clearance, double stiffness,
                  Forces& f) {
  for (const auto& [i, j] : pairs) {
    const Segment& a = segments[i];
    const Segment& b = segments[j];
    const auto [s, t] = closest_parameters(a.a.p, a.b.p, b.a.p, b.b.p);
    const Vector3d apart = (a.a.p + s * (a.b.p - a.a.p)) - (b.a.p + t * (b.b.p - b.a.p));
    const double distance = apart.norm();
    if (distance >= clearance || distance == 0.0) continue;
    const double overlap = clearance - distance;
    f.energy += 0.5 * stiffness * overlap * overlap;
    const Vector3d push = stiffness * overlap * apart / distance;
    push_point(a.a, (1 - s) * push, (1 - s) * stiffness, embedded, f);
    push_point(a.b, s * push, s * stiffness, embedded, f);
    push_point(b.a, -(1 - t) * push, (1 - t) * stiffness, embedded, f);
    push_point(b.b, -t * push, t * stiffness, embedded, f);
  }
}

// How many candidate pairs of segments are closer than `distance`.
std::size_t count_closer(const std::vector<Segment>& segments,
                         const std::vector<SegmentPair>& pairs, double distance) {
  std::size_t count = 0;
  for (const auto& [i, j] : pairs) {
    const Segment& a = segments[i];
    const Segment& b = segments[j];
    const auto [s, t] = closest_parameters(a.a.p, a.b.p, b.a.p, b.b.p);
    count += ((a.a.p + s * (a.b.p - a.a.p)) - (b.a.p + t * (b.b.p - b.a.p))).norm() < distance;
  }
  return count;
}

Forces compute_forces(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                      const JunctionOrder& order, const RelaxOptions& options,
                      const std::vector<SegmentPair>& contacts, double contact_stiffness) {
  Forces f;
  f.node_force.assign(graph.node_count, Vector3d::Zero());
  f.node_torque.assign(graph.node_count, Vector3d::Zero());
  f.midpoint_force.assign(graph.edge_count, Vector3d::Zero());
  f.node_contact.assign(graph.node_count, 0.0);
  f.midpoint_contact.assign(graph.edge_count, 0.0);
  add_dart_springs(embedded, graph, dart_points(embedded, graph, order), options.alignment, f);
  add_coulomb(embedded, options.charge, options.node_charge, f);
  if (contact_stiffness > 0.0)
    add_contacts(embedded, tube_segments(embedded, graph, order), contacts, options.clearance,
                 contact_stiffness, f);
  return f;
}

Vector3d capped(const Vector3d& v, double cap) {
  const double n = v.norm();
  return n > cap ? Vector3d(v * (cap / n)) : v;
}

// One preconditioned (Jacobi) gradient step: each body moves by step * force / stiffness, where a
// junction's stiffness grows with its q springs and its lever arms, and every body's with the
// contact springs on it. Without the contacts in the stiffness, a stiff contact would make the
// step overshoot and the iteration oscillate chaotically, so that rounding differences between
// platforms grew into different surfaces. Returns the root mean square of the motions.
double take_step(EmbeddedGraph& embedded, const Forces& f, int valence, double step) {
  const double arm = embedded.reach + embedded.arm + 1.0;
  double squared = 0.0;
  for (std::size_t v = 0; v < embedded.node_position.size(); ++v) {
    const double stiffness = valence + f.node_contact[v];
    const Vector3d move = capped(step * f.node_force[v] / stiffness, kMaxMove);
    embedded.node_position[v] += move;
    const Vector3d turn = capped(step * f.node_torque[v] / (stiffness * arm * arm), kMaxTurn);
    if (turn.norm() > 0.0) {
      const Eigen::Matrix3d rotation =
          Eigen::AngleAxisd(turn.norm(), turn.normalized()).toRotationMatrix();
      const Eigen::Quaterniond frame(rotation * embedded.node_frame[v]);
      embedded.node_frame[v] = frame.normalized().toRotationMatrix();
    }
    squared += move.squaredNorm();
  }
  for (std::size_t e = 0; e < embedded.edge_path.size(); ++e) {
    const Vector3d move =
        capped(step * f.midpoint_force[e] / (2.0 + f.midpoint_contact[e]), kMaxMove);
    embedded.edge_path[e][0] += move;
    squared += move.squaredNorm();
  }
  const double bodies =
      static_cast<double>(embedded.node_position.size() + embedded.edge_path.size());
  return std::sqrt(squared / bodies);
}

// A fixed displacement of every midpoint by up to kNudge in each coordinate, from an integer hash
// of its edge. The Jemisphere start is symmetric, an unstable equilibrium of the forces: without
// the nudge, the last bits of its coordinates (from the platform's sin, cos and cosh) would choose
// the way out, and native and wasm builds would relax into different surfaces.
void break_symmetry(EmbeddedGraph& embedded) {
  constexpr double kNudge = 1e-3;
  for (std::size_t e = 0; e < embedded.edge_path.size(); ++e) {
    std::uint32_t x = static_cast<std::uint32_t>(e) * 2654435761u + 1u;
    for (int k = 0; k < 3; ++k) {
      x ^= x >> 13;
      x *= 0x5bd1e995u;
      x ^= x >> 15;
      embedded.edge_path[e][0][k] += kNudge * (static_cast<double>(x % 2001) / 1000.0 - 1.0);
    }
  }
}

}  // namespace

double max_dart_angle(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                      const JunctionOrder& order) {
  double largest = 0.0;
  const std::vector<DartPoints> darts = dart_points(embedded, graph, order);
  for (std::size_t d = 0; d < darts.size(); ++d) {
    const Vector3d chord =
        embedded.edge_path[static_cast<std::size_t>(graph.dart_edge[d])][0] - darts[d].start;
    if (chord.norm() == 0.0) continue;
    largest = std::max(
        largest, std::acos(std::clamp(darts[d].direction.dot(chord.normalized()), -1.0, 1.0)));
  }
  return largest;
}

RelaxReport relax_embedding(EmbeddedGraph& embedded, const EdgeGraph& graph,
                            const JunctionOrder& order, const RelaxOptions& options,
                            const Progress& progress) {
  for (const std::vector<Vector3d>& path : embedded.edge_path)
    if (path.size() != 1) throw Error("the relaxation moves edge paths of one point, the midpoint");
  break_symmetry(embedded);
  RelaxReport report;
  const int iterations = std::max(options.iterations, 0);
  const int contact_from = iterations / 2;
  const int tail = std::max(iterations / 10, 1);
  double energy_before_tail = 0.0;
  std::vector<SegmentPair> contacts;
  for (int it = 0; it < iterations; ++it) {
    if (it % 16 == 0) progress.step("relaxation", static_cast<double>(it) / iterations);
    // The contacts come in during the second half, stiffening linearly. The candidates are
    // searched within twice the clearance every few steps (a Verlet list).
    const double contact =
        it < contact_from ? 0.0
                          : options.contact * (it - contact_from + 1) / (iterations - contact_from);
    if (it >= contact_from && (it - contact_from) % kContactRefresh == 0)
      contacts = contact_candidates(tube_segments(embedded, graph, order), 2.0 * options.clearance);
    const Forces f = compute_forces(embedded, graph, order, options, contacts, contact);
    if (it == iterations - tail) energy_before_tail = f.energy;
    const double decay = 1.0 - 0.95 * it / iterations;
    report.rms_motion = take_step(embedded, f, order.valence, options.step * decay);
  }
  // Settling: while tubes still overlap (centrelines closer than 0.6 clearances, about 2.4 tube
  // radii), more steps at full contact stiffness and a fifth of the first step, within a second
  // fixed budget.
  const double overlap = 0.6 * options.clearance;
  int settled = 0;
  for (; settled < options.settle_iterations; ++settled) {
    if (settled % kContactRefresh == 0) {
      const std::vector<Segment> segments = tube_segments(embedded, graph, order);
      contacts = contact_candidates(segments, 2.0 * options.clearance);
      if (count_closer(segments, contacts, overlap) == 0) break;
      progress.step("relaxation", 1.0);
    }
    const Forces f = compute_forces(embedded, graph, order, options, contacts, options.contact);
    take_step(embedded, f, order.valence, 0.2 * options.step);
  }
  const std::vector<Segment> segments = tube_segments(embedded, graph, order);
  contacts = contact_candidates(segments, 2.0 * options.clearance);
  report.overlaps = count_closer(segments, contacts, overlap);
  report.iterations = iterations + settled;
  report.energy = compute_forces(embedded, graph, order, options, contacts, options.contact).energy;
  if (iterations > 0 && energy_before_tail != 0.0)
    report.energy_change =
        std::abs(report.energy - energy_before_tail) / std::abs(energy_before_tail);
  report.max_dart_angle = max_dart_angle(embedded, graph, order);
  progress.step("relaxation", 1.0);
  return report;
}

}  // namespace tessera::regmap
