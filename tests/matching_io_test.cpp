// P1 instance files: JSON and CPLEX LP round trips, and every class of bad input giving a typed
// error that names the file and the place.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>

#include "base/error.h"
#include "matching/generate.h"
#include "matching/instance_json.h"
#include "matching/instance_lp.h"

namespace tessera::matching {
namespace {

std::vector<std::uint8_t> bytes_of(const std::string& text) {
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

// Edge endpoints in increasing order, as the LP reader gives them back.
MatchingProblem with_sorted_ends(MatchingProblem p) {
  for (MatchingEdge& e : p.edges)
    if (e.u > e.v) std::swap(e.u, e.v);
  return p;
}

void expect_same(const MatchingProblem& a, const MatchingProblem& b) {
  EXPECT_EQ(a.is_virtual, b.is_virtual);
  ASSERT_EQ(a.edges.size(), b.edges.size());
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    EXPECT_EQ(a.edges[e].u, b.edges[e].u) << "edge " << e;
    EXPECT_EQ(a.edges[e].v, b.edges[e].v) << "edge " << e;
    EXPECT_EQ(a.edges[e].weight, b.edges[e].weight) << "edge " << e;  // bit-exact
  }
  ASSERT_EQ(a.conflicts.size(), b.conflicts.size());
  for (std::size_t k = 0; k < a.conflicts.size(); ++k) {
    EXPECT_EQ(a.conflicts[k].first, b.conflicts[k].first) << "conflict " << k;
    EXPECT_EQ(a.conflicts[k].second, b.conflicts[k].second) << "conflict " << k;
  }
}

MatchingProblem sample_problem() {
  PlantedSpec spec;
  spec.ports = 21;
  spec.virtual_ports = 5;
  spec.extra_edges = 70;
  spec.conflicts = 90;
  spec.seed = 7;
  MatchingProblem p = planted_instance(spec);
  p.edges.push_back({3, 4, -0.1});  // a multi-edge candidate with a weight that is no short decimal
  p.edges.push_back({4, 3, 1e-300});
  p.is_virtual.push_back(1);  // a virtual port without edges
  p.is_virtual.push_back(0);  // and a port without edges: still a valid (infeasible) instance
  return p;
}

TEST(MatchingIo, JsonRoundTripIsExact) {
  const MatchingProblem p = sample_problem();
  expect_same(p, read_instance_json(write_instance_json(p), "p.json", Limits()));
}

TEST(MatchingIo, LpRoundTripIsExact) {
  const MatchingProblem p = sample_problem();
  expect_same(with_sorted_ends(p), read_instance_lp(write_instance_lp(p), "p.lp", Limits()));
}

TEST(MatchingIo, LpStatesTheProgram) {
  MatchingProblem p;
  p.is_virtual = {0, 0, 1};
  p.edges = {{0, 1, 2.5}, {1, 2, -1}, {0, 2, 0}};
  p.conflicts = {{0, 1}};
  const std::vector<std::uint8_t> bytes = write_instance_lp(p);
  const std::string text(bytes.begin(), bytes.end());
  for (const char* part : {"Minimize\n obj: 2.5 x0 - 1 x1 + 0 x2\n", "Subject To\n",
                           " p0: x0 + x2 = 1\n", " p1: x0 + x1 = 1\n", " v2: x1 + x2 <= 1\n",
                           " c0: x0 + x1 <= 1\n", "Binaries\n x0 x1 x2\nEnd\n"})
    EXPECT_NE(text.find(part), std::string::npos) << part << " not in\n" << text;
}

TEST(MatchingIo, LpReaderAcceptsCplexVariants) {
  const std::string text =
      "\\ a comment\nMINIMIZE\n 2 x0 + x1\n   +3.5e0 x2\nsubject to\n"
      "p0: x0 + x1 = 1\np1:\n x0\n + x2 = 1\nv2: x1 + x2 =< 1 \\ trailing comment\n"
      "v3: 0 x0 <= 1\nc0: x1 + x2 <= 1\nbinary x0 x1\n x2\nend\n";
  const MatchingProblem p = read_instance_lp(bytes_of(text), "v.lp", Limits());
  EXPECT_EQ(p.is_virtual, (std::vector<std::uint8_t>{0, 0, 1, 1}));
  ASSERT_EQ(p.edges.size(), 3u);
  EXPECT_EQ(p.edges[2].u, 1u);
  EXPECT_EQ(p.edges[2].v, 2u);
  EXPECT_EQ(p.edges[2].weight, 3.5);
  ASSERT_EQ(p.conflicts.size(), 1u);
}

template <class E>
void expect_error(const std::function<void()>& read, std::initializer_list<std::string> parts) {
  try {
    read();
    ADD_FAILURE() << "expected an error";
  } catch (const E& e) {
    for (const std::string& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "'" << part << "' not in: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong error type: " << e.what();
  }
}

void expect_json_error(const std::string& text, std::initializer_list<std::string> parts,
                       const Limits& limits = {}) {
  expect_error<InputError>([&] { read_instance_json(bytes_of(text), "bad.json", limits); }, parts);
}

void expect_lp_error(const std::string& text, std::initializer_list<std::string> parts,
                     const Limits& limits = {}) {
  expect_error<InputError>([&] { read_instance_lp(bytes_of(text), "bad.lp", limits); }, parts);
}

const std::string kJsonHead = "{\"format\": \"tessera-p1\", \"version\": 1, ";

TEST(MatchingIo, JsonErrorsNameThePlace) {
  expect_json_error("{\"format\": \"tessera-p1\",\n \"version\": 1,\n \"nodes\": }",
                    {"bad.json:3:", "not valid JSON"});
  expect_json_error("", {"bad.json:1:"});
  expect_json_error("[1, 2]", {"JSON object"});
  expect_json_error("{\"format\": \"mesh\"}", {"format", "tessera-p1"});
  expect_json_error(kJsonHead + "\"virtual\": [], \"edges\": [], \"conflicts\": []}",
                    {"\"nodes\" is missing"});
  expect_json_error(kJsonHead + "\"nodes\": 2, \"virtual\": [2], \"edges\": [], \"conflicts\": []}",
                    {"virtual[0]", "[0, 2)"});
  expect_json_error(
      kJsonHead + "\"nodes\": 2, \"virtual\": [], \"edges\": [[0, 1]], \"conflicts\": []}",
      {"edges[0]", "[u, v, weight]"});
  expect_json_error(kJsonHead +
                        "\"nodes\": 2, \"virtual\": [], \"edges\": [[0, 1, 1], [1, 5, 1]], "
                        "\"conflicts\": []}",
                    {"edges[1]", "node index"});
  expect_json_error(kJsonHead +
                        "\"nodes\": 2, \"virtual\": [], \"edges\": [[0, 1, 1]], "
                        "\"conflicts\": [[0, 1]]}",
                    {"conflicts[0]", "edge index"});
  expect_json_error(kJsonHead +
                        "\"nodes\": 2, \"virtual\": [], \"edges\": [[1, 1, 1]], "
                        "\"conflicts\": []}",
                    {"edge 0", "loop"});
  expect_json_error(kJsonHead +
                        "\"nodes\": 2, \"virtual\": [], \"edges\": [[0, 1, 1e999]], "
                        "\"conflicts\": []}",
                    {"bad.json"});
}

TEST(MatchingIo, JsonKeysComeInAnyOrderAndUnknownOnesAreSkipped) {
  const MatchingProblem p = read_instance_json(
      bytes_of("{\"conflicts\": [[0, 1]], \"note\": {\"by\": [1, {\"x\": []}]}, "
               "\"edges\": [[0, 1, 2.5], [1, 2, 1e-3]], \"virtual\": [2], \"nodes\": 3, "
               "\"version\": 1, \"format\": \"tessera-p1\"}"),
      "any.json", Limits());
  ASSERT_EQ(p.node_count(), 3u);
  EXPECT_EQ(p.is_virtual, (std::vector<std::uint8_t>{0, 0, 1}));
  ASSERT_EQ(p.edges.size(), 2u);
  EXPECT_EQ(p.edges[1].v, 2u);
  EXPECT_EQ(p.edges[1].weight, 1e-3);
  ASSERT_EQ(p.conflicts.size(), 1u);
  EXPECT_EQ(p.conflicts[0].second, 1u);
}

TEST(MatchingIo, JsonItemsOfTheWrongShapeAreNamed) {
  const std::string head = kJsonHead + "\"nodes\": 3, \"virtual\": [], ";
  expect_json_error(head + "\"edges\": [[0, 1, 1], [0, [1], 1]], \"conflicts\": []}",
                    {"edges[1]", "[u, v, weight]"});
  expect_json_error(head + "\"edges\": [[0, 1, 1, 4]], \"conflicts\": []}",
                    {"edges[0]", "[u, v, weight]"});
  expect_json_error(head + "\"edges\": [[0, 1, \"1\"]], \"conflicts\": []}",
                    {"edges[0]", "[u, v, weight]"});
  expect_json_error(head + "\"edges\": [[0, -1, 1]], \"conflicts\": []}",
                    {"edges[0]", "[u, v, weight]"});
  expect_json_error(head + "\"edges\": [[0, 1, 1]], \"conflicts\": [0]}",
                    {"conflicts[0]", "[e1, e2]"});
  expect_json_error(head + "\"edges\": {}, \"conflicts\": []}", {"edges", "an array"});
  expect_json_error(head + "\"edges\": [], \"edges\": [], \"conflicts\": []}", {"edges", "twice"});
  expect_json_error(kJsonHead +
                        "\"nodes\": 3, \"virtual\": [\"a\"], \"edges\": [], "
                        "\"conflicts\": []}",
                    {"virtual[0]", "node index"});
  expect_json_error(kJsonHead +
                        "\"nodes\": [3], \"virtual\": [], \"edges\": [], "
                        "\"conflicts\": []}",
                    {"nodes", "non-negative integer"});
  expect_json_error(head + "\"edges\": []}", {"\"conflicts\" is missing"});
  expect_json_error(head + "\"edges\": [[0, 1, 1]], \"conflicts\": []} []", {"bad.json:1:"});
}

TEST(MatchingIo, JsonLimitsAreCheckedBeforeAllocating) {
  Limits limits;
  limits.max_matching_nodes = 10;
  expect_error<LimitError>(
      [&] {
        read_instance_json(bytes_of(kJsonHead + "\"nodes\": 4000000000, \"virtual\": [], "
                                                "\"edges\": [], \"conflicts\": []}"),
                           "big.json", limits);
      },
      {"nodes", "--max-nodes"});
  limits = Limits();
  limits.max_matching_edges = 1;
  expect_error<LimitError>(
      [&] {
        read_instance_json(bytes_of(kJsonHead + "\"nodes\": 3, \"virtual\": [], \"edges\": "
                                                "[[0, 1, 1], [1, 2, 1]], \"conflicts\": []}"),
                           "big.json", limits);
      },
      {"edges", "--max-edges"});
}

TEST(MatchingIo, LpErrorsNameTheLine) {
  expect_lp_error("Maximize\n obj: x0\nEnd\n", {"bad.lp:1:", "minimizes"});
  expect_lp_error("Minimize\n obj: x0\nSubject To\n p0: x0 = 1\n", {"without 'End'"});
  expect_lp_error("Minimize\n obj: x0\nSubject To\n q0: x0 = 1\nEnd\n",
                  {"bad.lp:4:", "'q0'", "neither"});
  expect_lp_error("Minimize\n obj: x0\nSubject To\n p0: x0 = 1\n p1: x0 = 1\n p2: x0 = 1\nEnd\n",
                  {"bad.lp:6:", "third endpoint"});
  expect_lp_error("Minimize\n obj: x0\nSubject To\n p0: x0 <= 1\nEnd\n",
                  {"bad.lp:4:", "exactly one edge"});
  expect_lp_error(
      "Minimize\n obj: x0\nSubject To\n p0: x0 = 1\n p1: x0 = 1\n c0: x0 + y <= 1\nEnd\n",
      {"bad.lp:6:", "'y'", "not an edge"});
  expect_lp_error(
      "Minimize\n obj: x0\nSubject To\n p0: x0 = 1\n p1: x0 = 1\nBounds\n x0 <= 1\nEnd\n",
      {"bad.lp:7:", "no bounds"});
  expect_lp_error("Minimize\n obj: x0\nSubject To\n p0: x0 = 1\n p1: x0 = 1\nEnd\n",
                  {"x0 is not declared binary"});
  expect_lp_error("Minimize\n obj: x0\nSubject To\n p0: x0 = 1\n p2: x0 = 1\nBinaries\n x0\nEnd\n",
                  {"no row p1 or v1"});
  expect_lp_error("Minimize\n obj: 2 x0\nSubject To\n p0: x0 = \n", {"bad.lp:5:", "right-hand"});
  expect_lp_error(std::string("Minimize\n obj: x0\0\n", 19), {"bad.lp:2:", "binary file"});
  expect_lp_error("Minimize\n obj: x0 + 2 ..3 x1\n", {"bad.lp:2:", "'..3'"});
  Limits limits;
  limits.max_matching_edges = 100;
  expect_error<LimitError>(
      [&] {
        read_instance_lp(bytes_of("Minimize\n obj: x99999999999\nSubject To\nEnd\n"), "big.lp",
                         limits);
      },
      {"--max-edges"});
}

TEST(MatchingIo, TruncatedFilesNeverReadPastTheBuffer) {
  const MatchingProblem p = sample_problem();
  const std::vector<std::uint8_t> json = write_instance_json(p);
  const std::vector<std::uint8_t> lp = write_instance_lp(p);
  for (std::size_t cut : {std::size_t{0}, std::size_t{1}, json.size() / 3, json.size() - 2}) {
    const std::vector<std::uint8_t> head(json.begin(), json.begin() + cut);
    EXPECT_THROW(read_instance_json(head, "t.json", Limits()), InputError) << cut;
  }
  for (std::size_t cut : {std::size_t{0}, std::size_t{5}, lp.size() / 2, lp.size() - 3}) {
    const std::vector<std::uint8_t> head(lp.begin(), lp.begin() + cut);
    EXPECT_THROW(read_instance_lp(head, "t.lp", Limits()), InputError) << cut;
  }
}

}  // namespace
}  // namespace tessera::matching
