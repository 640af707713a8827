// The catalog of regular maps shipped in data/regmaps/catalog_g2-101.tsv (see its SOURCES.md): one
// reflexible orientable map per row, up to duality, with p <= q. Tab-separated columns:
//   name genus p q petrie |Aut| V E F source_key relators
// where relators is a Conder-style list "[ T^2, (R * S)^2, ... ]"; '#' lines are comments.
//
// The catalog is parsed from text (the wasm build embeds the file) or read from a path. Duals are
// reached by name with a prime: "R2.4'" is R2.4 with p, q and V, F swapped.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "regmap/presentation.h"

namespace tessera::regmap {

struct CatalogEntry {
  std::string name;  // "R3.1", or "R3.1'" for a dual
  int genus = 0;
  int p = 0;
  int q = 0;
  int petrie = 0;
  std::size_t order = 0;  // |Aut| = 4E
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::string source_key;
  std::vector<Word> relators;
};

using Catalog = std::vector<CatalogEntry>;

// Parses catalog text; `source` names it in errors ("<source>:<line>:<column>: ..."). Checks every
// row's figures against each other (|Aut| = 4E = 2pF = 2qV, V - E + F = 2 - 2g). Throws ParseError.
Catalog parse_catalog(std::string_view text, const std::string& source);

// Reads and parses the catalog file at `path`. Throws InputError if it cannot be read.
Catalog read_catalog(const std::string& path);

// The entry's dual: p and q, V and F, R and S in the relators swapped, the name primed (or
// unprimed).
CatalogEntry dual(const CatalogEntry& entry);

// The entry named `name` ("R3.1"), or the dual of the entry named without the prime ("R3.1'").
// Throws InputError naming the catalog's extent when there is none.
CatalogEntry find_map(const Catalog& catalog, const std::string& name);

// The presentation of an entry, with its order and Petrie length as stated figures.
Presentation presentation_of(const CatalogEntry& entry);

}  // namespace tessera::regmap
