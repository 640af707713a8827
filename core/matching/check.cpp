#include "matching/check.h"

namespace tessera::matching {

namespace {

constexpr std::size_t kReportedViolations = 10;

class Violations {
 public:
  explicit Violations(SolutionCheck& check) : check_(check) {}
  void add(const std::string& message) {
    if (check_.violations.size() < kReportedViolations) check_.violations.push_back(message);
    ++check_.violation_count;
  }

 private:
  SolutionCheck& check_;
};

// Marks the chosen edges; reports unknown and repeated indices.
std::vector<std::uint8_t> chosen_mask(const MatchingProblem& problem,
                                      const std::vector<std::uint32_t>& chosen,
                                      Violations& violations) {
  std::vector<std::uint8_t> mask(problem.edges.size(), 0);
  for (std::uint32_t e : chosen) {
    if (e >= mask.size()) {
      violations.add("edge " + std::to_string(e) + " does not exist");
    } else if (mask[e]) {
      violations.add("edge " + std::to_string(e) + " is chosen twice");
    } else {
      mask[e] = 1;
    }
  }
  return mask;
}

void check_degrees(const MatchingProblem& problem, const std::vector<std::uint8_t>& mask,
                   Violations& violations) {
  std::vector<std::uint32_t> degree(problem.node_count(), 0);
  for (std::size_t e = 0; e < mask.size(); ++e) {
    if (!mask[e]) continue;
    ++degree[problem.edges[e].u];
    ++degree[problem.edges[e].v];
  }
  for (std::size_t v = 0; v < degree.size(); ++v) {
    const bool is_virtual = problem.is_virtual[v] != 0;
    if (degree[v] == 1 || (is_virtual && degree[v] == 0)) continue;
    violations.add(std::string(is_virtual ? "virtual port " : "port ") + std::to_string(v) +
                   " is matched " + std::to_string(degree[v]) + " times");
  }
}

void check_conflicts(const MatchingProblem& problem, const std::vector<std::uint8_t>& mask,
                     Violations& violations) {
  for (const ConflictPair& c : problem.conflicts) {
    if (mask[c.first] && mask[c.second])
      violations.add("edges " + std::to_string(c.first) + " and " + std::to_string(c.second) +
                     " are both chosen but conflict");
  }
}

}  // namespace

SolutionCheck check_solution(const MatchingProblem& problem,
                             const std::vector<std::uint32_t>& chosen) {
  SolutionCheck check;
  Violations violations(check);
  const std::vector<std::uint8_t> mask = chosen_mask(problem, chosen, violations);
  check_degrees(problem, mask, violations);
  check_conflicts(problem, mask, violations);
  for (std::size_t e = 0; e < mask.size(); ++e)
    if (mask[e]) check.objective += problem.edges[e].weight;
  check.feasible = check.violation_count == 0;
  return check;
}

}  // namespace tessera::matching
