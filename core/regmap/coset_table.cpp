#include "regmap/coset_table.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <string>

#include "base/error.h"

namespace tessera::regmap {

namespace {

using Coset = std::int32_t;
constexpr Coset kUndefined = -1;
constexpr std::size_t kInitialRows = 1024;
constexpr std::size_t kClockInterval = 4096;            // definitions between time/progress checks
constexpr std::size_t kLettersBetweenChecks = 1 << 22;  // HLT letters traced between checks

std::size_t column(Letter x) {
  return static_cast<std::size_t>(x);
}

// The cyclic conjugates of the relators, grouped by first letter: a deduction at entry (c, x) needs
// exactly the conjugates that start with x (scanned at c) and with x^-1 (scanned at c^x). A relator
// that is a proper power u^k has only |u| distinct conjugates; the others are skipped.
class Conjugates {
 public:
  struct Span {
    std::uint32_t offset;
    std::uint32_t length;
  };

  // Relators whose deduction cost (distinct conjugates times length) exceeds this are left out of
  // deduction processing and returned by long_relators(). 64 keeps the six relators of Def. 9.2
  // (up to R^64) in it and sends the census's extra relators to HLT; measured on the whole
  // catalog, it is the fastest of the thresholds 0 (pure HLT), 16, 32, 64, 100, 400, 2000, 10000.
  static constexpr std::size_t kMaxDeductionCost = 64;

  explicit Conjugates(const std::vector<Word>& relators) {
    for (const Word& w : relators) {
      if (w.empty()) continue;
      if (period(w) * w.size() > kMaxDeductionCost) {
        long_.push_back(w);
      } else {
        add_relator(w);
      }
    }
  }

  const std::vector<Word>& long_relators() const { return long_; }

  const std::vector<Span>& starting_with(Letter x) const { return by_letter_[column(x)]; }
  const Letter* letters(const Span& s) const { return letters_.data() + s.offset; }

 private:
  static std::size_t period(const Word& w) {
    const std::size_t n = w.size();
    for (std::size_t d = 1; d < n; ++d) {
      if (n % d == 0 && std::equal(w.begin() + static_cast<std::ptrdiff_t>(d), w.end(), w.begin()))
        return d;
    }
    return n;
  }

  void add_relator(const Word& w) {
    // The word twice in a row: every rotation is then a contiguous span.
    const auto offset = static_cast<std::uint32_t>(letters_.size());
    letters_.insert(letters_.end(), w.begin(), w.end());
    letters_.insert(letters_.end(), w.begin(), w.end());
    const std::size_t distinct = period(w);
    for (std::size_t k = 0; k < distinct; ++k) {
      by_letter_[column(w[k])].push_back(
          {offset + static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(w.size())});
    }
  }

  std::vector<Letter> letters_;
  std::array<std::vector<Span>, kLetterCount> by_letter_;
  std::vector<Word> long_;
};

class Enumerator {
 public:
  Enumerator(const std::vector<Word>& relators, const Limits& limits, const Progress& progress)
      : conjugates_(relators),
        limits_(limits),
        progress_(progress),
        start_(std::chrono::steady_clock::now()) {
    check_limit(1, max_rows(), "the coset table", "--max-cosets");
    reserve_rows(std::min(kInitialRows, max_rows()));
    new_row();
  }

  CosetTable run() {
    for (scanning_ = 0; static_cast<std::size_t>(scanning_) < rows_; ++scanning_) {
      for (const Word& w : conjugates_.long_relators()) {
        if (!live(scanning_)) break;
        compact_if_worthwhile();
        count_work(w.size());
        trace<true>(scanning_, w.data(), w.size());
        process_deductions();
      }
      for (std::size_t x = 0; x < kLetterCount; ++x) {
        if (!live(scanning_)) break;
        if (entry(scanning_, x) != kUndefined) continue;
        compact_if_worthwhile();
        define(scanning_, x);
        process_deductions();
      }
    }
    stats_.seconds = elapsed();
    return standardized();
  }

  const EnumerationStats& stats() const { return stats_; }

 private:
  Coset& entry(Coset c, std::size_t x) {
    return table_[static_cast<std::size_t>(c) * kLetterCount + x];
  }
  bool live(Coset c) const { return forward_[static_cast<std::size_t>(c)] == c; }
  static std::size_t inv(std::size_t x) { return column(inverse(static_cast<Letter>(x))); }

  // Coset numbers are 32-bit: a table beyond that would not fit in memory anyway.
  std::size_t max_rows() const {
    return std::min<std::size_t>(limits_.max_coset_table, std::numeric_limits<Coset>::max());
  }

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  void reserve_rows(std::size_t rows) {
    table_.resize(rows * kLetterCount, kUndefined);
    forward_.resize(rows);
    capacity_ = rows;
  }

