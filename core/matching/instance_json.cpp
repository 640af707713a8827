#include "matching/instance_json.h"

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>

#include "base/error.h"
#include "export/byte_writer.h"

namespace tessera::matching {

namespace {

using Json = nlohmann::json;

constexpr const char* kFormat = "tessera-p1";
constexpr int kVersion = 1;

void write_virtual(const MatchingProblem& problem, ByteWriter& out) {
  out.text("\"virtual\": [");
  bool first = true;
  for (std::size_t v = 0; v < problem.node_count(); ++v) {
    if (!problem.is_virtual[v]) continue;
    if (!first) out.text(", ");
    out.integer(static_cast<long long>(v));
    first = false;
  }
  out.text("],\n");
}

void write_edges(const MatchingProblem& problem, ByteWriter& out) {
  out.text("\"edges\": [");
  for (std::size_t e = 0; e < problem.edges.size(); ++e) {
    const MatchingEdge& edge = problem.edges[e];
    out.text(e == 0 ? "\n[" : ",\n[");
    out.integer(edge.u);
    out.text(", ");
    out.integer(edge.v);
    out.text(", ");
    out.number(edge.weight);
    out.text("]");
  }
  out.text("],\n");
}

void write_conflicts(const MatchingProblem& problem, ByteWriter& out) {
  constexpr std::size_t kPerLine = 8;
  out.text("\"conflicts\": [");
  for (std::size_t k = 0; k < problem.conflicts.size(); ++k) {
    out.text(k == 0 ? "\n[" : (k % kPerLine == 0 ? ",\n[" : ", ["));
    out.integer(problem.conflicts[k].first);
    out.text(", ");
    out.integer(problem.conflicts[k].second);
    out.text("]");
  }
  out.text("]}\n");
}

std::size_t line_of_byte(std::span<const std::uint8_t> bytes, std::size_t byte) {
  const std::size_t end = std::min(byte, bytes.size());
  return 1 + static_cast<std::size_t>(std::count(bytes.begin(), bytes.begin() + end, '\n'));
}

// Reads an instance while nlohmann's parser walks the text (its SAX interface): no document tree
// is built. The tree took most of `tessera solve` on small instances (fandisk at alpha 1: about
// 20 of 26 ms) and 750 MB for dragon's. The root object's keys may come in any order, so the
// indices are checked against "nodes" and the edges once the object is read.
class Reader {
 public:
  Reader(std::span<const std::uint8_t> bytes, const std::string& file_name, const Limits& limits)
      : bytes_(bytes), file_name_(file_name), limits_(limits) {}

  MatchingProblem read() {
    Json::sax_parse(bytes_.begin(), bytes_.end(), this);
    for (const char* key : {"format", "version", "nodes", "virtual", "edges", "conflicts"})
      if (!seen_.contains(key)) fail("", std::string("the key \"") + key + "\" is missing");
    MatchingProblem problem;
    problem.is_virtual.assign(nodes_, 0);
    for (std::size_t i = 0; i < virtual_.size(); ++i)
      problem.is_virtual[index(virtual_[i], nodes_, "virtual", i, "a node")] = 1;
    problem.edges = std::move(edges_);
    for (std::size_t e = 0; e < problem.edges.size(); ++e) {
      index(problem.edges[e].u, nodes_, "edges", e, "a node");
      index(problem.edges[e].v, nodes_, "edges", e, "a node");
    }
    problem.conflicts = std::move(conflicts_);
    for (std::size_t k = 0; k < problem.conflicts.size(); ++k) {
      index(problem.conflicts[k].first, problem.edges.size(), "conflicts", k, "an edge");
      index(problem.conflicts[k].second, problem.edges.size(), "conflicts", k, "an edge");
    }
    return problem;
  }

