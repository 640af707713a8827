#include "matching/instance_lp.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

#include "base/error.h"
#include "base/text_scan.h"
#include "export/byte_writer.h"

namespace tessera::matching {

namespace {

// ---- writing ----

constexpr std::size_t kTermsPerLine = 8;

void write_term(ByteWriter& out, double coefficient, std::size_t column, std::size_t position) {
  if (position > 0 && position % kTermsPerLine == 0) out.text("\n  ");
  if (position > 0 || coefficient < 0) out.text(coefficient < 0 ? " - " : " + ");
  out.number(coefficient < 0 ? -coefficient : coefficient);
  out.text(" x");
  out.integer(static_cast<long long>(column));
}

void write_objective(const MatchingProblem& problem, ByteWriter& out) {
  out.text("Minimize\n obj:");
  for (std::size_t e = 0; e < problem.edges.size(); ++e) {
    if (e == 0) out.text(" ");
    write_term(out, problem.edges[e].weight, e, e);
  }
  out.text("\n");
}

void write_node_rows(const MatchingProblem& problem, ByteWriter& out) {
  std::vector<std::vector<std::uint32_t>> incident(problem.node_count());
  for (std::uint32_t e = 0; e < problem.edges.size(); ++e) {
    incident[problem.edges[e].u].push_back(e);
    incident[problem.edges[e].v].push_back(e);
  }
  for (std::size_t v = 0; v < problem.node_count(); ++v) {
    const bool is_virtual = problem.is_virtual[v] != 0;
    out.text(is_virtual ? " v" : " p");
    out.integer(static_cast<long long>(v));
    out.text(": ");
    if (incident[v].empty()) out.text("0 x0");
    for (std::size_t k = 0; k < incident[v].size(); ++k) {
      if (k > 0) out.text(k % kTermsPerLine == 0 ? "\n   + " : " + ");
      out.text("x");
      out.integer(incident[v][k]);
    }
    out.text(is_virtual ? " <= 1\n" : " = 1\n");
  }
}

void write_conflict_rows(const MatchingProblem& problem, ByteWriter& out) {
  for (std::size_t k = 0; k < problem.conflicts.size(); ++k) {
    out.text(" c");
    out.integer(static_cast<long long>(k));
    out.text(": x");
    out.integer(problem.conflicts[k].first);
    out.text(" + x");
    out.integer(problem.conflicts[k].second);
    out.text(" <= 1\n");
  }
}

void write_binaries(const MatchingProblem& problem, ByteWriter& out) {
  out.text("Binaries\n");
  for (std::size_t e = 0; e < problem.edges.size(); ++e) {
    out.text(e % kTermsPerLine == 0 ? (e == 0 ? " x" : "\n x") : " x");
    out.integer(static_cast<long long>(e));
  }
  out.text("\nEnd\n");
}

// ---- reading: tokens ----

enum class TokenKind { name, number, sign, relation, colon, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string_view text;
  std::size_t line = 0;
};

bool is_operator_char(char c) {
  return c == '+' || c == '-' || c == '<' || c == '>' || c == '=' || c == ':';
}

bool is_text_char(char c) {
  return static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
}

bool is_space_char(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}

// Splits the LP text into tokens; '\' starts a comment up to the end of the line.
class Scanner {
 public:
  Scanner(std::span<const std::uint8_t> bytes, const std::string& file_name)
      : text_(reinterpret_cast<const char*>(bytes.data()), bytes.size()), file_name_(file_name) {
    advance();
  }

  const Token& peek() const { return current_; }
  Token take() {
    Token t = current_;
    advance();
    return t;
  }

  [[noreturn]] void fail(std::size_t line, const std::string& message) const {
    throw ParseError(file_name_ + ":" + std::to_string(line) + ": " + message);
  }

 private:
  void skip_space_and_comments() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') ++line_;
      if (c == '\\') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (is_space_char(c)) {
        ++at_;
      } else {
        return;
      }
    }
  }

