// Todd-Coxeter coset enumeration over the trivial subgroup (thesis Sec. 9.3: "the coset table of
// the group"). Cosets are completed in order. Short relators (the six of Def. 9.2) are enforced the
// Felsch way: after every new entry, each of their cyclic conjugates through it is scanned, so
// deductions and coincidences are found at once and few cosets are defined beyond |G|. Long extra
// relators are traced once from each coset, HLT style, defining cosets to close them: Felsch would
// rescan all their conjugates at every entry, which costs the square of their length (the census
// has relators of several hundred letters). Dead rows are compacted away once a quarter of the
// table is dead.
//
// In:  relators over R, R^-1, S, S^-1, T (T is an involution by construction: its column is its own
//      inverse), Limits::max_coset_table (rows), Limits::max_coset_seconds.
// Out: the complete coset table of the trivial subgroup, i.e. the regular representation of the
//      group: row g holds g*x for the five letters x. Rows are standardized: row 0 is the identity
//      and the rows are numbered in breadth-first order over the letters, so results are
//      reproducible.
// Throws LimitError when the table would exceed max_coset_table rows or the enumeration runs longer
// than max_coset_seconds (an infinite group, e.g. a hyperbolic triangle group without extra
// relators, ends this way); CancelledError through `progress`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/limits.h"
#include "base/progress.h"
#include "regmap/presentation.h"

namespace tessera::regmap {

struct CosetTable {
  std::vector<std::int32_t> entries;  // row-major, kLetterCount entries per row

  std::size_t rows() const { return entries.size() / kLetterCount; }
  std::int32_t at(std::int32_t row, Letter x) const {
    return entries[static_cast<std::size_t>(row) * kLetterCount + static_cast<std::size_t>(x)];
  }
};

struct EnumerationStats {
  std::size_t cosets_defined = 0;  // definitions made (the total cost of the enumeration)
  std::size_t max_rows = 0;        // the largest the table grew, dead rows included
  double seconds = 0.0;
};

CosetTable enumerate_cosets(const std::vector<Word>& relators, const Limits& limits,
                            const Progress& progress = Progress(),
                            EnumerationStats* stats = nullptr);

}  // namespace tessera::regmap
