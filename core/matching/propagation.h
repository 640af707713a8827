// Unit propagation on P1's 0/1 variables, shared by probing (probing.h) and the diving heuristic
// (incumbent.h). Setting x_e = 1 drops every edge exclusive with e (sharing a node, or in a
// conflict pair with it) to 0; a port left with one usable edge forces that edge to 1, and so on.
// A port left with no usable edge, or two forced edges that exclude each other, is a
// contradiction.
#pragma once

#include <cstdint>
#include <vector>

#include "matching/adjacency.h"
#include "matching/problem.h"

namespace tessera::matching {

enum class Fixed : std::int8_t { free = -1, zero = 0, one = 1 };

class Propagation {
 public:
  // `incident` is incident_edges(problem), `exclusive` is exclusive_edges(problem) (or a
  // supergraph of it); `start` fixes some edges already (consistently), or is empty.
  Propagation(const MatchingProblem& problem, const Adjacency& incident, const Adjacency& exclusive,
              const std::vector<Fixed>& start = {});

  const std::vector<Fixed>& values() const { return values_; }
  bool infeasible() const { return infeasible_; }

  // Tries x_e = 1 with all its consequences, without committing them; false on a contradiction.
  bool try_one(std::uint32_t e);
  // The edges the last successful try_one() drove to 0: first the free edges exclusive with e
  // itself (direct_drops() of them), then those its forced edges excluded.
  const std::vector<std::uint32_t>& dropped() const { return dropped_; }
  std::size_t direct_drops() const { return direct_drops_; }
  // The edges the last successful try_one() drove to 1: e, then those it forced.
  const std::vector<std::uint32_t>& forced() const { return forced_; }
  // Makes the consequences of the last successful try_one() permanent.
  void commit();

  // x_e = 0 for good; a port it leaves with one usable edge forces that edge (committed).
  void fix_zero(std::uint32_t e);
  // Forces the single usable edge of every port that has one; true if anything changed.
  bool force_single_edges();

  // The committed state, to go back to (a search that backtracks).
  struct State {
    std::vector<Fixed> values;
    std::vector<std::uint8_t> matched;
    bool infeasible = false;
  };
  State save() const { return {values_, matched_, infeasible_}; }
  void restore(const State& state);

 private:
  bool force(std::uint32_t g);
  // The usable edge count of port p in the current try (capped at 2) and the last usable one.
  std::uint32_t usable_edges(std::uint32_t p, std::uint32_t& last) const;
  void check_port(std::uint32_t p);

  const MatchingProblem& problem_;
  const Adjacency& incident_;
  const Adjacency& exclusive_;
  std::vector<Fixed> values_;
  std::vector<std::uint8_t> matched_;  // per node: an edge at it is fixed to 1
  bool infeasible_ = false;
  // Per node and edge: the try (stamp) that covered, zeroed or forced it.
  std::vector<std::uint32_t> covered_, zero_, one_;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> dropped_, forced_, queue_;
  std::size_t direct_drops_ = 0;
};

}  // namespace tessera::matching