  std::size_t scan_number(std::size_t i) const {
    while (i < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[i])) || text_[i] == '.'))
      ++i;
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) ++j;
      if (j < text_.size() && std::isdigit(static_cast<unsigned char>(text_[j]))) {
        while (j < text_.size() && std::isdigit(static_cast<unsigned char>(text_[j]))) ++j;
        i = j;
      }
    }
    return i;
  }

  std::size_t scan_name(std::size_t i) const {
    while (i < text_.size() && !is_space_char(text_[i]) && !is_operator_char(text_[i]) &&
           text_[i] != '\\' && is_text_char(text_[i]))
      ++i;
    return i;
  }

  std::size_t scan_operator(std::size_t i, TokenKind& kind) const {
    const char c = text_[i];
    if (c == ':') {
      kind = TokenKind::colon;
      return i + 1;
    }
    if (c == '+' || c == '-') {
      kind = TokenKind::sign;
      return i + 1;
    }
    kind = TokenKind::relation;
    return i + 1 < text_.size() &&
                   (text_[i + 1] == '=' || text_[i + 1] == '<' || text_[i + 1] == '>')
               ? i + 2
               : i + 1;
  }

  void advance() {
    skip_space_and_comments();
    current_ = Token{TokenKind::end, {}, line_};
    if (at_ >= text_.size()) return;
    const char c = text_[at_];
    if (!is_text_char(c))
      fail(line_, "a byte that is no LP text (code " +
                      std::to_string(static_cast<unsigned char>(c)) + "); is this a binary file?");
    std::size_t end = at_;
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      current_.kind = TokenKind::number;
      end = scan_number(at_);
    } else if (is_operator_char(c)) {
      end = scan_operator(at_, current_.kind);
    } else {
      current_.kind = TokenKind::name;
      end = scan_name(at_);
    }
    current_.text = text_.substr(at_, end - at_);
    at_ = end;
  }

  std::string_view text_;
  const std::string& file_name_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
  Token current_;
};

// ---- reading: the LP program ----

enum class Section { objective, constraints, bounds, binaries, generals, end, none };

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

struct Term {
  double coefficient = 0.0;
  std::string_view variable;
  std::size_t line = 0;
};

struct Row {
  std::string_view name;
  std::vector<Term> terms;
  std::string relation;
  double rhs = 0.0;
  std::size_t line = 0;
};

// CPLEX reads '<' as '<=' and '=<' the same.
std::string normalized_relation(std::string_view relation) {
  if (relation == "<" || relation == "=<") return "<=";
  if (relation == ">" || relation == "=>") return ">=";
  return std::string(relation);
}

struct LpProgram {
  std::vector<Term> objective;
  std::vector<Row> rows;
  std::vector<Token> binaries;
};

class LpParser {
 public:
  explicit LpParser(Scanner& scanner) : in_(scanner) {}

  LpProgram parse() {
    LpProgram program;
    Section section = section_keyword();
    if (section != Section::objective)
      in_.fail(in_.peek().line, "expected 'Minimize' (P1 is a minimization)");
    while (section != Section::end) {
      section = parse_section(section, program);
      if (section == Section::none) in_.fail(in_.peek().line, "expected a section keyword");
    }
    return program;
  }

 private:
  // Consumes a section keyword if one is next.
  Section section_keyword() {
    const Token& t = in_.peek();
    if (t.kind == TokenKind::end) in_.fail(t.line, "the file ends without 'End'");
    if (t.kind != TokenKind::name) return Section::none;
    const std::string word = lower(t.text);
    Section section = Section::none;
    if (word == "minimize" || word == "minimum" || word == "min") section = Section::objective;
    if (word == "maximize" || word == "maximum" || word == "max")
      in_.fail(t.line, "'" + std::string(t.text) + "': P1 minimizes (5.1)");
    if (word == "st" || word == "s.t." || word == "subject" || word == "such")
      section = Section::constraints;
    if (word == "bounds" || word == "bound") section = Section::bounds;
    if (word == "binaries" || word == "binary" || word == "bin") section = Section::binaries;
    if (word == "generals" || word == "general" || word == "gen") section = Section::generals;
    if (word == "end") section = Section::end;
    if (section == Section::none) return section;
    in_.take();
    if (word == "subject" || word == "such") expect_word(word == "subject" ? "to" : "that");
    return section;
  }

