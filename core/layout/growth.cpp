#include "layout/growth.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "base/error.h"
#include "base/limits.h"

namespace tessera::layout {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Parametric lengths (one unit is about a triangle) below which two points of a line coincide.
constexpr double kLengthTolerance = 1e-7;
// Two intersections of the same two lines closer than this (in both lengths) are one.
constexpr double kSameCrossing = 1e-6;
// Events within one tick of parametric length happen at once (growth.h, Event).
constexpr double kEventTick = 1e-6;

// Saturates: absurd lengths stay in range.
std::int64_t tick_of(double time) {
  return static_cast<std::int64_t>(std::floor(std::min(time / kEventTick, 9e18)));
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool along_u(const Eigen::Vector2d& d) {
  return std::abs(d.x()) > std::abs(d.y());
}

double length_at(const SeparatrixPiece& piece, double offset) {
  return piece.start + std::min(std::abs(offset), piece.length);
}

}  // namespace

const char* to_string(LineEnd end) {
  switch (end) {
    case LineEnd::growing:
      return "growing";
    case LineEnd::length_limit:
      return "length_limit";
    case LineEnd::spiral:
      return "spiral";
    case LineEnd::boundary:
      return "boundary";
    case LineEnd::singularity:
      return "singularity";
  }
  return "unknown";
}

SeparatrixGrowth::SeparatrixGrowth(const Charts& charts, Ports ports, const GrowthOptions& options)
    : charts_(charts), options_(options), collector_(ports.ports.size(), options.rho) {
  graph_.ports = std::move(ports);
  graph_.separatrices.resize(graph_.ports.ports.size());
  for (const Port& port : graph_.ports.ports)
    cursors_.push_back(cursor_at_corner(charts_, port.corner, port.direction));
  face_pieces_.resize(charts_.mesh.face_count());
}

void SeparatrixGrowth::grow(double length_limit, const Progress& progress) {
  graph_.length_limit = length_limit;
  using Entry = std::pair<double, Index>;  // (length traced, line): the frontier
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> growing;
  for (Index line = 0; line < graph_.separatrices.size(); ++line) {
    Separatrix& s = graph_.separatrices[line];
    if (s.end == LineEnd::length_limit && s.length < length_limit) s.end = LineEnd::growing;
    if (s.end == LineEnd::growing) growing.push({cursors_[line].length, line});
  }
  const auto is_growing = [&](Index line) {
    return graph_.separatrices[line].end == LineEnd::growing;
  };
  std::size_t since_report = 0;
  const Clock::time_point start = Clock::now();
  while (true) {
    while (!growing.empty() && !is_growing(growing.top().second)) growing.pop();
    handle_events_until(growing.empty() ? kInfinity : growing.top().first);
    if (growing.empty()) break;
    const Index line = growing.top().second;
    if (!is_growing(line)) continue;  // stopped by an event just handled
    growing.pop();
    advance(line, length_limit);
    if (is_growing(line)) growing.push({cursors_[line].length, line});
    if (++since_report == 4096) {
      since_report = 0;
      check_clock(start);
      progress.step("separatrices", std::min(1.0, cursors_[line].length / length_limit));
    }
  }
  check_clock(start);
  seconds_ += seconds_since(start);
}

void SeparatrixGrowth::check_clock(Clock::time_point start) const {
  if (seconds_ + seconds_since(start) <= options_.max_seconds) return;
  throw LimitError("growing the separatrices passed its time guard of " +
                   format_seconds(options_.max_seconds) + " after " + std::to_string(steps_) +
                   " faces crossed and " + std::to_string(crossings_found_) +
                   " crossings found, below their limits (--max-trace-steps, "
                   "--max-trace-crossings); the guard depends on the machine's speed and load, "
                   "not on the input: raise it with --max-trace-seconds");
}

Index SeparatrixGrowth::port_arriving(Index face, Index vertex,
                                      const Eigen::Vector2d& direction) const {
  const Index point = graph_.ports.point_of_vertex[vertex];
  const VertexRing& ring = graph_.ports.points[point].ring;
  for (std::size_t k = 0; k < ring.corners.size(); ++k) {
    if (charts_.connectivity.face[ring.corners[k].corner] != face) continue;
    return graph_.ports.nearest_port(point, unfolded_angle(charts_, ring, k, -direction));
  }
  return kNoIndex;
}

SeparatrixGrowth::NearSingularity SeparatrixGrowth::near_singularity(const LineCursor& cursor,
                                                                     const LineStep& step) const {
  NearSingularity nearest;
  if (!(step.length > 0)) return nearest;
  const Eigen::Vector2d travel = (step.point - cursor.point) / step.length;
  const Index first = charts_.first_corner(cursor.face);
  for (Index h = first; h < first + 3; ++h) {
    if (graph_.ports.point_of_vertex[charts_.vertex(h)] == kNoIndex) continue;
    if (cursor.starts_at_corner && h == cursor.entry) continue;  // its own singularity
    const Eigen::Vector2d to = charts_.uv(h) - cursor.point;
    const double along = to.dot(travel), offset = cross(travel, to);
    if (along < 0 || along > step.length + kNearSingularity) continue;
    if (std::abs(offset) > kNearSingularity) continue;
    if (nearest.corner == kNoIndex || along < nearest.along) nearest = {h, along, offset};
  }
  return nearest;
}

void SeparatrixGrowth::queue_end(const PendingEnd& end, double time) {
  pending_ends_.push_back(end);
  events_.push(
      {tick_of(time), 0, end.line, 0, 0, static_cast<Index>(pending_ends_.size() - 1), {}});
}

void SeparatrixGrowth::advance(Index line, double length_limit) {
  Separatrix& s = graph_.separatrices[line];
  LineCursor& cursor = cursors_[line];
  check_limit(++steps_, options_.max_steps, "separatrix tracing (faces crossed)",
              "--max-trace-steps");
  ++s.steps;
  const LineStep step = line_step(charts_, cursor);
  if (!step.valid) throw Error("separatrix " + std::to_string(line) + " leaves its port outside");
  SeparatrixPiece piece{line,          cursor.face, cursor.point, step.point, cursor.direction,
                        cursor.length, step.length};
  const double room = length_limit - cursor.length;
  const NearSingularity near = near_singularity(cursor, step);
  if (near.corner != kNoIndex && near.along < room) {
    const Eigen::Vector2d travel = (step.point - cursor.point) / step.length;
    piece.to = cursor.point + near.along * travel;
    piece.length = near.along;
    s.length = cursor.length + near.along;
    s.end = LineEnd::singularity;
    s.end_vertex = charts_.vertex(near.corner);
    queue_end({line, port_arriving(cursor.face, s.end_vertex, travel), near.offset, kNoIndex, {}},
              s.length);
    add_piece(piece);
    return;
  }
  if (step.length >= room) {
    if (step.length > 0)
      piece.to = cursor.point + (room / step.length) * (step.point - cursor.point);
    piece.length = room;
    s.length = length_limit;
    s.end = LineEnd::length_limit;
    add_piece(piece);
    return;
  }
  s.length = cursor.length + step.length;
  add_piece(piece);
  const Index face = cursor.face;
  if (!cross_edge(charts_, step, cursor)) {
    s.end = LineEnd::boundary;
    queue_end({line, kNoIndex, 0, face, step.point}, s.length);
  }
}

void SeparatrixGrowth::add_piece(const SeparatrixPiece& piece) {
  const Index index = static_cast<Index>(graph_.pieces.size());
  graph_.pieces.push_back(piece);
  graph_.separatrices[piece.line].pieces.push_back(index);
  std::vector<Index>& here = face_pieces_[piece.face];
  for (Index other : here) discover(graph_.pieces[other], graph_.pieces[index]);
  here.push_back(index);
}

// Two pieces in one chart cross only if one runs along u and the other along v: an interval test.
void SeparatrixGrowth::discover(const SeparatrixPiece& a, const SeparatrixPiece& b) {
  if (along_u(a.direction) == along_u(b.direction)) return;
  const SeparatrixPiece& u_line = along_u(a.direction) ? a : b;
  const SeparatrixPiece& v_line = along_u(a.direction) ? b : a;
  const double tolerance = charts_.tolerance(a.face);
  const double u = v_line.from.x(), v = u_line.from.y();
  if (u < std::min(u_line.from.x(), u_line.to.x()) - tolerance ||
      u > std::max(u_line.from.x(), u_line.to.x()) + tolerance ||
      v < std::min(v_line.from.y(), v_line.to.y()) - tolerance ||
      v > std::max(v_line.from.y(), v_line.to.y()) + tolerance)
    return;
  const double length_u = length_at(u_line, u - u_line.from.x());
  const double length_v = length_at(v_line, v - v_line.from.y());
  // Lines leaving one singularity meet there, and lines that ran into a singularity meet the
  // lines leaving it: neither is an intersection of open separatrices.
  if (std::min(length_u, length_v) <= kLengthTolerance) return;
  const auto at_singular_end = [&](Index line, double length) {
    const Separatrix& s = graph_.separatrices[line];
    return s.end == LineEnd::singularity && length >= s.length - kLengthTolerance;
  };
  if (at_singular_end(u_line.line, length_u) || at_singular_end(v_line.line, length_v)) return;
  if (u_line.line == v_line.line && std::abs(length_u - length_v) <= kLengthTolerance) return;

  const bool u_first = u_line.line != v_line.line ? u_line.line < v_line.line : length_u < length_v;
  const SeparatrixPiece& first = u_first ? u_line : v_line;
  const SeparatrixPiece& second = u_first ? v_line : u_line;
  Crossing m;
  m.line_a = first.line;
  m.line_b = second.line;
  m.length_a = u_first ? length_u : length_v;
  m.length_b = u_first ? length_v : length_u;
  m.face = a.face;
  m.point = {u, v};
  m.direction_a = first.direction;
  m.direction_b = second.direction;
  if (!is_new(m)) return;
  check_limit(crossings_found_ + 1, options_.max_crossings, "separatrix tracing (crossings found)",
              "--max-trace-crossings");
  events_.push(
      {tick_of(m.time()), 1, m.line_a, m.line_b, tick_of(m.length_a), crossings_found_++, m});
}

bool SeparatrixGrowth::is_new(const Crossing& m) {
  std::vector<std::pair<double, double>>& seen = found_[{m.line_a, m.line_b}];
  for (const auto& [la, lb] : seen)
    if (std::abs(la - m.length_a) <= kSameCrossing && std::abs(lb - m.length_b) <= kSameCrossing)
      return false;
  seen.push_back({m.length_a, m.length_b});
  return true;
}

void SeparatrixGrowth::handle_events_until(double time) {
  // Only ticks every line has grown past: an event found later lands in a later tick or in this
  // one, still unhandled, whatever the order the lines grew in.
  const std::int64_t now =
      time == kInfinity ? std::numeric_limits<std::int64_t>::max() : tick_of(time);
  while (!events_.empty() && events_.top().tick < now) {
    const Event event = events_.top();
    events_.pop();
    handle(event);
  }
}

void SeparatrixGrowth::handle(const Event& event) {
  if (event.kind == 1) {
    const Crossing& m = event.crossing;
    if (m.length_a > graph_.separatrices[m.line_a].stop ||
        m.length_b > graph_.separatrices[m.line_b].stop)
      return;
    for (Index line : collector_.on_crossing(graph_, m)) stop(line, m.time());
    return;
  }
  const PendingEnd& end = pending_ends_[event.index];
  const Separatrix& s = graph_.separatrices[end.line];
  if (s.end == LineEnd::singularity)
    collector_.on_singularity(graph_, end.line, end.port_hit, s.length, end.offset);
  else if (s.end == LineEnd::boundary)
    collector_.on_boundary(graph_, end.line, s.length, end.face, end.point);
}

void SeparatrixGrowth::stop(Index line, double time) {
  Separatrix& s = graph_.separatrices[line];
  if (s.end != LineEnd::growing && s.length <= time) return;  // it ended before
  s.stop = time;
  s.length = std::min(s.length, time);
  s.end = LineEnd::spiral;
  s.end_vertex = kNoIndex;
}

}  // namespace tessera::layout
