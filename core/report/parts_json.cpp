// The parts list written as JSON text without making it a JSON value (essi/report_json.hpp): the same text as
// parts_to_json(...).dump(indent), its members in the order nlohmann::json keeps them (by name) and its numbers
// written by nlohmann's own conversion.
#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "essi/report_json.hpp"
#include "json_text.hpp"

namespace essi {
namespace {

void part_json(JsonText& j, const Part& p) {
    j.open('{');
    j.box("box_mm", p.box);
    j.rounded("cut_length_mm", p.cut_length_mm);
    j.key("cuts");
    j.open('[');
    for (const PartCut& c : p.cuts) {
        j.element();
        j.open('{');
        j.integer("first_line", c.first_line);
        j.integer("last_line", c.last_line);
        j.close('}');
    }
    j.close(']');
    j.integer("group", p.group);
    j.key("label_mm");
    j.open('{');
    j.rounded("x", p.label_at.x);
    j.rounded("y", p.label_at.y);
    j.close('}');
    j.integer("plate", p.plate);
    j.rounded("turned_deg", p.turned_deg);
    j.close('}');
}

void group_json(JsonText& j, const PartGroup& g) {
    j.open('{');
    j.integer("count", g.count);
    j.rounded("cut_length_mm", g.cut_length_mm);
    j.integer("group", g.number);
    j.integer("holes", g.holes);
    j.rounded_or_null("mass_kg", g.mass_kg);
    j.key("mirror_of");
    if (g.mirror_of > 0) j.integer(g.mirror_of);
    else j.null();
    j.rounded("net_area_mm2", g.net_area_mm2);
    j.key("outline_mm");
    j.open('{');
    j.rounded("length", g.length_mm);
    j.rounded("width", g.width_mm);
    j.close('}');
    j.key("parts");
    j.open('[');
    for (const std::uint32_t k : g.parts) {
        j.element();
        j.integer(k);
    }
    j.close(']');
    j.integer("pierces", g.pierces);
    j.close('}');
}

void plate_json(JsonText& j, const PlateUse& p) {
    j.open('{');
    j.box("area_mm", p.area);
    j.key("from_profile");
    j.boolean(p.from_profile);
    j.rounded("net_area_mm2", p.net_area_mm2);
    j.integer("parts", p.parts);
    j.integer("plate", p.plate);
    j.key("plate_mm");
    j.open('{');
    j.rounded("x", p.area.max_x - p.area.min_x);
    j.rounded("y", p.area.max_y - p.area.min_y);
    j.close('}');
    j.key("remnant_mm");
    if (p.remnant) {
        j.open('{');
        j.rounded("x0", p.remnant->min_x);
        j.rounded("x1", p.remnant->max_x);
        j.rounded("y0", p.remnant->min_y);
        j.rounded("y1", p.remnant->max_y);
        j.close('}');
    } else {
        j.null();
    }
    j.rounded_or_null("scrap_kg", p.scrap_kg);
    j.rounded("utilisation", p.utilisation);
    j.close('}');
}

template <class T, class Write>
void array_json(JsonText& j, const std::vector<T>& items, Write write) {
    j.open('[');
    for (const T& item : items) {
        j.element();
        write(j, item);
    }
    j.close(']');
}

}  // namespace

void write_parts_member_json(const PartsList& parts, std::string_view member, int indent, int depth,
                             const std::function<void(std::string_view)>& write) {
    JsonText j(indent, depth, write);
    if (member == "parts") array_json(j, parts.parts, part_json);
    else if (member == "groups") array_json(j, parts.groups, group_json);
    else if (member == "plates") array_json(j, parts.plates, plate_json);
}

}  // namespace essi
