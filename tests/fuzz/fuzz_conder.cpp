// Fuzzes a presentation in Conder's text format and, when it parses, its coset enumeration under
// small limits (an infinite or huge group must end in a LimitError, never hang).
#include <string_view>

#include "fuzz_target.h"
#include "regmap/conder_format.h"
#include "regmap/finite_group.h"

TESSERA_FUZZ_TARGET({
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const tessera::regmap::Presentation presentation =
      tessera::regmap::parse_conder_entry(text, "fuzz.txt");
  tessera::regmap::enumerate_group(presentation, tessera::fuzz::fuzz_limits());
})