  // A fresh row, growing the table if it is full. Dead rows count against the limit until the next
  // compaction: they hold memory too.
  Coset new_row() {
    if (rows_ == capacity_) {
      check_limit(rows_ + 1, max_rows(),
                  "the coset table (the group may be infinite or larger than expected)",
                  "--max-cosets");
      reserve_rows(std::min(capacity_ * 2, max_rows()));
    }
    const auto c = static_cast<Coset>(rows_++);
    forward_[static_cast<std::size_t>(c)] = c;
    std::fill_n(table_.begin() + static_cast<std::ptrdiff_t>(c) * kLetterCount, kLetterCount,
                kUndefined);
    stats_.max_rows = std::max(stats_.max_rows, rows_);
    if (++stats_.cosets_defined % kClockInterval == 0) check_clock();
    return c;
  }

  void define(Coset c, std::size_t x) {
    const Coset d = new_row();
    entry(c, x) = d;
    entry(d, inv(x)) = c;
    deductions_.push_back({c, x});
  }

  void check_clock() {
    if (elapsed() > limits_.max_coset_seconds)
      throw LimitError("coset enumeration ran longer than " +
                       format_seconds(limits_.max_coset_seconds) + " with " +
                       std::to_string(rows_ - dead_) +
                       " cosets and still growing (the group may be infinite: check the "
                       "relators); raise the limit with --max-seconds");
    progress_.step("coset enumeration",
                   static_cast<double>(scanning_) / static_cast<double>(rows_));
  }

  // Long relators can keep the scans busy without defining rows: the clock is also checked after
  // every few million letters traced.
  void count_work(std::size_t letters) {
    letters_traced_ += letters;
    if (letters_traced_ < kLettersBetweenChecks) return;
    letters_traced_ = 0;
    check_clock();
  }

  // Renumbers the live cosets 0, 1, ... in their order once a quarter of the rows are dead (so the
  // cost is amortized). Called only between definitions, when no deduction or coincidence is
  // pending, so only the table and `scanning_` hold coset numbers.
  void compact_if_worthwhile() {
    if (dead_ * 4 < rows_ || dead_ == 0) return;
    std::vector<Coset> renumber(rows_, kUndefined);
    Coset next = 0;
    for (std::size_t c = 0; c < rows_; ++c) {
      if (live(static_cast<Coset>(c))) renumber[c] = next++;
    }
    for (std::size_t c = 0; c < rows_; ++c) {
      const Coset to = renumber[c];
      if (to == kUndefined) continue;
      for (std::size_t x = 0; x < kLetterCount; ++x) {
        const Coset value = entry(static_cast<Coset>(c), x);
        entry(to, x) = value == kUndefined ? kUndefined : renumber[static_cast<std::size_t>(value)];
      }
      forward_[static_cast<std::size_t>(to)] = to;
    }
    rows_ = static_cast<std::size_t>(next);
    dead_ = 0;
    scanning_ = renumber[static_cast<std::size_t>(scanning_)];
  }

  void process_deductions() {
    while (!deductions_.empty()) {
      const auto [c, x] = deductions_.back();
      deductions_.pop_back();
      if (!live(c)) continue;
      scan_all(c, conjugates_.starting_with(static_cast<Letter>(x)));
      if (!live(c)) continue;
      const Coset d = entry(c, x);
      if (d != kUndefined) scan_all(d, conjugates_.starting_with(inverse(static_cast<Letter>(x))));
    }
  }

  void scan_all(Coset c, const std::vector<Conjugates::Span>& spans) {
    for (const Conjugates::Span& span : spans) {
      trace<false>(c, conjugates_.letters(span), span.length);
      if (!live(c)) return;
    }
  }

  // Traces the relator w (n letters) from c forwards and backwards. A complete trace that does not
  // close is a coincidence; a gap of one letter is a deduction. A longer gap is left alone (Felsch)
  // or, when `kFill`, closed with new cosets one at a time (HLT). A template parameter, so that the
  // Felsch scan, the hot loop of the enumeration, compiles without the filling branch.
  template <bool kFill>
  void trace(Coset c, const Letter* w, std::size_t n) {
    Coset f = c, b = c;
    std::size_t i = 0, j = n;  // w[0..i) traced forwards to f, w[j..n) backwards to b
    for (;;) {
      while (i < j) {
        const Coset next = entry(f, column(w[i]));
        if (next == kUndefined) break;
        f = next;
        ++i;
      }
      if (i == j) {
        if (f != b) coincidence(f, b);
        return;
      }
      while (j > i) {
        const Coset prev = entry(b, inv(column(w[j - 1])));
        if (prev == kUndefined) break;
        b = prev;
        --j;
      }
      if (j == i) {
        coincidence(f, b);
        return;
      }
      const std::size_t x = column(w[i]);
      if (j == i + 1) {
        entry(f, x) = b;
        entry(b, inv(x)) = f;
        deductions_.push_back({f, x});
        return;
      }
      if (!kFill) return;
      define(f, x);
    }
  }

