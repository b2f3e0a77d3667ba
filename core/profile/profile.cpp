// Built-in profiles and the JSON form of a profile. Parsing never throws: nlohmann::json is used in its
// non-throwing form and every key is type-checked before it is read.
#include "essi/profile.hpp"
#include "essi/text.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace essi {
namespace {

using nlohmann::json;

Profile make_iso6582() { return Profile{}; }

Profile make_woyda() {
    Profile p;
    p.name = "woyda";
    p.dialect = Dialect::Woyda;
    p.end_codes = {{fn::kCancelFunctions, 0}, {fn::kEndOfTape, 0}, {-1, '/'}};
    return p;
}

std::string end_code_text(const EndCode& e) {
    if (e.function >= 0) return std::to_string(e.function);
    return std::string(1, e.mark);
}

std::optional<EndCode> parse_end_code(const json& j) {
    if (j.is_number_integer()) {
        const auto v = j.get<long long>();
        if (v < 0 || v > 999) return std::nullopt;
        return EndCode{static_cast<int>(v), 0};
    }
    if (!j.is_string()) return std::nullopt;
    const auto& s = j.get_ref<const std::string&>();
    if (s == "/" || s == "=") return EndCode{-1, s[0]};
    if (s.empty() || s.size() > 3) return std::nullopt;
    int v = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + (c - '0');
    }
    return EndCode{v, 0};
}

// Reads the keys of `j` into `p`; each problem becomes one message in `errors`.
// The values a profile key may take: wide enough for any machine, narrow enough that no length, time or position
// computed from them overflows to infinity (a unit of 1e308 mm made "inf" reports that were "ok").
struct Range {
    double min, max;
};
constexpr Range kUnitRange{1e-9, 1000};             // mm per unit increment
constexpr Range kUnitsRange{0, 1e9};                // tolerances and kerf, in unit increments
constexpr Range kChordRange{1e-6, 1000};            // mm
constexpr Range kSecondsRange{0, 1e6};              // dwell and pierce time, s
constexpr Range kSpeedRange{1e-9, 1e9};             // mm/min
constexpr Range kPositionRange{-1e9, 1e9};          // mm: offsets and table limits

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The bytes of a key that an error message quotes (essi::excerpt).
constexpr std::size_t kMaxKeyChars = 40;