  // nlohmann's SAX interface: each returns true to go on; errors throw.
  bool null() { return scalar(Scalar{}); }
  bool boolean(bool) { return scalar(Scalar{}); }
  bool number_integer(std::int64_t value) {
    return value < 0 ? scalar(Scalar{false, true, double(value)})
                     : number_unsigned(static_cast<std::uint64_t>(value));
  }
  bool number_unsigned(std::uint64_t value) {
    return scalar(Scalar{true, true, double(value), value});
  }
  bool number_float(double value, const std::string&) { return scalar(Scalar{false, true, value}); }
  bool string(std::string& value) { return scalar(Scalar{false, false, 0.0, 0, &value}); }
  bool binary(Json::binary_t&) { return scalar(Scalar{}); }
  bool key(std::string& name) {
    if (depth_ != 1) return true;
    key_ = name;
    if (!seen_.insert(key_).second && list_of(key_) != List::none)
      fail(key_, "the key appears twice");
    return true;
  }
  bool start_object(std::size_t) {
    if (depth_ == 0) {
      ++depth_;
      return true;
    }
    return container();
  }
  bool start_array(std::size_t) {
    if (depth_ == 0) fail("", "expected a JSON object {\"format\": \"tessera-p1\", ...}");
    return container(true);
  }
  bool end_object() { return end(); }
  bool end_array() { return end(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    throw ParseError(file_name_ + ":" + std::to_string(line_of_byte(bytes_, position)) +
                     ": not valid JSON (" + e.what() + ")");
  }

 private:
  enum class List { none, virtual_ports, edges, conflicts };

  // A JSON value that is neither an object nor an array.
  struct Scalar {
    bool index = false;  // a non-negative integer
    bool number = false;
    double value = 0.0;
    std::uint64_t unsigned_value = 0;
    const std::string* string = nullptr;
  };

  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw ParseError(file_name_ + ": " + (where.empty() ? "" : where + ": ") + message);
  }

  // "list[i]", made only for a message (an instance has hundreds of thousands of items).
  static std::string item_name(const char* list, std::size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
  }

  // Item i of `list` holds `value`, an index below `bound`.
  std::uint32_t index(std::uint64_t value, std::size_t bound, const char* list, std::size_t i,
                      const char* what) const {
    if (value >= bound)
      fail(item_name(list, i), std::string("expected ") + what + " index in [0, " +
                                   std::to_string(bound) + "), got " + std::to_string(value));
    return static_cast<std::uint32_t>(value);
  }

  bool scalar(const Scalar& value) {
    if (depth_ == 0) fail("", "expected a JSON object {\"format\": \"tessera-p1\", ...}");
    if (depth_ == 1) return member(value);
    if (skipped_ > 0) return true;
    if (depth_ == 2 && list_ == List::virtual_ports) {
      check_limit(virtual_.size() + 1, limits_.max_matching_nodes, file_name_ + " (virtual)",
                  "--max-nodes");
      if (!value.index) fail(item_name("virtual", virtual_.size()), "expected a node index");
      virtual_.push_back(value.unsigned_value);
      return true;
    }
    if (depth_ != 3) item_shape_error(list_count());
    if (item_.size() == item_length()) item_shape_error(list_count());
    item_.push_back(value);
    return true;
  }

  // A value of the root object.
  bool member(const Scalar& value) {
    if (key_ == "format") {
      if (!value.string || *value.string != kFormat)
        fail("format", std::string("expected \"") + kFormat + "\"; this is not a P1 instance");
    } else if (key_ == "version") {
      if (!value.index || value.unsigned_value != kVersion)
        fail("version", "only version 1 is known; was the file written by a newer Tessera?");
    } else if (key_ == "nodes") {
      if (!value.index) fail("nodes", "expected the number of nodes, a non-negative integer");
      check_limit(value.unsigned_value, limits_.max_matching_nodes, file_name_ + " (nodes)",
                  "--max-nodes");
      nodes_ = static_cast<std::size_t>(value.unsigned_value);
    } else if (list_of(key_) != List::none) {
      fail(key_, "expected an array");
    }
    return true;
  }

