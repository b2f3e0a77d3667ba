#include "essi/report_json.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "json_text.hpp"

namespace essi {

namespace {

constexpr double pow10(int n) {
    double r = 1;
    for (int i = 0; i < n; ++i) r *= 10;
    return r;
}
constexpr double kJsonLengthScale = pow10(kJsonLengthDecimals);

nlohmann::json point_to_json(Point p) { return {{"x", round_for_json(p.x)}, {"y", round_for_json(p.y)}}; }

nlohmann::json rounded_or_null(const std::optional<double>& v) {
    return v ? nlohmann::json(round_for_json(*v)) : nlohmann::json(nullptr);
}

nlohmann::json cost_to_json(const Cost& c) {
    return {{"currency", c.currency},
            {"time_s", round_for_json(c.time_s)},
            {"time_basis", c.machine_time ? "machine_time_s" : "estimated_time_s"},
            {"machine", round_for_json(c.machine)},
            {"pierces", round_for_json(c.pierces)},
            {"cut", round_for_json(c.cut)},
            {"material_kg", rounded_or_null(c.material_kg)},
            {"material", rounded_or_null(c.material)},
            {"total", round_for_json(c.total)}};
}

}  // namespace

double round_for_json(double value) {
    if (!std::isfinite(value)) return value;
    const double r = std::round(value * kJsonLengthScale) / kJsonLengthScale;
    return r == 0 ? 0.0 : r;  // no "-0.0" in reports
}

nlohmann::json diagnostic_to_json(const Diagnostic& d, Lang lang) {
    nlohmann::json j = nlohmann::json::object();
    j["severity"] = std::string(severity_name(d.severity));
    j["code"] = code_name(d.code);
    j["line"] = d.line;
    j["column"] = d.column;
    j["message"] = diagnostic_message(d, lang);
    // The cut plan's (6xx): the contour concerned, the point on the drawing, the other places, the overlap.
    if (d.contour_first > 0) j["contour"] = {{"first_line", d.contour_first}, {"last_line", d.contour_last}};
    if (d.has_at) j["at"] = point_to_json(d.at);
    if (!d.related().empty()) {
        nlohmann::json related = nlohmann::json::array();
        for (const RelatedLocation& r : d.related())
            related.push_back({{"line", r.line}, {"end_line", r.end_line}, {"message", related_message(r, lang)}});
        j["related"] = std::move(related);
    }
    if (!d.overlap().empty()) {
        nlohmann::json polygons = nlohmann::json::array();
        for (const std::vector<Point>& polygon : d.overlap()) {
            nlohmann::json points = nlohmann::json::array();
            for (Point p : polygon) points.push_back({round_for_json(p.x), round_for_json(p.y)});
            polygons.push_back(std::move(points));
        }
        j["overlap"] = std::move(polygons);
    }
    return j;
}

nlohmann::json diagnostics_to_json(std::span<const Diagnostic> diagnostics, Lang lang) {
    nlohmann::json diags = nlohmann::json::array();
    for (const Diagnostic& d : diagnostics) diags.push_back(diagnostic_to_json(d, lang));
    return diags;
}

nlohmann::json box_to_json(const Box& b) {
    if (b.empty) return nullptr;
    return {
        {"min_x", round_for_json(b.min_x)},
        {"min_y", round_for_json(b.min_y)},
        {"max_x", round_for_json(b.max_x)},
        {"max_y", round_for_json(b.max_y)},
    };
}

nlohmann::json stats_to_json(const Stats& s) {
    nlohmann::json j = nlohmann::json::object();
    j["cut_length_mm"] = round_for_json(s.cut_length_mm);
    j["cut_length_compensated_mm"] = round_for_json(s.cut_length_compensated_mm);
    j["mark_length_mm"] = round_for_json(s.mark_length_mm);
    j["travel_length_mm"] = round_for_json(s.travel_length_mm);
    j["rapid_length_mm"] = round_for_json(s.rapid_length_mm);
    j["pierces"] = s.pierces;
    j["blocks"] = s.blocks;
    j["motions"] = s.motions;
    j["estimated_time_s"] = round_for_json(s.estimated_time_s);
    j["cut_bbox_mm"] = box_to_json(s.cut_bbox);
    j["machine_cut_bbox_mm"] = box_to_json(s.machine_cut_bbox);
    j["machine_motion_bbox_mm"] = box_to_json(s.machine_motion_bbox);
    j["end_position_mm"] = point_to_json(s.end_position);
    if (s.machine_time) {
        const MachineTime& t = *s.machine_time;
        j["machine_time_s"] = round_for_json(t.total_s);
        j["machine_time_breakdown_s"] = {{"cutting", round_for_json(t.cutting_s)},
                                         {"marking", round_for_json(t.marking_s)},
                                         {"rapid", round_for_json(t.rapid_s)},
                                         {"travel", round_for_json(t.travel_s)},
                                         {"pierce", round_for_json(t.pierce_s)},
                                         {"dwell", round_for_json(t.dwell_s)},
                                         {"acceleration", round_for_json(t.acceleration_s)}};
    }
    if (s.cost) j["cost"] = cost_to_json(*s.cost);
    if (s.consumables) {
        j["consumables"] = {{"electrodes", round_for_json(s.consumables->electrodes)},
                            {"pierces", s.consumables->pierces},
                            {"arc_on_s", round_for_json(s.consumables->arc_on_s)}};
    }
    return j;
}

namespace {

nlohmann::json optional_number(const std::optional<double>& v) {
    return v ? nlohmann::json(round_for_json(*v)) : nlohmann::json(nullptr);
}

nlohmann::json part_to_json(const Part& p) {
    nlohmann::json cuts = nlohmann::json::array();
    for (const PartCut& c : p.cuts) cuts.push_back({{"first_line", c.first_line}, {"last_line", c.last_line}});
    return {{"group", p.group},
            {"plate", p.plate},
            {"cuts", std::move(cuts)},
            {"box_mm", box_to_json(p.box)},
            {"label_mm", {{"x", round_for_json(p.label_at.x)}, {"y", round_for_json(p.label_at.y)}}},
            {"cut_length_mm", round_for_json(p.cut_length_mm)},
            {"turned_deg", round_for_json(p.turned_deg)}};
}

nlohmann::json group_to_json(const PartGroup& g) {
    return {{"group", g.number},
            {"count", g.count},
            {"net_area_mm2", round_for_json(g.net_area_mm2)},
            {"outline_mm", {{"length", round_for_json(g.length_mm)}, {"width", round_for_json(g.width_mm)}}},
            {"cut_length_mm", round_for_json(g.cut_length_mm)},
            {"holes", g.holes},
            {"pierces", g.pierces},
            {"mass_kg", optional_number(g.mass_kg)},
            {"mirror_of", g.mirror_of > 0 ? nlohmann::json(g.mirror_of) : nlohmann::json(nullptr)},
            {"parts", g.parts}};
}

nlohmann::json plate_to_json(const PlateUse& p) {
    nlohmann::json remnant = nullptr;
    if (p.remnant)
        remnant = {{"x0", round_for_json(p.remnant->min_x)},
                   {"y0", round_for_json(p.remnant->min_y)},
                   {"x1", round_for_json(p.remnant->max_x)},
                   {"y1", round_for_json(p.remnant->max_y)}};
    return {{"plate", p.plate},
            {"area_mm", box_to_json(p.area)},
            {"plate_mm",
             {{"x", round_for_json(p.area.max_x - p.area.min_x)}, {"y", round_for_json(p.area.max_y - p.area.min_y)}}},
            {"from_profile", p.from_profile},
            {"parts", p.parts},
            {"net_area_mm2", round_for_json(p.net_area_mm2)},
            {"utilisation", round_for_json(p.utilisation)},
            {"scrap_kg", optional_number(p.scrap_kg)},
            {"remnant_mm", std::move(remnant)}};
}

}  // namespace

nlohmann::json parts_to_json(const PartsList& list) {
    nlohmann::json parts = nlohmann::json::array(), groups = nlohmann::json::array(), plates = nlohmann::json::array();
    for (const Part& p : list.parts) parts.push_back(part_to_json(p));
    for (const PartGroup& g : list.groups) groups.push_back(group_to_json(g));
    for (const PlateUse& p : list.plates) plates.push_back(plate_to_json(p));
    return {{"parts", std::move(parts)}, {"groups", std::move(groups)}, {"plates", std::move(plates)}};
}

namespace {

// What stands for a file's diagnostics or parts list member in write_report_json's text until it is written there.
std::string member_placeholder(std::size_t file, std::string_view member) {
    return "(" + std::string(member) + " of file " + std::to_string(file) + ")";
}
constexpr std::string_view kPartsMembers[] = {"groups", "parts", "plates"};  // (as a JSON object orders them)

// file_report_to_json, the diagnostics and the parts list's members as their placeholders when `file_index` is
// given.
nlohmann::json file_json(const FileReport& file, Lang lang, std::optional<std::size_t> file_index) {
    nlohmann::json j = nlohmann::json::object();
    j["path"] = file.display_path();
    j["ok"] = file.ok();
    j["input"] = input_format_name(file.result.input);
    if (file.result.auto_profile) {
        j["profile"] = file.result.profile;
        j["dialect_evidence"] = file.result.dialect_evidence;
    }
    if (file_index && !file.result.diagnostics.empty())
        j["diagnostics"] = member_placeholder(*file_index, "diagnostics");
    else j["diagnostics"] = diagnostics_to_json(file.result.diagnostics, lang);
    j["stats"] = stats_to_json(file.result.stats);
    if (file.omitted() > 0) j["diagnostics_omitted"] = file.omitted();
    if (file.result.parts && file_index) {
        for (const std::string_view member : kPartsMembers)
            j[std::string(member)] = member_placeholder(*file_index, member);
    } else if (file.result.parts) {
        nlohmann::json parts = parts_to_json(*file.result.parts);
        for (auto& [key, value] : parts.items()) j[key] = std::move(value);
    }
    return j;
}

nlohmann::json report_json(std::span<const FileReport> files, std::string_view profile_name, Lang lang,
                           bool parts_as_placeholders) {
    nlohmann::json out = nlohmann::json::object();
    nlohmann::json arr = nlohmann::json::array();
    std::size_t files_ok = 0, errors = 0, warnings = 0;
    for (std::size_t k = 0; k < files.size(); ++k) {
        const FileReport& f = files[k];
        arr.push_back(file_json(f, lang, parts_as_placeholders ? std::optional<std::size_t>(k) : std::nullopt));
        if (f.ok()) ++files_ok;
        errors += f.errors();
        warnings += f.warnings();
    }
    out["files"] = std::move(arr);
    out["summary"] = {
        {"files", files.size()},
        {"files_ok", files_ok},
        {"errors", errors},
        {"warnings", warnings},
    };
    out["profile"] = std::string(profile_name);
    return out;
}

}  // namespace

nlohmann::json file_report_to_json(const FileReport& file, Lang lang) { return file_json(file, lang, std::nullopt); }

nlohmann::json report_to_json(std::span<const FileReport> files, std::string_view profile_name, Lang lang) {
    return report_json(files, profile_name, lang, false);
}

void write_report_json(std::span<const FileReport> files, std::string_view profile_name, Lang lang, int indent,
                       const std::function<void(std::string_view)>& write) {
    const std::string text = report_json(files, profile_name, lang, indent > 0).dump(indent);
    const std::string_view all(text);
    std::size_t at = 0;
    // Writes the text up to the placeholder of `member`, if it is there, and the member's value in its place.
    const auto write_member = [&](std::size_t file, std::string_view member, const auto& write_value) {
        // `"member": "placeholder"` (a quote inside a string is written escaped: nothing else reads so)
        const std::string stand_in = "\"" + std::string(member) + "\": \"" + member_placeholder(file, member) + "\"";
        const std::size_t found = all.find(stand_in, at);
        if (found == std::string_view::npos) return;
        const std::size_t line = all.rfind('\n', found) + 1;  // (the member's indentation: its line's spaces)
        write(all.substr(at, found + member.size() + 4 - at));
        write_value(static_cast<int>((found - line) / indent));
        at = found + stand_in.size();
    };
    for (std::size_t k = 0; k < files.size() && indent > 0; ++k) {
        const CheckResult& r = files[k].result;
        if (!r.diagnostics.empty())
            write_member(k, "diagnostics",
                         [&](int depth) { write_diagnostics_json(r.diagnostics, lang, indent, depth, write); });
        if (!r.parts) continue;
        for (const std::string_view member : kPartsMembers)
            write_member(k, member,
                         [&](int depth) { write_parts_member_json(*r.parts, member, indent, depth, write); });
    }
    write(all.substr(at));
}

namespace {

// diagnostic_to_json(d, lang), its members by name as nlohmann::json keeps them.
void diagnostic_json(JsonText& j, const Diagnostic& d, Lang lang) {
    j.open('{');
    if (d.has_at) {
        j.key("at");
        j.open('{');
        j.rounded("x", d.at.x);
        j.rounded("y", d.at.y);
        j.close('}');
    }
    j.string("code", code_name(d.code));
    j.integer("column", d.column);
    if (d.contour_first > 0) {
        j.key("contour");
        j.open('{');
        j.integer("first_line", d.contour_first);
        j.integer("last_line", d.contour_last);
        j.close('}');
    }
    j.integer("line", d.line);
    j.string("message", diagnostic_message(d, lang));
    if (!d.overlap().empty()) {
        j.key("overlap");
        j.open('[');
        for (const std::vector<Point>& polygon : d.overlap()) {
            j.element();
            j.open('[');
            for (const Point p : polygon) {
                j.element();
                j.open('[');
                j.element();
                j.number(round_for_json(p.x));
                j.element();
                j.number(round_for_json(p.y));
                j.close(']');
            }
            j.close(']');
        }
        j.close(']');
    }
    if (!d.related().empty()) {
        j.key("related");
        j.open('[');
        for (const RelatedLocation& r : d.related()) {
            j.element();
            j.open('{');
            j.integer("end_line", r.end_line);
            j.integer("line", r.line);
            j.string("message", related_message(r, lang));
            j.close('}');
        }
        j.close(']');
    }
    j.string("severity", severity_name(d.severity));
    j.close('}');
}

}  // namespace

void write_diagnostics_json(std::span<const Diagnostic> diagnostics, Lang lang, int indent, int depth,
                            const std::function<void(std::string_view)>& write) {
    JsonText j(indent, depth, write);
    j.open('[');
    for (const Diagnostic& d : diagnostics) {
        j.element();
        diagnostic_json(j, d, lang);
    }
    j.close(']');
}

nlohmann::json stats_report_to_json(std::span<const FileReport> files, std::string_view profile_name) {
    nlohmann::json out = nlohmann::json::object();
    nlohmann::json arr = nlohmann::json::array();
    for (const FileReport& f : files) {
        arr.push_back({{"path", f.display_path()}, {"stats", stats_to_json(f.result.stats)}});
    }
    out["files"] = std::move(arr);
    out["profile"] = std::string(profile_name);
    return out;
}

}  // namespace essi