void apply_keys(const json& j, Profile& p, std::vector<std::string>& errors) {
    auto number = [&](const char* key, double& out, Range range) {
        auto it = j.find(key);
        if (it == j.end()) return;
        if (!it->is_number()) {
            errors.push_back(std::string("\"") + key + "\" must be a number");
            return;
        }
        const double v = it->get<double>();
        if (!(v >= range.min && v <= range.max)) {  // (NaN and infinities too)
            errors.push_back(std::string("\"") + key + "\" must be between " + number_text(range.min) + " and " +
                             number_text(range.max) + "; found " + number_text(v));
            return;
        }
        out = v;
    };
    auto boolean = [&](const char* key, bool& out) {
        auto it = j.find(key);
        if (it == j.end()) return;
        if (!it->is_boolean()) {
            errors.push_back(std::string("\"") + key + "\" must be true or false");
            return;
        }
        out = it->get<bool>();
    };
    auto choice = [&](const char* key, auto& out, std::initializer_list<std::pair<const char*, std::decay_t<decltype(out)>>> options) {
        auto it = j.find(key);
        if (it == j.end()) return;
        std::string allowed;
        for (const auto& [name, value] : options) {
            if (it->is_string() && it->get_ref<const std::string&>() == name) {
                out = value;
                return;
            }
            allowed += allowed.empty() ? "" : ", ";
            allowed += std::string("\"") + name + "\"";
        }
        errors.push_back(std::string("\"") + key + "\" must be one of " + allowed);
    };

    if (auto it = j.find("name"); it != j.end()) {
        if (it->is_string()) p.name = it->get<std::string>();
        else errors.push_back("\"name\" must be a string");
    }
    choice("dialect", p.dialect, {{"iso6582", Dialect::Iso6582}, {"woyda", Dialect::Woyda}});
    number("unit_mm", p.unit_mm, kUnitRange);
    choice("whitespace", p.whitespace, {{"skip", WhitespacePolicy::Skip}, {"strict", WhitespacePolicy::Strict}});
    if (auto it = j.find("end_codes"); it != j.end()) {
        if (!it->is_array()) {
            errors.push_back("\"end_codes\" must be an array such as [63, 64, \"/\"]");
        } else {
            std::vector<EndCode> codes;
            for (const auto& e : *it) {
                auto code = parse_end_code(e);
                if (!code) {
                    errors.push_back("\"end_codes\" entries must be function codes 0-999 or \"/\" or \"=\"");
                    codes.clear();
                    break;
                }
                codes.push_back(*code);
            }
            if (!codes.empty() || it->empty()) p.end_codes = codes;
        }
    }
    number("arc_tolerance", p.arc_tolerance_units, kUnitsRange);
    number("chord_tolerance_mm", p.chord_tolerance_mm, kChordRange);
    boolean("optional_ignore", p.optional_ignore);
    boolean("rapid_single_block", p.rapid_single_block);
    choice("kerf_value", p.kerf_value, {{"width", KerfValueMeaning::Width}, {"offset", KerfValueMeaning::Offset}});
    number("kerf", p.kerf_units, kUnitsRange);
    number("default_dwell_s", p.default_dwell_s, kSecondsRange);
    number("feed_mm_min", p.feed_mm_min, kSpeedRange);
    number("rapid_mm_min", p.rapid_mm_min, kSpeedRange);
    number("pierce_time_s", p.pierce_time_s, kSecondsRange);
    number("setup_offset_x_mm", p.setup_offset_x_mm, kPositionRange);
    number("setup_offset_y_mm", p.setup_offset_y_mm, kPositionRange);
    if (auto it = j.find("table"); it != j.end()) {
        if (it->is_null()) {
            p.table.reset();
        } else if (it->is_object()) {
            TableLimits t;
            const char* keys[] = {"min_x_mm", "min_y_mm", "max_x_mm", "max_y_mm"};
            double* fields[] = {&t.min_x_mm, &t.min_y_mm, &t.max_x_mm, &t.max_y_mm};
            bool good = true;
            for (int i = 0; i < 4; ++i) {
                auto f = it->find(keys[i]);
                if (f == it->end() || !f->is_number() ||
                    !(f->get<double>() >= kPositionRange.min && f->get<double>() <= kPositionRange.max)) {
                    errors.push_back(std::string("\"table\" needs a number \"") + keys[i] + "\" between " +
                                     number_text(kPositionRange.min) + " and " + number_text(kPositionRange.max));
                    good = false;
                } else {
                    *fields[i] = f->get<double>();
                }
            }
            if (good && (t.min_x_mm >= t.max_x_mm || t.min_y_mm >= t.max_y_mm)) {
                errors.push_back("\"table\" minimum must be below its maximum");
                good = false;
            }
            if (good) p.table = t;
        } else {
            errors.push_back("\"table\" must be null or an object with min_x_mm, min_y_mm, max_x_mm, max_y_mm");
        }
    }
    static constexpr const char* kKnownKeys[] = {
        "name", "base", "dialect", "unit_mm", "whitespace", "end_codes", "arc_tolerance", "chord_tolerance_mm",
        "optional_ignore", "rapid_single_block", "kerf_value", "kerf", "default_dwell_s", "feed_mm_min",
        "rapid_mm_min", "pierce_time_s", "setup_offset_x_mm", "setup_offset_y_mm", "table"};
    for (auto it = j.begin(); it != j.end(); ++it) {
        bool known = false;
        for (const char* k : kKnownKeys) known = known || it.key() == k;
        if (!known) errors.push_back("unknown key \"" + excerpt(it.key(), kMaxKeyChars) + "\"");
    }
}

}  // namespace