  void expect_word(const char* word) {
    const Token t = in_.take();
    if (t.kind != TokenKind::name || lower(t.text) != word)
      in_.fail(t.line, std::string("expected '") + word + "'");
  }

  Section parse_section(Section section, LpProgram& program) {
    switch (section) {
      case Section::objective:
        skip_row_label();
        program.objective = expression();
        break;
      case Section::constraints:
        while (section_keyword_ahead() == false) program.rows.push_back(row());
        break;
      case Section::bounds:
        if (!section_keyword_ahead())
          in_.fail(in_.peek().line, "a P1 instance has no bounds beyond its binaries (5.4)");
        break;
      case Section::binaries:
        while (!section_keyword_ahead()) program.binaries.push_back(take_name("a variable"));
        break;
      case Section::generals:
        if (!section_keyword_ahead())
          in_.fail(in_.peek().line, "a P1 instance has binaries (5.4), no general integers");
        break;
      case Section::end:
      case Section::none:
        break;
    }
    return section_keyword();
  }

  bool section_keyword_ahead() {
    const Token& t = in_.peek();
    if (t.kind == TokenKind::end) in_.fail(t.line, "the file ends without 'End'");
    if (t.kind != TokenKind::name) return false;
    static const char* const kWords[] = {"minimize", "minimum", "min",      "maximize", "maximum",
                                         "max",      "st",      "s.t.",     "subject",  "such",
                                         "bounds",   "bound",   "binaries", "binary",   "bin",
                                         "generals", "general", "gen",      "end"};
    const std::string word = lower(t.text);
    return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
  }

  Token take_name(const char* what) {
    const Token t = in_.take();
    if (t.kind != TokenKind::name)
      in_.fail(t.line, std::string("expected ") + what +
                           (t.kind == TokenKind::end ? ", got the end of the file"
                                                     : ", got " + quoted(t.text)));
    return t;
  }

  void skip_row_label() {
    // "obj:" is optional; a label is a name followed by ':'.
    if (in_.peek().kind != TokenKind::name || section_keyword_ahead()) return;
    const Token name = in_.take();
    if (in_.peek().kind == TokenKind::colon) {
      in_.take();
      return;
    }
    pending_ = name;
  }

  double number(const Token& t) {
    const std::optional<double> x = parse_double(t.text);
    if (!x) in_.fail(t.line, "expected a number, got " + quoted(t.text));
    return *x;
  }

  // Terms "[+|-] [number] name" up to a relation or a section keyword.
  std::vector<Term> expression() {
    std::vector<Term> terms;
    for (;;) {
      if (!pending_ && (in_.peek().kind == TokenKind::relation || section_keyword_ahead()))
        return terms;
      double sign = 1.0;
      if (!pending_ && in_.peek().kind == TokenKind::sign) sign = in_.take().text == "-" ? -1 : 1;
      double coefficient = 1.0;
      if (!pending_ && in_.peek().kind == TokenKind::number) coefficient = number(in_.take());
      const Token variable = pending_ ? *pending_ : take_name("a variable name");
      pending_.reset();
      terms.push_back({sign * coefficient, variable.text, variable.line});
    }
  }

  Row row() {
    Row r;
    const Token name = take_name("a row name ('p0:', 'v3:' or 'c12:')");
    if (in_.take().kind != TokenKind::colon)
      in_.fail(name.line, "expected ':' after the row name " + quoted(name.text));
    r.name = name.text;
    r.line = name.line;
    r.terms = expression();
    const Token relation = in_.take();
    if (relation.kind != TokenKind::relation)
      in_.fail(relation.line, "the row " + quoted(r.name) + " has no '=', '<=' or '>='");
    r.relation = normalized_relation(relation.text);
    double sign = 1.0;
    if (in_.peek().kind == TokenKind::sign) sign = in_.take().text == "-" ? -1 : 1;
    const Token rhs = in_.take();
    if (rhs.kind != TokenKind::number)
      in_.fail(rhs.line, "expected the right-hand side of row " + quoted(r.name));
    r.rhs = sign * number(rhs);
    return r;
  }

  Scanner& in_;
  std::optional<Token> pending_;
};

