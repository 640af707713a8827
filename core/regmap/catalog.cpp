#include "regmap/catalog.h"

#include <algorithm>
#include <charconv>

#include "base/error.h"
#include "mesh/readers.h"
#include "regmap/conder_format.h"

namespace tessera::regmap {

namespace {

constexpr std::size_t kColumns = 11;

std::string where(const std::string& source, std::size_t line, std::size_t column) {
  return source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

struct Field {
  std::string_view text;
  std::size_t column;  // 1-based byte column in its line
};

std::vector<Field> split_tabs(std::string_view line) {
  std::vector<Field> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t tab = line.find('\t', start);
    fields.push_back(
        {line.substr(start, tab == std::string_view::npos ? tab : tab - start), start + 1});
    if (tab == std::string_view::npos) return fields;
    start = tab + 1;
  }
}

template <typename Int>
Int parse_count(const Field& field, const char* what, const std::string& at_line,
                std::size_t line) {
  Int value{};
  const char* begin = field.text.data();
  const char* end = begin + field.text.size();
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || field.text.empty() || value <= 0)
    throw ParseError(where(at_line, line, field.column) + "the " + what +
                     " column expects a positive integer, found '" + std::string(field.text) + "'");
  return value;
}

void check_figures(const CatalogEntry& e, const std::string& source, std::size_t line) {
  const long long v = static_cast<long long>(e.vertices), ed = static_cast<long long>(e.edges),
                  f = static_cast<long long>(e.faces);
  const bool consistent = e.order == 4 * e.edges && e.order == 2 * e.vertices * e.q &&
                          e.order == 2 * e.faces * e.p && v - ed + f == 2 - 2LL * e.genus;
  if (!consistent)
    throw ParseError(where(source, line, 1) + "the figures of " + e.name +
                     " contradict each other (|Aut| = 4E = 2qV = 2pF and V - E + F = 2 - 2g)");
}

CatalogEntry parse_row(std::string_view row, const std::string& source, std::size_t line) {
  const std::vector<Field> fields = split_tabs(row);
  if (fields.size() != kColumns)
    throw ParseError(where(source, line, 1) + "expected " + std::to_string(kColumns) +
                     " tab-separated columns (name genus p q petrie aut V E F key relators), "
                     "found " +
                     std::to_string(fields.size()));
  CatalogEntry e;
  e.name = std::string(fields[0].text);
  if (e.name.empty()) throw ParseError(where(source, line, 1) + "the name column is empty");
  e.genus = parse_count<int>(fields[1], "genus", source, line);
  e.p = parse_count<int>(fields[2], "p", source, line);
  e.q = parse_count<int>(fields[3], "q", source, line);
  e.petrie = parse_count<int>(fields[4], "Petrie length", source, line);
  e.order = parse_count<std::size_t>(fields[5], "|Aut|", source, line);
  e.vertices = parse_count<std::size_t>(fields[6], "V", source, line);
  e.edges = parse_count<std::size_t>(fields[7], "E", source, line);
  e.faces = parse_count<std::size_t>(fields[8], "F", source, line);
  if (e.p > kMaxValence || e.q > kMaxValence)
    throw ParseError(where(source, line, fields[2].column) + "p or q is above " +
                     std::to_string(kMaxValence));
  e.source_key = std::string(fields[9].text);
  e.relators = parse_relator_list(fields[10].text, TextOrigin{source, line, fields[10].column});
  check_figures(e, source, line);
  return e;
}

}  // namespace

Catalog parse_catalog(std::string_view text, const std::string& source) {
  Catalog catalog;
  std::size_t line = 0, start = 0;
  while (start < text.size()) {
    ++line;
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view row = text.substr(start, end - start);
    start = end + 1;
    if (!row.empty() && row.back() == '\r') row.remove_suffix(1);
    if (row.empty() || row.front() == '#') continue;
    catalog.push_back(parse_row(row, source, line));
  }
  if (catalog.empty()) throw ParseError(source + ": the catalog holds no maps");
  return catalog;
}

Catalog read_catalog(const std::string& path) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = read_file_bytes(path, Limits());
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) +
                     " (the regular-map catalog; set TESSERA_DATA_DIR to the folder holding "
                     "regmaps/)");
  }
  return parse_catalog(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                       path);
}

CatalogEntry dual(const CatalogEntry& entry) {
  Presentation swapped = dual(presentation_of(entry));
  CatalogEntry result = entry;
  result.name = swapped.name;
  result.p = swapped.p;
  result.q = swapped.q;
  result.vertices = entry.faces;
  result.faces = entry.vertices;
  result.relators = std::move(swapped.relators);
  return result;
}

CatalogEntry find_map(const Catalog& catalog, const std::string& name) {
  const bool want_dual = is_dual_name(name);
  const std::string base = want_dual ? name.substr(0, name.size() - 1) : name;
  const auto it = std::find_if(catalog.begin(), catalog.end(),
                               [&](const CatalogEntry& e) { return e.name == base; });
  if (it == catalog.end()) {
    const auto [lo, hi] = std::minmax_element(
        catalog.begin(), catalog.end(),
        [](const CatalogEntry& a, const CatalogEntry& b) { return a.genus < b.genus; });
    const std::string extent = catalog.empty() ? "it is empty"
                                               : std::to_string(catalog.size()) +
                                                     " maps of genus " + std::to_string(lo->genus) +
                                                     " to " + std::to_string(hi->genus);
    throw InputError("no map named '" + name + "' in the catalog (" + extent +
                     "); names look like R3.1, or R3.1' for a dual; 'tessera regmap catalog' "
                     "lists them");
  }
  return want_dual ? dual(*it) : *it;
}

Presentation presentation_of(const CatalogEntry& entry) {
  Presentation presentation;
  presentation.name = entry.name;
  presentation.p = entry.p;
  presentation.q = entry.q;
  presentation.relators = entry.relators;
  presentation.stated_order = entry.order;
  presentation.stated_petrie = entry.petrie;
  return presentation;
}

}  // namespace tessera::regmap