std::optional<Profile> builtin_profile(std::string_view name) {
    if (name == "iso6582") return make_iso6582();
    if (name == "woyda") return make_woyda();
    return std::nullopt;
}

std::vector<std::string> builtin_profile_names() { return {"iso6582", "woyda"}; }

ProfileResult parse_profile(std::string_view json_text) {
    ProfileResult result;
    auto bad = [&](std::string message) {
        result.diagnostics.push_back(
            {Severity::Error, DiagCode::E402_BadProfile, 0, 0, std::move(message)});
    };
    const json j = json::parse(json_text.begin(), json_text.end(), nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) {
        bad("the text is not valid JSON; expected an object such as {\"base\": \"woyda\", \"feed_mm_min\": 1200}");
        return result;
    }
    if (!j.is_object()) {
        bad("expected a JSON object of settings");
        return result;
    }
    std::string base = "iso6582";
    if (auto it = j.find("base"); it != j.end()) {
        if (!it->is_string()) {
            bad("\"base\" must be the name of a built-in profile (iso6582, woyda)");
            return result;
        }
        base = it->get<std::string>();
    }
    auto profile = builtin_profile(base);
    if (!profile) {
        bad("unknown base profile \"" + base + "\"; expected iso6582 or woyda");
        return result;
    }
    if (j.find("name") == j.end()) profile->name = base + "+custom";
    std::vector<std::string> errors;
    apply_keys(j, *profile, errors);
    for (auto& e : errors) bad(std::move(e));
    if (errors.empty()) result.profile = std::move(profile);
    return result;
}

std::string profile_to_json(const Profile& p) {
    json j;
    j["name"] = p.name;
    j["dialect"] = p.dialect == Dialect::Woyda ? "woyda" : "iso6582";
    j["unit_mm"] = p.unit_mm;
    j["whitespace"] = p.whitespace == WhitespacePolicy::Strict ? "strict" : "skip";
    json ends = json::array();
    for (const auto& e : p.end_codes) {
        if (e.function >= 0) ends.push_back(e.function);
        else ends.push_back(end_code_text(e));
    }
    j["end_codes"] = ends;
    j["arc_tolerance"] = p.arc_tolerance_units;
    j["chord_tolerance_mm"] = p.chord_tolerance_mm;
    j["optional_ignore"] = p.optional_ignore;
    j["rapid_single_block"] = p.rapid_single_block;
    j["kerf_value"] = p.kerf_value == KerfValueMeaning::Offset ? "offset" : "width";
    j["kerf"] = p.kerf_units;
    j["default_dwell_s"] = p.default_dwell_s;
    j["feed_mm_min"] = p.feed_mm_min;
    j["rapid_mm_min"] = p.rapid_mm_min;
    j["pierce_time_s"] = p.pierce_time_s;
    j["setup_offset_x_mm"] = p.setup_offset_x_mm;
    j["setup_offset_y_mm"] = p.setup_offset_y_mm;
    if (p.table) {
        j["table"] = {{"min_x_mm", p.table->min_x_mm}, {"min_y_mm", p.table->min_y_mm},
                      {"max_x_mm", p.table->max_x_mm}, {"max_y_mm", p.table->max_y_mm}};
    } else {
        j["table"] = nullptr;
    }
    return j.dump(2, ' ', false, json::error_handler_t::replace);
}

bool mm_to_units(const Profile& p, Point mm, long long& x, long long& y) {
    const double ux = std::round((mm.x - p.setup_offset_x_mm) / p.unit_mm);
    const double uy = std::round((mm.y - p.setup_offset_y_mm) / p.unit_mm);
    constexpr double kLimit = 9.0e18;  // below 2^63: the cast is defined
    if (!(std::fabs(ux) < kLimit && std::fabs(uy) < kLimit)) return false;  // (NaN too)
    x = static_cast<long long>(ux);
    y = static_cast<long long>(uy);
    return units_to_mm(p, x, y) == mm;
}

}  // namespace essi