// ---- reading: from the LP program to P1 ----

// "x12" with prefix 'x' -> 12, if below `bound`.
std::optional<std::size_t> indexed_name(std::string_view name, char prefix) {
  if (name.size() < 2 || name[0] != prefix) return std::nullopt;
  const std::string_view digits = name.substr(1);
  if (digits.size() > 1 && digits[0] == '0') return std::nullopt;
  for (char c : digits)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  const std::optional<std::int64_t> value = parse_integer(digits);
  if (!value) return std::nullopt;
  return static_cast<std::size_t>(*value);
}

class ProblemBuilder {
 public:
  ProblemBuilder(const Scanner& scanner, const std::string& file_name, const Limits& limits)
      : in_(scanner), file_name_(file_name), limits_(limits) {}

  MatchingProblem build(const LpProgram& program) {
    for (const Row& row : program.rows) add_row(row);
    MatchingProblem problem;
    problem.is_virtual = node_kinds();
    problem.edges = edges(program);
    problem.conflicts = conflicts();
    check_binaries(program, problem.edges.size());
    return problem;
  }

 private:
  std::size_t column(std::string_view name, std::size_t line) {
    const std::optional<std::size_t> e = indexed_name(name, 'x');
    if (!e) in_.fail(line, "the variable " + quoted(name) + " is not an edge x<e>");
    check_limit(*e + 1, limits_.max_matching_edges, file_name_ + " (edges)", "--max-edges");
    if (*e >= columns_.size()) columns_.resize(*e + 1);
    return *e;
  }

  void require(bool ok, const Row& row, const std::string& expected) {
    if (!ok) in_.fail(row.line, "row " + quoted(row.name) + " should be " + expected);
  }

  void add_row(const Row& row) {
    const char kind = row.name.empty() ? '\0' : row.name[0];
    const std::optional<std::size_t> index = indexed_name(row.name, kind);
    if (!index || (kind != 'p' && kind != 'v' && kind != 'c'))
      in_.fail(row.line, "the row " + quoted(row.name) +
                             " is neither a port p<i>, a virtual port v<i> nor a conflict c<k>");
    if (kind == 'c') {
      add_conflict_row(row, *index);
    } else {
      add_node_row(row, *index, kind == 'v');
    }
  }

  void add_node_row(const Row& row, std::size_t node, bool is_virtual) {
    require(row.relation == (is_virtual ? "<=" : "=") && row.rhs == 1.0, row,
            is_virtual ? "'... <= 1' (at most one edge)" : "'... = 1' (exactly one edge)");
    check_limit(node + 1, limits_.max_matching_nodes, file_name_ + " (nodes)", "--max-nodes");
    if (node >= node_rows_.size()) node_rows_.resize(node + 1, 0);
    if (node_rows_[node] != 0) in_.fail(row.line, "a second row for node " + std::to_string(node));
    node_rows_[node] = is_virtual ? 2 : 1;
    for (const Term& term : row.terms) {
      const std::size_t e = column(term.variable, row.line);
      if (term.coefficient == 0.0) continue;
      require(term.coefficient == 1.0, row, "a sum of edges with coefficient 1");
      if (columns_[e].size() == 2)
        in_.fail(row.line, "the edge " + quoted(term.variable) + " has a third endpoint here");
      columns_[e].push_back(static_cast<std::uint32_t>(node));
    }
  }

  void add_conflict_row(const Row& row, std::size_t k) {
    require(row.relation == "<=" && row.rhs == 1.0 && row.terms.size() == 2 &&
                row.terms[0].coefficient == 1.0 && row.terms[1].coefficient == 1.0,
            row, "'x<a> + x<b> <= 1' (5.3)");
    check_limit(k + 1, limits_.max_matching_conflicts, file_name_ + " (conflicts)",
                "--max-conflicts");
    const ConflictPair pair{static_cast<std::uint32_t>(column(row.terms[0].variable, row.line)),
                            static_cast<std::uint32_t>(column(row.terms[1].variable, row.line))};
    if (!conflicts_.emplace(k, pair).second)
      in_.fail(row.line, "a second row for conflict " + std::to_string(k));
  }