  // An object or array opens below the root.
  bool container(bool array = false) {
    ++depth_;
    if (skipped_ > 0 || (depth_ == 2 && !array)) {
      if (depth_ == 2) member_container();
      ++skipped_;
      return true;
    }
    if (depth_ == 2) return list_start();
    if (depth_ == 3 && array && (list_ == List::edges || list_ == List::conflicts)) {
      const bool edges = list_ == List::edges;
      check_limit(list_count() + 1,
                  edges ? limits_.max_matching_edges : limits_.max_matching_conflicts,
                  file_name_ + (edges ? " (edges)" : " (conflicts)"),
                  edges ? "--max-edges" : "--max-conflicts");
      item_.clear();
      return true;
    }
    item_shape_error(list_count());
  }

  // An object as a member of the root: wrong for the keys the reader knows, skipped otherwise.
  void member_container() {
    if (list_of(key_) != List::none) fail(key_, "expected an array");
    member(Scalar{});
  }

  bool list_start() {
    list_ = list_of(key_);
    if (list_ == List::none) {
      member(Scalar{});  // a header key holding an array fails there
      skipped_ = 1;
    }
    return true;
  }

  static List list_of(const std::string& key) {
    return key == "virtual"     ? List::virtual_ports
           : key == "edges"     ? List::edges
           : key == "conflicts" ? List::conflicts
                                : List::none;
  }

  bool end() {
    --depth_;
    if (skipped_ > 0) {
      --skipped_;
      return true;
    }
    if (depth_ == 2) finish_item();
    if (depth_ == 1) list_ = List::none;
    return true;
  }

  std::size_t item_length() const { return list_ == List::edges ? 3 : 2; }
  std::size_t list_count() const {
    return list_ == List::edges ? edges_.size() : conflicts_.size();
  }

  [[noreturn]] void item_shape_error(std::size_t i) const {
    if (list_ == List::edges)
      fail(item_name("edges", i),
           "expected [u, v, weight] with node indices u, v and a number weight");
    if (list_ == List::conflicts)
      fail(item_name("conflicts", i), "expected [e1, e2], two edge indices");
    fail(item_name("virtual", virtual_.size()), "expected a node index");
  }

  void finish_item() {
    const std::size_t i = list_count();
    const auto is_index = [](const Scalar& s) { return s.index && s.unsigned_value <= UINT32_MAX; };
    if (item_.size() != item_length() || !is_index(item_[0]) || !is_index(item_[1]))
      item_shape_error(i);
    const auto u = static_cast<std::uint32_t>(item_[0].unsigned_value);
    const auto v = static_cast<std::uint32_t>(item_[1].unsigned_value);
    if (list_ == List::conflicts) {
      conflicts_.push_back({u, v});
      return;
    }
    if (!item_[2].number) item_shape_error(i);
    edges_.push_back({u, v, item_[2].value});
  }

  std::span<const std::uint8_t> bytes_;
  const std::string& file_name_;
  const Limits& limits_;
  int depth_ = 0;
  int skipped_ = 0;  // depth inside a value the reader does not use
  std::string key_;  // the root's key whose value is read
  List list_ = List::none;
  std::vector<Scalar> item_;
  std::set<std::string> seen_;  // the root's keys
  std::size_t nodes_ = 0;
  std::vector<std::uint64_t> virtual_;
  std::vector<MatchingEdge> edges_;
  std::vector<ConflictPair> conflicts_;
};

}  // namespace

std::vector<std::uint8_t> write_instance_json(const MatchingProblem& problem) {
  ByteWriter out;
  out.text("{\"format\": \"");
  out.text(kFormat);
  out.text("\", \"version\": 1, \"nodes\": ");
  out.integer(static_cast<long long>(problem.node_count()));
  out.text(",\n");
  write_virtual(problem, out);
  write_edges(problem, out);
  write_conflicts(problem, out);
  return out.take();
}

MatchingProblem read_instance_json(std::span<const std::uint8_t> bytes,
                                   const std::string& file_name, const Limits& limits) {
  check_limit(bytes.size(), limits.max_file_bytes, file_name + " (bytes)", "--max-file-bytes");
  MatchingProblem problem = Reader(bytes, file_name, limits).read();
  validate_problem(problem, limits, file_name);
  return problem;
}

}  // namespace tessera::matching