  Coset representative(Coset c) {
    Coset root = c;
    while (forward_[static_cast<std::size_t>(root)] != root)
      root = forward_[static_cast<std::size_t>(root)];
    while (forward_[static_cast<std::size_t>(c)] != root) {
      const Coset next = forward_[static_cast<std::size_t>(c)];
      forward_[static_cast<std::size_t>(c)] = root;
      c = next;
    }
    return root;
  }

  void merge(Coset a, Coset b) {
    a = representative(a);
    b = representative(b);
    if (a == b) return;
    const Coset keep = std::min(a, b), lose = std::max(a, b);
    forward_[static_cast<std::size_t>(lose)] = keep;
    ++dead_;
    coincidences_.push_back(lose);
  }

  // Holt's coincidence procedure: the larger coset dies, its row is folded into the survivor,
  // and each entry that lands in a free place is a new deduction.
  void coincidence(Coset a, Coset b) {
    coincidences_.clear();
    merge(a, b);
    for (std::size_t k = 0; k < coincidences_.size(); ++k) {
      const Coset gone = coincidences_[k];
      for (std::size_t x = 0; x < kLetterCount; ++x) {
        const Coset target = entry(gone, x);
        if (target == kUndefined) continue;
        entry(target, inv(x)) = kUndefined;
        const Coset mu = representative(gone), nu = representative(target);
        if (entry(mu, x) != kUndefined) {
          merge(nu, entry(mu, x));
        } else if (entry(nu, inv(x)) != kUndefined) {
          merge(mu, entry(nu, inv(x)));
        } else {
          entry(mu, x) = nu;
          entry(nu, inv(x)) = mu;
          deductions_.push_back({mu, x});
        }
      }
    }
  }

  // The live rows renumbered breadth-first from coset 0 over the letters in order.
  CosetTable standardized() {
    std::vector<Coset> renumber(rows_, kUndefined), order;
    order.reserve(rows_ - dead_);
    renumber[0] = 0;
    order.push_back(0);
    for (std::size_t k = 0; k < order.size(); ++k) {
      for (std::size_t x = 0; x < kLetterCount; ++x) {
        const Coset next = entry(order[k], x);
        if (next == kUndefined || !live(next))
          throw Error("coset enumeration left an incomplete table (an internal error)");
        if (renumber[static_cast<std::size_t>(next)] != kUndefined) continue;
        renumber[static_cast<std::size_t>(next)] = static_cast<Coset>(order.size());
        order.push_back(next);
      }
    }
    CosetTable result;
    result.entries.resize(order.size() * kLetterCount);
    for (std::size_t k = 0; k < order.size(); ++k) {
      for (std::size_t x = 0; x < kLetterCount; ++x)
        result.entries[k * kLetterCount + x] =
            renumber[static_cast<std::size_t>(entry(order[k], x))];
    }
    return result;
  }

  struct Deduction {
    Coset coset;
    std::size_t letter;
  };

  Conjugates conjugates_;
  const Limits& limits_;
  const Progress& progress_;
  std::chrono::steady_clock::time_point start_;
  std::vector<Coset> table_;
  std::vector<Coset> forward_;  // forward_[c] == c for live cosets, towards the survivor otherwise
  std::size_t rows_ = 0, capacity_ = 0, dead_ = 0;
  Coset scanning_ = 0;  // the coset whose row is being completed
  std::size_t letters_traced_ = 0;
  std::vector<Deduction> deductions_;
  std::vector<Coset> coincidences_;
  EnumerationStats stats_;
};

// The enumeration closes a table in which every relator holds at every coset; checking that once
// at the end costs one pass and turns the enumeration into a certificate.
void check_relators_hold(const CosetTable& table, const std::vector<Word>& relators) {
  for (std::size_t c = 0; c < table.rows(); ++c) {
    for (const Word& w : relators) {
      auto g = static_cast<std::int32_t>(c);
      for (Letter x : w) g = table.at(g, x);
      if (g != static_cast<std::int32_t>(c))
        throw Error("coset enumeration closed a table in which " + to_string(w) +
                    " does not hold (an internal error)");
    }
  }
}

}  // namespace

CosetTable enumerate_cosets(const std::vector<Word>& relators, const Limits& limits,
                            const Progress& progress, EnumerationStats* stats) {
  Enumerator enumerator(relators, limits, progress);
  CosetTable table = enumerator.run();
  check_relators_hold(table, relators);
  if (stats) *stats = enumerator.stats();
  return table;
}

}  // namespace tessera::regmap
