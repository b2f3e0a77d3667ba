// The parts list as text and CSV (essi/parts_report.hpp).
#include "essi/parts_report.hpp"

#include "essi/text.hpp"
#include "essi/text_report.hpp"

namespace essi {
namespace {

// "3-12 13-20": a part's cuts by their lines.
std::string cut_lines(const Part& p) {
    std::string s;
    for (const PartCut& c : p.cuts) {
        if (!s.empty()) s += ' ';
        s += std::to_string(c.first_line) + "-" + std::to_string(c.last_line);
    }
    return s;
}

std::string group_text(const PartGroup& g, const PartsList& list, Lang lang) {
    std::string s = format_message(
        Msg::PartsGroup, lang,
        {std::to_string(g.number), std::to_string(g.count), mm_text(g.net_area_mm2), mm_text(g.length_mm),
         mm_text(g.width_mm), mm_text(g.cut_length_mm), std::to_string(g.holes), std::to_string(g.pierces)});
    if (g.mass_kg) s += format_message(Msg::PartsMass, lang, {fixed_text(*g.mass_kg, 3)});
    if (g.mirror_of > 0) s += format_message(Msg::PartsMirrorOf, lang, {std::to_string(g.mirror_of)});
    s += "\n";
    for (const std::uint32_t k : g.parts) {
        const Part& p = list.parts[k];
        s += "  " +
             format_message(Msg::PartsCopy, lang, {std::to_string(k + 1), std::to_string(p.plate), cut_lines(p)}) +
             "\n";
    }
    return s;
}

std::string plate_text(const PlateUse& p, Lang lang) {
    std::string s = format_message(
        Msg::PartsPlate, lang,
        {std::to_string(p.plate), mm_text(p.area.max_x - p.area.min_x), mm_text(p.area.max_y - p.area.min_y),
         text(p.from_profile ? Msg::PartsPlateFromProfile : Msg::PartsPlateFromParts, lang), std::to_string(p.parts),
         fixed_text(100 * p.utilisation, 1)});
    if (p.scrap_kg) s += format_message(Msg::PartsScrap, lang, {fixed_text(*p.scrap_kg, 3)});
    if (p.remnant)
        s += format_message(Msg::PartsRemnant, lang,
                            {mm_text(p.remnant->min_x), mm_text(p.remnant->max_x), mm_text(p.remnant->min_y),
                             mm_text(p.remnant->max_y)});
    else s += text(Msg::PartsNoRemnant, lang);
    return s + "\n";
}

}  // namespace

std::string parts_text(const PartsList& parts, Lang lang) {
    if (parts.parts.empty()) return format_message(Msg::PartsNone, lang) + "\n";
    std::string s = format_message(Msg::PartsSummary, lang,
                                   {std::to_string(parts.parts.size()), std::to_string(parts.groups.size())}) +
                    "\n";
    for (const PartGroup& g : parts.groups) s += group_text(g, parts, lang);
    for (const PlateUse& p : parts.plates) s += plate_text(p, lang);
    return s;
}

std::string parts_csv(const PartsList& parts) {
    std::string out =
        "group,count,net_area_mm2,length_mm,width_mm,cut_length_mm,holes,pierces,mass_kg,mirror_of,parts\r\n";
    for (const PartGroup& g : parts.groups) {
        std::string copies;
        for (const std::uint32_t k : g.parts) copies += (copies.empty() ? "" : ";") + cut_lines(parts.parts[k]);
        out += std::to_string(g.number) + "," + std::to_string(g.count) + "," + mm_text(g.net_area_mm2) + "," +
               mm_text(g.length_mm) + "," + mm_text(g.width_mm) + "," + mm_text(g.cut_length_mm) + "," +
               std::to_string(g.holes) + "," + std::to_string(g.pierces) + "," +
               (g.mass_kg ? fixed_text(*g.mass_kg, 3) : std::string()) + "," +
               (g.mirror_of > 0 ? std::to_string(g.mirror_of) : std::string()) + "," + csv_field(copies) + "\r\n";
    }
    return out;
}

}  // namespace essi
