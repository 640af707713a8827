// Conder's text format, the catalog rows and dual maps: what parses, and a clear ParseError with
// its position for every kind of malformed input.
#include <gtest/gtest.h>

#include <string>

#include "base/error.h"
#include "regmap/catalog.h"
#include "regmap/conder_format.h"

namespace tessera::regmap {
namespace {

using enum Letter;

// Verbatim entries of Conder's list (see data/regmaps/SOURCES.md).
constexpr const char* kR97_10 =
    "R97.10 :  Type {3,30}_40  Order 2880  mV = 2  mF = 1   \n"
    "Defining relations for automorphism group:\n"
    "[ T^2, R^-3, (R * S)^2, (R * T)^2, (S * T)^2, (S^-2 * R * S^-1)^3 ]\n";

std::string parse_error_of(const std::string& text) {
  try {
    parse_conder_entry(text, "map.txt");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

TEST(RegmapPresentation, ReadsConderEntry) {
  const Presentation p = parse_conder_entry(kR97_10, "excerpt");
  EXPECT_EQ(p.name, "R97.10");
  EXPECT_EQ(p.p, 3);
  EXPECT_EQ(p.q, 30);
  EXPECT_EQ(p.stated_petrie, 40);
  EXPECT_EQ(p.stated_order, 2880u);
  ASSERT_EQ(p.relators.size(), 6u);
  EXPECT_EQ(p.relators[1], (Word{Ri, Ri, Ri}));
  EXPECT_EQ(p.relators[5], power({Si, Si, R, Si}, 3));
}

TEST(RegmapPresentation, NameAndFiguresAreOptional) {
  const Presentation p = parse_conder_entry("Type {4,3}\n[ R^4 ]", "cube.txt");
  EXPECT_EQ(p.name, "cube.txt");
  EXPECT_EQ(p.p, 4);
  EXPECT_EQ(p.q, 3);
  EXPECT_EQ(p.stated_order, 0u);
  EXPECT_EQ(p.stated_petrie, 0);
}

TEST(RegmapPresentation, ExpandsNestedPowersAndInverses) {
  const std::vector<Word> w =
      parse_relator_list("[ ((R * S)^2 * T)^3, (R * S^-1)^-2, T^-1 ]", TextOrigin{"x", 1, 1});
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0], power({R, S, R, S, T}, 3));
  EXPECT_EQ(w[1], (Word{S, Ri, S, Ri}));
  EXPECT_EQ(w[2], (Word{T}));
}

TEST(RegmapPresentation, ReportsEachMalformedClassWithItsPosition) {
  const struct {
    const char* text;
    const char* expected;
  } cases[] = {
      {"", "map.txt:1:1: the presentation is empty"},
      {"  \n\t ", "the presentation is empty"},
      {"R3.1 : Order 336\n[ R^3 ]", "map.txt:1:8: missing type"},
      {"[ R^3 ]", "missing type"},
      {"Type {3}\n[ R ]", "expected ','"},
      {"Type {1,7}\n[ R ]", "needs p >= 2 and q >= 2"},
      {"Type {3,7}\n[ R^3, X^2 ]", "map.txt:2:8: unknown generator 'X'"},
      {"Type {3,7}\n[ r^3 ]", "unknown generator 'r'"},
      {"Type {3,7}\n[ (R * S^2 ]",
       "map.txt:2:12: expected ')' to close a parenthesis, found ']' "
       "(unbalanced parentheses)"},
      {"Type {3,7}\n[ R * S) ]", "unexpected ')' (unbalanced parentheses)"},
      {"Type {3,7}\n[ () ]", "expected a generator (R, S, T) or '(', found ')'"},
      {"Type {3,7}\n[ R^99999999999 ]", "the exponent is larger than 1000000"},
      {"Type {3,7}\n[ ((R^1000)^1000)^1000 ]", "expands to more than 1000000 letters"},
      {"Type {3,7}\n[ R^", "expected the exponent (a number), found the end of the text"},
      {"Type {3,7}\n[ R^3, S^2", "expected ',' or ']' after a relator, found the end of the text"},
      {"Type {3,7}\n[ ]", "the relator list is empty"},
      {"Type {3,7}\n", "expected a relator list '[ ... ]', found nothing"},
      {"Type {3,7}\n[ R^3 ] [ S ]", "unexpected '[' after the relator list"},
      {"Type {3,7} Ordr 5\n[ R ]", "unexpected 'O' in the header line"},
  };
  for (const auto& c : cases) {
    EXPECT_NE(parse_error_of(c.text).find(c.expected), std::string::npos)
        << "input: " << c.text << "\nerror: " << parse_error_of(c.text);
  }
}

TEST(RegmapPresentation, NeverReadsPastTheBuffer) {
  const std::string text = "Type {3,7}\n[ (R * S)^2 ]";
  // Every prefix is a truncated input: each must fail cleanly with a ParseError.
  for (std::size_t n = 0; n + 1 < text.size(); ++n) {
    EXPECT_THROW(parse_conder_entry(std::string_view(text.data(), n), "cut"), ParseError) << n;
  }
  EXPECT_NO_THROW(parse_conder_entry(text, "whole"));
}

TEST(RegmapPresentation, NulByteInsideRelatorIsAnError) {
  const std::string text("Type {3,7}\n[ R\0S ]", 18);
  EXPECT_NE(parse_error_of(text).find("byte 0"), std::string::npos) << parse_error_of(text);
}

constexpr const char* kTwoRows =
    "# cols: name genus p q petrie aut V E F key relators\n"
    "R2.4\t2\t5\t10\t2\t20\t1\t5\t2\t2.4\t[ T^2, (R * S)^2, (R * T)^2, (S * T)^2, "
    "(S^-1 * R^-1) * S * R, R^-5 ]\n"
    "R2.5\t2\t6\t6\t6\t24\t2\t6\t2\t2.5\t[ T^2, (R * S)^2, (R * T)^2, (S * T)^2, "
    "(R * S^-1)^2, R^6, S^6 ]\r\n";

TEST(RegmapCatalogText, ParsesRowsFromText) {
  const Catalog catalog = parse_catalog(kTwoRows, "embedded");
  ASSERT_EQ(catalog.size(), 2u);
  EXPECT_EQ(catalog[0].name, "R2.4");
  EXPECT_EQ(catalog[0].p, 5);
  EXPECT_EQ(catalog[0].q, 10);
  EXPECT_EQ(catalog[0].order, 20u);
  EXPECT_EQ(catalog[0].relators.size(), 6u);
  EXPECT_EQ(catalog[1].relators.back(), power({S}, 6));
}

TEST(RegmapCatalogText, FindsMapsAndTheirDuals) {
  const Catalog catalog = parse_catalog(kTwoRows, "embedded");
  const CatalogEntry d = find_map(catalog, "R2.4'");
  EXPECT_EQ(d.name, "R2.4'");
  EXPECT_EQ(d.p, 10);
  EXPECT_EQ(d.q, 5);
  EXPECT_EQ(d.vertices, 2u);
  EXPECT_EQ(d.faces, 1u);
  EXPECT_EQ(d.relators[4], (Word{Ri, Si, R, S}));  // (S^-1 R^-1) S R with R and S swapped
  EXPECT_EQ(dual(d).name, "R2.4");
  EXPECT_EQ(dual(d).relators, catalog[0].relators);
  try {
    find_map(catalog, "R9.99");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no map named 'R9.99'"), std::string::npos) << e.what();
  }
}

TEST(RegmapCatalogText, ReportsMalformedRows) {
  const struct {
    std::string text;
    const char* expected;
  } cases[] = {
      {"", "the catalog holds no maps"},
      {"# only a comment\n", "the catalog holds no maps"},
      {"R2.4\t2\t5\n", "cat:1:1: expected 11 tab-separated columns"},
      {"R2.4\t2\tfive\t10\t2\t20\t1\t5\t2\t2.4\t[ R ]\n", "cat:1:8: the p column expects"},
      {"R2.4\t2\t5\t10\t2\t20\t1\t5\t3\t2.4\t[ R ]\n", "contradict each other"},
      {"\nR2.4\t2\t5\t10\t2\t20\t1\t5\t2\t2.4\t[ R, Q ]\n", "cat:2:33: unknown generator 'Q'"},
  };
  for (const auto& c : cases) {
    try {
      parse_catalog(c.text, "cat");
      ADD_FAILURE() << "no error for: " << c.text;
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
    }
  }
}

TEST(RegmapCatalogText, MissingFileIsAnInputError) {
  EXPECT_THROW(read_catalog("/nonexistent/catalog.tsv"), InputError);
}

}  // namespace
}  // namespace tessera::regmap
