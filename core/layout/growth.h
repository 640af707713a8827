// Motorcycle growing (thesis Sec. 4.1, 6.7, 6.8; LAYOUT_NOTES "Growing and events"): every open
// separatrix grows from its port at unit parametric speed, the one with the smallest length one
// face at a time. Each face keeps the pieces of separatrices crossing it (Sec. 6.9 "Data
// structure"); a new piece is tested against them, which finds every intersection once. An
// intersection of a and b at m happens at time max(L_a(m), L_b(m)); events (intersections,
// separatrix ends) are handled in time order once every growing separatrix has passed their time,
// so that when a candidate edge is examined every singularity that could spoil its triangle has
// been seen (Prop. 4.1). A separatrix stops at L_max, when the spiral test stops it, at a
// singularity or at the boundary.
//
// In:  the charts of M_f and its ports. Out: the PortGraph without conflicts (conflicts.h adds I).
// grow() may be called again with a larger L_max (Sec. 5.1, when G has no perfect matching): the
// separatrices stopped by L_max continue, everything found so far stays.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

#include "base/limits.h"
#include "base/progress.h"
#include "layout/candidates.h"
#include "layout/port_graph.h"
#include "layout/trace.h"

namespace tessera::layout {

struct GrowthOptions {
  double rho = 10;                                           // spiral test threshold (Sec. 6.8)
  std::size_t max_steps = Limits{}.max_trace_steps;          // faces entered by all separatrices
  std::size_t max_crossings = Limits{}.max_trace_crossings;  // crossings found by all of them
  double max_seconds = Limits{}.max_trace_seconds;  // time guard: wall time of all grow() calls
};

class SeparatrixGrowth {
 public:
  using Clock = std::chrono::steady_clock;

  SeparatrixGrowth(const Charts& charts, Ports ports, const GrowthOptions& options);

  // Grows every separatrix not yet stopped to `length_limit`. Throws LimitError when the steps of
  // all separatrices exceed options.max_steps, their crossings options.max_crossings (the work,
  // the same on every machine), or the time guard options.max_seconds; CancelledError when
  // cancelled.
  void grow(double length_limit, const Progress& progress);

  const PortGraph& graph() const { return graph_; }
  std::size_t steps() const { return steps_; }
  std::size_t crossings() const { return crossings_found_; }
  PortGraph take_graph() { return std::move(graph_); }

 private:
  // A crossing waits in its event, so that only the pending ones are held (a dragon grows more
  // than 8 million). Events are handled by tick (their time in steps of kEventTick), then by kind,
  // lines and where on the first line, so that the order of events at one time, which the spiral
  // test's stops depend on, follows the lines, not rounding or the order the lines grew in: on a
  // symmetric surface, mirror lines meet their crossings at times that differ by rounding only, and
  // a pair can cross twice at once (the double torus sample: which of two mirror lines the test
  // stopped went with 1e-9 radians of the field, and native and wasm built different graphs).
  struct Event {
    std::int64_t tick = 0;
    int kind = 0;                 // 0: a separatrix end, 1: a crossing
    Index first = 0, second = 0;  // kind 0: the line; kind 1: the crossing's lines
    std::int64_t tick_a = 0;      // kind 1: length_a in ticks (two crossings of a pair at once)
    Index index = 0;  // kind 0: into pending_ends_; kind 1: the crossing's number, in order found
    Crossing crossing;
    bool operator>(const Event& o) const {
      return std::tie(tick, kind, first, second, tick_a, index) >
             std::tie(o.tick, o.kind, o.first, o.second, o.tick_a, o.index);
    }
  };
  struct PendingEnd {
    Index line = 0;
    Index port_hit = kNoIndex;  // LineEnd::singularity: the port it arrives along,
    double offset = 0;          //   and the singularity's signed distance (left > 0)
    Index face = kNoIndex;      // LineEnd::boundary: the exit point
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
  };
  // A singular corner of the cursor's face that the step passes (almost) through.
  struct NearSingularity {
    Index corner = kNoIndex;
    double along = 0;   // distance travelled to the point nearest to it
    double offset = 0;  // its signed distance from the line, left > 0
  };

  void advance(Index line, double length_limit);
  NearSingularity near_singularity(const LineCursor& cursor, const LineStep& step) const;
  Index port_arriving(Index face, Index vertex, const Eigen::Vector2d& direction) const;
  void queue_end(const PendingEnd& end, double time);
  void add_piece(const SeparatrixPiece& piece);
  void discover(const SeparatrixPiece& a, const SeparatrixPiece& b);
  bool is_new(const Crossing& m);
  void handle_events_until(double time);
  void handle(const Event& event);
  void stop(Index line, double time);
  void check_clock(Clock::time_point start) const;

  Charts charts_;
  GrowthOptions options_;
  PortGraph graph_;
  EdgeCollector collector_;
  std::vector<LineCursor> cursors_;
  std::vector<std::vector<Index>> face_pieces_;
  Index crossings_found_ = 0;
  std::vector<PendingEnd> pending_ends_;
  std::map<std::pair<Index, Index>, std::vector<std::pair<double, double>>> found_;
  std::priority_queue<Event, std::vector<Event>, std::greater<>> events_;
  std::size_t steps_ = 0;
  double seconds_ = 0;  // spent in grow()
};

}  // namespace tessera::layout