  std::vector<std::uint8_t> node_kinds() const {
    std::vector<std::uint8_t> is_virtual(node_rows_.size());
    for (std::size_t v = 0; v < node_rows_.size(); ++v) {
      if (node_rows_[v] == 0)
        throw ParseError(file_name_ + ": no row p" + std::to_string(v) + " or v" +
                         std::to_string(v) + " although higher nodes have one");
      is_virtual[v] = node_rows_[v] == 2;
    }
    return is_virtual;
  }

  std::vector<MatchingEdge> edges(const LpProgram& program) {
    std::vector<double> weights(columns_.size(), 0.0);
    for (const Term& term : program.objective) {
      const std::size_t e = column(term.variable, term.line);
      if (e >= weights.size()) weights.resize(e + 1, 0.0);
      weights[e] += term.coefficient;
    }
    std::vector<MatchingEdge> result(columns_.size());
    for (std::size_t e = 0; e < columns_.size(); ++e) {
      if (columns_[e].size() != 2)
        throw ParseError(file_name_ + ": the edge x" + std::to_string(e) + " appears in " +
                         std::to_string(columns_[e].size()) + " node rows; an edge has two ends");
      const auto [u, v] = std::minmax(columns_[e][0], columns_[e][1]);
      result[e] = {u, v, weights[e]};
    }
    return result;
  }

  std::vector<ConflictPair> conflicts() const {
    std::vector<ConflictPair> result;
    result.reserve(conflicts_.size());
    std::size_t expected = 0;
    for (const auto& [k, pair] : conflicts_) {
      if (k != expected++)
        throw ParseError(file_name_ + ": no row c" + std::to_string(expected - 1) +
                         " although higher conflicts have one");
      result.push_back(pair);
    }
    return result;
  }

  void check_binaries(const LpProgram& program, std::size_t edge_count) {
    std::vector<std::uint8_t> binary(edge_count, 0);
    for (const Token& t : program.binaries) {
      const std::optional<std::size_t> e = indexed_name(t.text, 'x');
      if (!e || *e >= edge_count)
        in_.fail(t.line, "the binary " + quoted(t.text) + " is not an edge of the rows");
      binary[*e] = 1;
    }
    const auto open = std::find(binary.begin(), binary.end(), 0);
    if (open != binary.end())
      throw ParseError(file_name_ + ": x" + std::to_string(open - binary.begin()) +
                       " is not declared binary (5.4)");
  }

  const Scanner& in_;
  const std::string& file_name_;
  const Limits& limits_;
  std::vector<std::vector<std::uint32_t>> columns_;  // per edge: the nodes of its rows
  std::vector<std::uint8_t> node_rows_;              // 0 none, 1 port, 2 virtual port
  std::map<std::size_t, ConflictPair> conflicts_;
};

}  // namespace

std::vector<std::uint8_t> write_instance_lp(const MatchingProblem& problem) {
  if (problem.edges.empty())
    throw InputError("a P1 instance without edges has no LP form (an LP needs a variable)");
  ByteWriter out;
  out.text("\\ Tessera P1 instance, thesis (5.1)-(5.4): ");
  out.integer(static_cast<long long>(problem.node_count()));
  out.text(" nodes, ");
  out.integer(static_cast<long long>(problem.edges.size()));
  out.text(" edges, ");
  out.integer(static_cast<long long>(problem.conflicts.size()));
  out.text(" conflict pairs\n");
  write_objective(problem, out);
  out.text("Subject To\n");
  write_node_rows(problem, out);
  write_conflict_rows(problem, out);
  write_binaries(problem, out);
  return out.take();
}

MatchingProblem read_instance_lp(std::span<const std::uint8_t> bytes, const std::string& file_name,
                                 const Limits& limits) {
  check_limit(bytes.size(), limits.max_file_bytes, file_name + " (bytes)", "--max-file-bytes");
  Scanner scanner(bytes, file_name);
  const LpProgram program = LpParser(scanner).parse();
  MatchingProblem problem = ProblemBuilder(scanner, file_name, limits).build(program);
  validate_problem(problem, limits, file_name);
  return problem;
}

}  // namespace tessera::matching
