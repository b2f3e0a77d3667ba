// The parts list as `essi parts` writes it (docs/cli.md): text in the reader's language, and CSV. Its JSON is
// parts_to_json (essi/report_json.hpp), the report's contract.
#pragma once

#include <string>

#include "essi/i18n.hpp"
#include "essi/parts.hpp"

namespace essi {

// The groups, each with its parts and the lines they are cut on, then the plates; every line ends in a newline.
[[nodiscard]] std::string parts_text(const PartsList& parts, Lang lang = Lang::En);

// One row a group (RFC 4180, a header line, CR LF): group,count,net_area_mm2,length_mm,width_mm,cut_length_mm,
// holes,pierces,mass_kg,mirror_of,parts (each part's cuts as FIRST-LAST lines, a part's cuts apart by spaces, the
// parts by ";").
[[nodiscard]] std::string parts_csv(const PartsList& parts);

}  // namespace essi
