// The CPLEX LP form of a P1 instance, the very program (5.1)-(5.4) of the thesis, so that
// `glpsol --lp` and `cbc` solve the same instance as Tessera's solvers:
//
//   Minimize
//    obj: 2.5 x0 + 1 x1 + ...            x<e>: edge e, its weight as the coefficient  (5.1)
//   Subject To
//    p0: x0 + x3 = 1                     p<i>: port i, exactly one edge               (5.2)
//    v5: x1 + x2 <= 1                    v<i>: virtual port i, at most one edge
//    c0: x0 + x4 <= 1                    c<k>: conflict pair k                         (5.3)
//   Binaries
//    x0 x1 ...                                                                         (5.4)
//   End
//
// A node without edges keeps its row as "p3: 0 x0 = 1" so that the node count survives.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/limits.h"
#include "matching/problem.h"

namespace tessera::matching {

// Throws InputError for a problem without edges (an LP needs a column).
std::vector<std::uint8_t> write_instance_lp(const MatchingProblem& problem);

// Reads the LP files write_instance_lp() writes (comments, line breaks, spacing and the order of
// rows and sections may differ). Edge endpoints come back in increasing order. Throws ParseError
// with the line for syntax errors and for rows or columns that do not name a P1 node, conflict or
// edge; LimitError and InputError as read_instance_json(). Never reads past `bytes`.
MatchingProblem read_instance_lp(std::span<const std::uint8_t> bytes, const std::string& file_name,
                                 const Limits& limits);

}  // namespace tessera::matching
