#include "matching/instance_json.h"

#include <algorithm>
#include <nlohmann/json.hpp>

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

class Reader {
 public:
  Reader(const std::string& file_name, const Limits& limits)
      : file_name_(file_name), limits_(limits) {}

  MatchingProblem read(const Json& root) const {
    if (!root.is_object()) fail("", "expected a JSON object {\"format\": \"tessera-p1\", ...}");
    check_header(root);
    MatchingProblem problem;
    problem.is_virtual.assign(node_count(root), 0);
    read_virtual(member(root, "virtual"), problem);
    read_edges(member(root, "edges"), problem);
    read_conflicts(member(root, "conflicts"), problem);
    return problem;
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw ParseError(file_name_ + ": " + (where.empty() ? "" : where + ": ") + message);
  }

  const Json& member(const Json& root, const char* key) const {
    const auto it = root.find(key);
    if (it == root.end()) fail("", std::string("the key \"") + key + "\" is missing");
    return *it;
  }

  void check_header(const Json& root) const {
    const Json& format = member(root, "format");
    if (!format.is_string() || format.get<std::string>() != kFormat)
      fail("format", std::string("expected \"") + kFormat + "\"; this is not a P1 instance");
    const Json& version = member(root, "version");
    if (!version.is_number_integer() || version.get<long long>() != kVersion)
      fail("version", "only version 1 is known; was the file written by a newer Tessera?");
  }

  // "list[i]", made only for a message (an instance has hundreds of thousands of items).
  static std::string item_name(const char* list, std::size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
  }

  // Item i of `list` holds `value`, an index below `bound`.
  std::uint32_t index(const Json& value, std::size_t bound, const char* list, std::size_t i,
                      const char* what) const {
    if (!value.is_number_integer() || value.get<long long>() < 0 ||
        static_cast<unsigned long long>(value.get<long long>()) >= bound)
      fail(item_name(list, i), std::string("expected ") + what + " index in [0, " +
                                   std::to_string(bound) + "), got " + value.dump());
    return static_cast<std::uint32_t>(value.get<long long>());
  }

  const Json& array(const Json& value, const std::string& where, std::size_t limit,
                    const char* flag) const {
    if (!value.is_array()) fail(where, "expected an array");
    check_limit(value.size(), limit, file_name_ + " (" + where + ")", flag);
    return value;
  }

  std::size_t node_count(const Json& root) const {
    const Json& nodes = member(root, "nodes");
    if (!nodes.is_number_integer() || nodes.get<long long>() < 0)
      fail("nodes", "expected the number of nodes, a non-negative integer");
    const auto n = static_cast<unsigned long long>(nodes.get<long long>());
    check_limit(n, limits_.max_matching_nodes, file_name_ + " (nodes)", "--max-nodes");
    return static_cast<std::size_t>(n);
  }

  void read_virtual(const Json& list, MatchingProblem& problem) const {
    array(list, "virtual", limits_.max_matching_nodes, "--max-nodes");
    for (std::size_t i = 0; i < list.size(); ++i)
      problem.is_virtual[index(list[i], problem.node_count(), "virtual", i, "a node")] = 1;
  }

  void read_edges(const Json& list, MatchingProblem& problem) const {
    array(list, "edges", limits_.max_matching_edges, "--max-edges");
    problem.edges.reserve(list.size());
    for (std::size_t e = 0; e < list.size(); ++e) {
      const Json& item = list[e];
      if (!item.is_array() || item.size() != 3 || !item[2].is_number())
        fail(item_name("edges", e),
             "expected [u, v, weight] with node indices u, v and a number weight");
      MatchingEdge edge;
      edge.u = index(item[0], problem.node_count(), "edges", e, "a node");
      edge.v = index(item[1], problem.node_count(), "edges", e, "a node");
      edge.weight = item[2].get<double>();
      problem.edges.push_back(edge);
    }
  }

  void read_conflicts(const Json& list, MatchingProblem& problem) const {
    array(list, "conflicts", limits_.max_matching_conflicts, "--max-conflicts");
    problem.conflicts.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
      const Json& item = list[k];
      if (!item.is_array() || item.size() != 2)
        fail(item_name("conflicts", k), "expected [e1, e2], two edge indices");
      ConflictPair pair;
      pair.first = index(item[0], problem.edges.size(), "conflicts", k, "an edge");
      pair.second = index(item[1], problem.edges.size(), "conflicts", k, "an edge");
      problem.conflicts.push_back(pair);
    }
  }

  const std::string& file_name_;
  const Limits& limits_;
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
  Json root;
  try {
    root = Json::parse(bytes.begin(), bytes.end());
  } catch (const Json::parse_error& e) {
    throw ParseError(file_name + ":" + std::to_string(line_of_byte(bytes, e.byte)) +
                     ": not valid JSON (" + e.what() + ")");
  } catch (const Json::exception& e) {  // e.g. a number out of the range of a double
    throw ParseError(file_name + ": not a readable JSON instance (" + e.what() + ")");
  }
  MatchingProblem problem = Reader(file_name, limits).read(root);
  validate_problem(problem, limits, file_name);
  return problem;
}

}  // namespace tessera::matching
