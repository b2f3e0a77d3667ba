// Built-in profiles and the JSON form of a profile. Parsing never throws: nlohmann::json is used in its
// non-throwing form and every key is type-checked before it is read.
#include "essi/profile.hpp"
#include "essi/text.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <functional>

#include <nlohmann/json.hpp>

#include "key_position.hpp"

namespace essi {
namespace {

using nlohmann::json;
using ordered_json = nlohmann::ordered_json;  // profile_to_json keeps the keys in the order of the struct

// The built-in profiles' JSON text, compiled in from builtin/NAME.json (core/CMakeLists.txt).
struct BuiltinProfile {
    std::string_view name;
    std::string_view json;
};
constexpr BuiltinProfile kBuiltinProfiles[] = {
#include "builtin_profiles.inc"
};
// The default profile, listed first.
constexpr std::string_view kDefaultProfile = "iso6582";

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

// The bytes of a key that an error message quotes (essi::excerpt).
constexpr std::size_t kMaxKeyChars = 40;

// "M70", "G04": a letter and a number of at most 3 digits.
std::optional<EiaWord> parse_eia_word(const json& j) {
    if (!j.is_string()) return std::nullopt;
    const auto& s = j.get_ref<const std::string&>();
    if (s.size() < 2 || s.size() > 4 || s[0] < 'A' || s[0] > 'Z') return std::nullopt;
    int v = 0;
    for (std::size_t i = 1; i < s.size(); ++i) {
        if (s[i] < '0' || s[i] > '9') return std::nullopt;
        v = v * 10 + (s[i] - '0');
    }
    return EiaWord{s[0], v};
}

std::string eia_word_text(const EiaWord& w) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%c%02d", w.letter, w.number);
    return buf;
}

// The problems found in a profile's keys, each with the key it is about (its path from the top object), for the
// line and column of its E402. A KeyScope names the key that is being read.
struct KeyError {
    Message message;
    std::vector<std::string> key;
};
struct KeyErrors {
    std::vector<KeyError> list;
    std::vector<std::string> key;  // the key being read
    void push_back(Message m) { list.push_back({std::move(m), key}); }
    [[nodiscard]] std::size_t size() const { return list.size(); }
};
class KeyScope {
public:
    KeyScope(KeyErrors& errors, std::string key) : errors_(errors) { errors_.key.push_back(std::move(key)); }
    ~KeyScope() { errors_.key.pop_back(); }
    KeyScope(const KeyScope&) = delete;
    KeyScope& operator=(const KeyScope&) = delete;

private:
    KeyErrors& errors_;
};

// The "eia" object of a profile (docs/semantics.md §10); keys absent keep their values.
constexpr long long kMaxEiaCodeValue = 9999;  // the value an EIA word stands for (4 digits, as ESSI's values)

void apply_eia_keys(const json& j, EiaDialect& e, KeyErrors& errors) {
    if (!j.is_object()) {
        errors.push_back({Msg::ProfileEiaNotObject});
        return;
    }
    // A problem with the key "eia.KEY": `msg` with the key as {0}.
    auto fail = [&](const std::string& key, Msg msg) { errors.push_back({msg, {"eia." + key}}); };
    for (const char* key : {"strict_order", "one_function_per_block"}) {
        auto it = j.find(key);
        if (it == j.end()) continue;
        const KeyScope at(errors, key);
        if (!it->is_boolean()) fail(key, Msg::ProfileMustBeBoolean);
        else (std::string_view(key) == "strict_order" ? e.strict_order : e.one_function_per_block) = it->get<bool>();
    }
    if (auto it = j.find("letters"); it != j.end()) {
        const KeyScope at(errors, "letters");
        const bool ok = it->is_string() && !it->get_ref<const std::string&>().empty() &&
                        std::all_of(it->get_ref<const std::string&>().begin(), it->get_ref<const std::string&>().end(),
                                    [](char c) { return c >= 'A' && c <= 'Z'; });
        if (ok) e.letters = it->get<std::string>();
        else errors.push_back({Msg::ProfileEiaLetters});
    }
    for (const char* key : {"rapid_motion", "position_preset"}) {
        auto it = j.find(key);
        if (it == j.end()) continue;
        const KeyScope at(errors, key);
        int& out = std::string_view(key) == "rapid_motion" ? e.rapid_motion_g : e.position_preset_g;
        if (it->is_null()) {
            out = -1;
        } else if (auto w = parse_eia_word(*it); w && w->letter == 'G') {
            out = w->number;
        } else {
            fail(key, Msg::ProfileEiaGWord);
        }
    }
    if (auto it = j.find("dwell_letter"); it != j.end()) {
        const KeyScope at(errors, "dwell_letter");
        if (it->is_string() && it->get_ref<const std::string&>().size() == 1 &&
            it->get_ref<const std::string&>()[0] >= 'A' && it->get_ref<const std::string&>()[0] <= 'Z')
            e.dwell_letter = it->get_ref<const std::string&>()[0];
        else errors.push_back({Msg::ProfileEiaDwellLetter});
    }
    if (auto it = j.find("dwell_unit_s"); it != j.end()) {
        const KeyScope at(errors, "dwell_unit_s");
        if (it->is_number() && it->get<double>() >= 1e-6 && it->get<double>() <= 3600)
            e.dwell_unit_s = it->get<double>();
        else errors.push_back({Msg::ProfileEiaDwellUnit});
    }
    for (const char* key : {"inch", "mm"}) {
        auto it = j.find(key);
        if (it == j.end()) continue;
        const KeyScope at(errors, key);
        std::vector<EiaWord> words;
        bool ok = it->is_array();
        if (ok)
            for (const auto& w : *it) {
                auto word = parse_eia_word(w);
                ok = ok && word.has_value();
                if (word) words.push_back(*word);
            }
        if (ok) (std::string_view(key) == "inch" ? e.inch_words : e.mm_words) = std::move(words);
        else fail(key, Msg::ProfileEiaWords);
    }
    if (auto it = j.find("codes"); it != j.end()) {
        const KeyScope at(errors, "codes");
        std::vector<EiaCode> codes;
        bool ok = it->is_array();
        if (ok)
            for (const auto& row : *it) {
                const auto whole = [&](std::size_t k, long long below) {
                    return row[k].is_number_integer() && row[k].get<long long>() >= 0 &&
                           row[k].get<long long>() < below;
                };
                const bool pair = row.is_array() && (row.size() == 2 || row.size() == 3) && whole(1, fn::kCodeCount) &&
                                  (row.size() == 2 || whole(2, kMaxEiaCodeValue + 1));
                auto word = pair ? parse_eia_word(row[0]) : std::nullopt;
                if (!word || (word->letter != 'G' && word->letter != 'M')) {
                    ok = false;
                    break;
                }
                codes.push_back({*word, static_cast<int>(row[1].get<long long>()),
                                 row.size() == 3 ? static_cast<int>(row[2].get<long long>()) : -1});
            }
        if (ok) e.codes = std::move(codes);
        else errors.push_back({Msg::ProfileEiaCodes});
    }
    static constexpr const char* kKnownEiaKeys[] = {"letters",
                                                    "strict_order",
                                                    "one_function_per_block",
                                                    "rapid_motion",
                                                    "position_preset",
                                                    "dwell_letter",
                                                    "dwell_unit_s",
                                                    "inch",
                                                    "mm",
                                                    "codes"};
    for (auto it = j.begin(); it != j.end(); ++it) {
        const bool known = std::any_of(std::begin(kKnownEiaKeys), std::end(kKnownEiaKeys),
                                       [&](const char* k) { return it.key() == k; });
        const KeyScope at(errors, it.key());
        if (!known) errors.push_back({Msg::ProfileUnknownKey, {"eia." + excerpt(it.key(), kMaxKeyChars)}});
    }
}

ordered_json eia_to_json(const EiaDialect& e) {
    ordered_json words_inch = ordered_json::array(), words_mm = ordered_json::array(), codes = ordered_json::array();
    for (const auto& w : e.inch_words) words_inch.push_back(eia_word_text(w));
    for (const auto& w : e.mm_words) words_mm.push_back(eia_word_text(w));
    for (const auto& c : e.codes)
        codes.push_back(c.value < 0 ? ordered_json::array({eia_word_text(c.word), c.function})
                                    : ordered_json::array({eia_word_text(c.word), c.function, c.value}));
    const auto g_or_null = [](int g) { return g < 0 ? ordered_json(nullptr) : ordered_json(eia_word_text({'G', g})); };
    return {{"letters", e.letters},
            {"strict_order", e.strict_order},
            {"one_function_per_block", e.one_function_per_block},
            {"rapid_motion", g_or_null(e.rapid_motion_g)},
            {"position_preset", g_or_null(e.position_preset_g)},
            {"dwell_letter", std::string(1, e.dwell_letter)},
            {"dwell_unit_s", e.dwell_unit_s},
            {"inch", words_inch},
            {"mm", words_mm},
            {"codes", codes}};
}

// Reads the keys of `j` into `p`; each problem becomes one message in `errors`.
// The values a profile key may take: wide enough for any machine, narrow enough that no length, time or position
// computed from them overflows to infinity (a unit of 1e308 mm made "inf" reports that were "ok").
struct Range {
    double min, max;
};
constexpr Range kUnitRange{1e-9, 1000};       // mm per unit increment
constexpr Range kUnitsRange{0, 1e9};          // tolerances and kerf, in unit increments
constexpr Range kChordRange{1e-6, 1000};      // mm
constexpr Range kSecondsRange{0, 1e6};        // dwell and pierce time, s
constexpr Range kDwellUnitRange{1e-6, 3600};  // s: the unit of a dwell's value (0.001: milliseconds)
constexpr Range kSpeedRange{1e-9, 1e9};       // mm/min
constexpr Range kGapRange{0, 1e6};            // mm: closure_gap_mm
constexpr Range kPositionRange{-1e9, 1e9};    // mm: offsets and table limits
constexpr Range kRotationRange{-360, 360};    // degrees
constexpr std::size_t kMaxZeroOffsets = 100;  // entries of zero_offsets

// A point given as {"x_mm": ..., "y_mm": ...} (an offset): the error names `where` ("\"tool_offsets.marker\"", or
// a ProfileZeroOffsetEntry).
bool parse_offset(const json& v, const MessageArgs::Arg& where, Point& out, KeyErrors& errors) {
    const auto coordinate = [&](const char* key, double& to) {
        const KeyScope at(errors, key);
        const auto f = v.find(key);
        if (f == v.end() || !f->is_number() ||
            !(f->get<double>() >= kPositionRange.min && f->get<double>() <= kPositionRange.max)) {
            errors.push_back({Msg::ProfileNeedsNumber,
                              {where, key, number_text(kPositionRange.min), number_text(kPositionRange.max)}});
            return false;
        }
        to = f->get<double>();
        return true;
    };
    if (!v.is_object()) {
        errors.push_back({Msg::ProfileOffsetNotObject, {where}});
        return false;
    }
    for (auto it = v.begin(); it != v.end(); ++it) {
        if (it.key() != "x_mm" && it.key() != "y_mm") {
            const KeyScope at(errors, it.key());
            errors.push_back({Msg::ProfileOffsetUnknownKey, {where, excerpt(it.key(), kMaxKeyChars)}});
            return false;
        }
    }
    Point p;
    if (!coordinate("x_mm", p.x) || !coordinate("y_mm", p.y)) return false;
    out = p;
    return true;
}

// zero_offsets, zero_offset, plate_rotation_deg, tool_offsets and the older setup_offset_x_mm/_y_mm (the
// default entry), docs/semantics.md §12.
void apply_placement_keys(const json& j, Profile& p, KeyErrors& errors) {
    for (const char* axis : {"setup_offset_x_mm", "setup_offset_y_mm"}) {
        const auto it = j.find(axis);
        if (it == j.end()) continue;
        const KeyScope at(errors, axis);
        if (!it->is_number() || !(it->get<double>() >= kPositionRange.min && it->get<double>() <= kPositionRange.max)) {
            errors.push_back(
                {Msg::ProfileSetupOffset, {axis, number_text(kPositionRange.min), number_text(kPositionRange.max)}});
            continue;
        }
        Point& entry = p.zero_offsets[Profile::kDefaultZeroOffset];
        (axis[13] == 'x' ? entry.x : entry.y) = it->get<double>();
    }
    if (const auto it = j.find("zero_offsets"); it != j.end()) {
        const KeyScope at(errors, "zero_offsets");
        if (!it->is_object()) {
            errors.push_back({Msg::ProfileZeroOffsetsNotObject});
        } else {
            for (auto e = it->begin(); e != it->end(); ++e) {
                const KeyScope entry(errors, e.key());
                if (e.key().empty() || e.key().size() > kMaxKeyChars) {
                    errors.push_back({Msg::ProfileZeroOffsetName, {kMaxKeyChars}});
                    continue;
                }
                Point offset;
                if (parse_offset(e.value(), Message{Msg::ProfileZeroOffsetEntry, {e.key()}}, offset, errors))
                    p.zero_offsets[e.key()] = offset;
            }
            if (p.zero_offsets.size() > kMaxZeroOffsets)
                errors.push_back({Msg::ProfileZeroOffsetsTooMany, {kMaxZeroOffsets}});
        }
    }
    {
        const KeyScope zero_offset(errors, "zero_offset");
        if (const auto it = j.find("zero_offset"); it != j.end()) {
            if (!it->is_string()) errors.push_back({Msg::ProfileZeroOffsetNotName});
            else p.zero_offset = it->get<std::string>();
        }
        if (p.zero_offsets.find(p.zero_offset) == p.zero_offsets.end()) {
            std::string names;
            int listed = 0;
            for (const auto& [name, offset] : p.zero_offsets)
                if (listed++ < 5) names += (names.empty() ? "\"" : ", \"") + name + "\"";
            if (listed > 5) names += " ...";
            errors.push_back({Msg::ProfileZeroOffsetMissing, {excerpt(p.zero_offset, kMaxKeyChars), names}});
        }
    }
    if (const auto it = j.find("plate_rotation_deg"); it != j.end()) {
        const KeyScope at(errors, "plate_rotation_deg");
        if (!it->is_number() || !(it->get<double>() >= kRotationRange.min && it->get<double>() <= kRotationRange.max))
            errors.push_back({Msg::ProfilePlateRotation});
        else p.plate_rotation_deg = it->get<double>();
    }
    if (const auto it = j.find("tool_offsets"); it != j.end()) {
        const KeyScope at(errors, "tool_offsets");
        if (!it->is_object()) {
            errors.push_back({Msg::ProfileToolOffsetsNotObject});
            return;
        }
        for (auto e = it->begin(); e != it->end(); ++e) {
            const KeyScope entry(errors, e.key());
            if (e.key() == "marker") parse_offset(e.value(), "\"tool_offsets.marker\"", p.marker_offset, errors);
            else if (e.key() == "powder_marker")
                parse_offset(e.value(), "\"tool_offsets.powder_marker\"", p.powder_marker_offset, errors);
            else errors.push_back({Msg::ProfileToolOffsetsUnknownKey, {excerpt(e.key(), kMaxKeyChars)}});
        }
    }
}

// Machine time, the plate and the costs (docs/semantics.md §9, "Machine time" and "Cost").
constexpr Range kAccelRange{1e-3, 1e6};          // mm/s²
constexpr Range kDeviationRange{0, 1000};        // mm
constexpr Range kPlateRange{1e-6, 1e6};          // mm: a plate's size and thickness
constexpr Range kDensityRange{1e-6, 1e6};        // kg/m³
constexpr Range kPriceRange{0, 1e9};             // a price in the profile's currency
constexpr Range kElectrodePiercesRange{1, 1e9};  // pierces an electrode lasts
constexpr Range kElectrodeArcRange{1e-6, 1e9};   // s of arc an electrode lasts
constexpr std::size_t kMaxCurrencyBytes = 16;

// One number of an object of numbers: its key, where it goes, its range; `given` (when not null) says whether
// the object has it, else it must.
struct NumberField {
    const char* key;
    double* out;
    Range range;
    bool* given = nullptr;
};

// The value of `key`: null (`out` reset) or an object read by `read` (into a value that becomes `out` when
// it has no error). `example` shows the object in the message when the value is neither.
template <class T, class Read>
void null_or_object(const json& j, const char* key, std::optional<T>& out, const char* example, KeyErrors& errors,
                    Read read) {
    const auto it = j.find(key);
    if (it == j.end()) return;
    const KeyScope at(errors, key);
    if (it->is_null()) {
        out.reset();
        return;
    }
    if (!it->is_object()) {
        errors.push_back({Msg::ProfileNullOrObject, {key, example}});
        return;
    }
    T value{};
    const std::size_t before = errors.size();
    read(*it, value);
    if (errors.size() == before) out = std::move(value);
}

// A text of an object: 1 to `max_bytes` bytes of printable UTF-8.
struct TextField {
    const char* key;
    std::string* out;
    std::size_t max_bytes;
    bool required = true;
};

// The numbers of `object` (the value of the key `name`) into `fields`, its texts into `texts`; any other key is
// unknown.
void read_fields(const json& object, const char* name, std::initializer_list<NumberField> fields,
                 std::initializer_list<TextField> texts, KeyErrors& errors) {
    const std::string quoted = std::string("\"") + name + "\"";
    for (const NumberField& f : fields) {
        const KeyScope at(errors, f.key);
        const auto v = object.find(f.key);
        if (v == object.end() && f.given != nullptr) continue;
        const std::string key = std::string(name) + "." + f.key;
        if (v == object.end()) {
            errors.push_back(
                {Msg::ProfileNeedsNumber, {quoted, f.key, number_text(f.range.min), number_text(f.range.max)}});
            continue;
        }
        if (!v->is_number()) {
            errors.push_back({Msg::ProfileMustBeNumber, {key}});
            continue;
        }
        if (!(v->get<double>() >= f.range.min && v->get<double>() <= f.range.max)) {
            errors.push_back(
                {Msg::ProfileOutOfRange,
                 {key, number_text(f.range.min), number_text(f.range.max), number_text(v->get<double>())}});
            continue;
        }
        *f.out = v->get<double>();
        if (f.given != nullptr) *f.given = true;
    }
    for (const TextField& f : texts) {
        const KeyScope at(errors, f.key);
        const auto v = object.find(f.key);
        if (v == object.end() && !f.required) continue;
        const std::string* t = v != object.end() && v->is_string() ? &v->get_ref<const std::string&>() : nullptr;
        if (t != nullptr && !t->empty() && t->size() <= f.max_bytes && display_text(*t) == *t) *f.out = *t;
        else errors.push_back({Msg::ProfileText, {std::string(name) + "." + f.key, f.max_bytes}});
    }
    for (auto it = object.begin(); it != object.end(); ++it) {
        const auto named = [&](const char* k) { return it.key() == k; };
        const bool known =
            std::any_of(fields.begin(), fields.end(), [&](const NumberField& f) { return named(f.key); }) ||
            std::any_of(texts.begin(), texts.end(), [&](const TextField& t) { return named(t.key); });
        const KeyScope at(errors, it.key());
        if (!known)
            errors.push_back({Msg::ProfileUnknownKey, {std::string(name) + "." + excerpt(it.key(), kMaxKeyChars)}});
    }
}

// `deviation` reads junction_deviation_mm (a number like the others), after accel_mm_s2.
template <class ReadDeviation>
void apply_cost_keys(const json& j, Profile& p, KeyErrors& errors, ReadDeviation deviation) {
    if (const auto it = j.find("accel_mm_s2"); it != j.end()) {
        const KeyScope at(errors, "accel_mm_s2");
        const double v = it->is_number() ? it->get<double>() : 0;
        if (it->is_null()) {
            p.accel_mm_s2.reset();
        } else if (!it->is_number()) {
            errors.push_back({Msg::ProfileNullOrNumber,
                              {"accel_mm_s2", number_text(kAccelRange.min), number_text(kAccelRange.max)}});
        } else if (!(v >= kAccelRange.min && v <= kAccelRange.max)) {
            errors.push_back(
                {Msg::ProfileOutOfRange,
                 {"accel_mm_s2", number_text(kAccelRange.min), number_text(kAccelRange.max), number_text(v)}});
        } else {
            p.accel_mm_s2 = v;
        }
    }
    deviation();
    null_or_object(j, "material", p.material, R"({"name": "S355", "thickness_mm": 15, "density_kg_m3": 7850})", errors,
                   [&](const json& v, Material& m) {
                       read_fields(v, "material",
                                   {{"thickness_mm", &m.thickness_mm, kPlateRange},
                                    {"density_kg_m3", &m.density_kg_m3, kDensityRange}},
                                   {{"name", &m.name, kMaxProfileNameBytes}}, errors);
                   });
    null_or_object(j, "plate_mm", p.plate, R"({"x": 3000, "y": 1500})", errors, [&](const json& v, PlateSize& s) {
        read_fields(v, "plate_mm", {{"x", &s.x_mm, kPlateRange}, {"y", &s.y_mm, kPlateRange}}, {}, errors);
    });
    null_or_object(j, "costs", p.costs, R"({"currency": "EUR", "machine_per_hour": 90, "per_pierce": 0.05})", errors,
                   [&](const json& v, Costs& c) {
                       bool given = false;  // (each price is optional: 0 when not given)
                       read_fields(v, "costs",
                                   {{"machine_per_hour", &c.machine_per_hour, kPriceRange, &given},
                                    {"per_pierce", &c.per_pierce, kPriceRange, &given},
                                    {"per_m_cut", &c.per_m_cut, kPriceRange, &given},
                                    {"material_per_kg", &c.material_per_kg, kPriceRange, &given}},
                                   {{"currency", &c.currency, kMaxCurrencyBytes, false}}, errors);
                   });
    null_or_object(j, "consumables", p.consumables, R"({"electrode_pierces": 800, "electrode_arc_s": 7200})", errors,
                   [&](const json& v, ElectrodeLife& life) {
                       double pierces = 0, arc_s = 0;
                       bool has_pierces = false, has_arc = false;
                       read_fields(v, "consumables",
                                   {{"electrode_pierces", &pierces, kElectrodePiercesRange, &has_pierces},
                                    {"electrode_arc_s", &arc_s, kElectrodeArcRange, &has_arc}},
                                   {}, errors);
                       if (has_pierces) life.pierces = pierces;
                       if (has_arc) life.arc_s = arc_s;
                   });
}

void apply_keys(const json& j, Profile& p, KeyErrors& errors) {
    auto number = [&](const char* key, double& out, Range range) {
        auto it = j.find(key);
        if (it == j.end()) return;
        const KeyScope at(errors, key);
        if (!it->is_number()) {
            errors.push_back({Msg::ProfileMustBeNumber, {key}});
            return;
        }
        const double v = it->get<double>();
        if (!(v >= range.min && v <= range.max)) {  // (NaN and infinities too)
            errors.push_back(
                {Msg::ProfileOutOfRange, {key, number_text(range.min), number_text(range.max), number_text(v)}});
            return;
        }
        out = v;
    };
    auto boolean = [&](const char* key, bool& out) {
        auto it = j.find(key);
        if (it == j.end()) return;
        const KeyScope at(errors, key);
        if (!it->is_boolean()) {
            errors.push_back({Msg::ProfileMustBeBoolean, {key}});
            return;
        }
        out = it->get<bool>();
    };
    auto choice = [&](const char* key, auto& out,
                      std::initializer_list<std::pair<const char*, std::decay_t<decltype(out)>>> options) {
        auto it = j.find(key);
        if (it == j.end()) return;
        const KeyScope at(errors, key);
        std::string allowed;
        for (const auto& [name, value] : options) {
            if (it->is_string() && it->get_ref<const std::string&>() == name) {
                out = value;
                return;
            }
            allowed += allowed.empty() ? "" : ", ";
            allowed += std::string("\"") + name + "\"";
        }
        errors.push_back({Msg::ProfileMustBeOneOf, {key, allowed}});
    };

    if (auto it = j.find("name"); it != j.end()) {
        const KeyScope at(errors, "name");
        if (!it->is_string()) errors.push_back({Msg::ProfileNameNotString});
        else if (const std::string& name = it->get_ref<const std::string&>(); is_valid_profile_name(name))
            p.name = name;
        else errors.push_back({Msg::ProfileNameText, {kMaxProfileNameBytes, excerpt(name, kMaxKeyChars)}});
    }
    choice("dialect", p.dialect,
           {{"iso6582", Dialect::Iso6582}, {"woyda", Dialect::Woyda}, {"hypertherm", Dialect::Hypertherm}});
    number("unit_mm", p.unit_mm, kUnitRange);
    choice("whitespace", p.whitespace, {{"skip", WhitespacePolicy::Skip}, {"strict", WhitespacePolicy::Strict}});
    if (auto it = j.find("end_codes"); it != j.end()) {
        const KeyScope at(errors, "end_codes");
        if (!it->is_array()) {
            errors.push_back({Msg::ProfileEndCodesNotArray});
        } else {
            std::vector<EndCode> codes;
            for (const auto& e : *it) {
                auto code = parse_end_code(e);
                if (!code) {
                    errors.push_back({Msg::ProfileEndCodesEntry});
                    codes.clear();
                    break;
                }
                codes.push_back(*code);
            }
            if (!codes.empty() || it->empty()) p.end_codes = codes;
        }
    }
    boolean("end_at_data_end", p.end_at_data_end);
    if (auto it = j.find("torch_direction"); it != j.end()) {
        const KeyScope at(errors, "torch_direction");
        const std::string d = it->is_string() ? it->get<std::string>() : std::string();
        if (d == "+x") p.torch_direction = {1, 0};
        else if (d == "-x") p.torch_direction = {-1, 0};
        else if (d == "+y") p.torch_direction = {0, 1};
        else if (d == "-y") p.torch_direction = {0, -1};
        else errors.push_back({Msg::ProfileMustBeOneOf, {"torch_direction", "\"+x\", \"-x\", \"+y\", \"-y\""}});
    }
    number("arc_tolerance", p.arc_tolerance_units, kUnitsRange);
    number("chord_tolerance_mm", p.chord_tolerance_mm, kChordRange);
    boolean("optional_ignore", p.optional_ignore);
    boolean("rapid_single_block", p.rapid_single_block);
    choice("kerf_value", p.kerf_value, {{"width", KerfValueMeaning::Width}, {"offset", KerfValueMeaning::Offset}});
    number("kerf", p.kerf_units, kUnitsRange);
    number("default_dwell_s", p.default_dwell_s, kSecondsRange);
    number("dwell_unit_s", p.dwell_unit_s, kDwellUnitRange);
    number("feed_mm_min", p.feed_mm_min, kSpeedRange);
    number("rapid_mm_min", p.rapid_mm_min, kSpeedRange);
    number("pierce_time_s", p.pierce_time_s, kSecondsRange);
    apply_cost_keys(j, p, errors, [&] { number("junction_deviation_mm", p.junction_deviation_mm, kDeviationRange); });
    apply_placement_keys(j, p, errors);
    number("closure_gap_mm", p.closure_gap_mm, kGapRange);
    number("max_dwell_s", p.max_dwell_s, kSecondsRange);
    boolean("lead_in_required", p.lead_in_required);
    if (auto it = j.find("max_per_code"); it != j.end()) {
        const KeyScope at(errors, "max_per_code");
        if (it->is_number_unsigned() && it->get<std::uint64_t>() <= kMaxPerCodeLimit)
            p.max_per_code = static_cast<std::size_t>(it->get<std::uint64_t>());
        else errors.push_back({Msg::ProfileWholeNumber, {"max_per_code", kMaxPerCodeLimit}});
    }
    if (auto it = j.find("feed_range_mm_min"); it != j.end()) {
        const KeyScope at(errors, "feed_range_mm_min");
        const bool pair = it->is_array() && it->size() == 2 && (*it)[0].is_number() && (*it)[1].is_number();
        const double lo = pair ? (*it)[0].get<double>() : 0, hi = pair ? (*it)[1].get<double>() : 0;
        if (pair && lo >= 0 && lo <= hi && hi <= kSpeedRange.max) {
            p.feed_min_mm_min = lo;
            p.feed_max_mm_min = hi;
        } else {
            errors.push_back({Msg::ProfileFeedRange, {number_text(kSpeedRange.max)}});
        }
    }
    if (auto it = j.find("table"); it != j.end()) {
        const KeyScope at(errors, "table");
        if (it->is_null()) {
            p.table.reset();
        } else if (it->is_object()) {
            TableLimits t;
            const char* keys[] = {"min_x_mm", "min_y_mm", "max_x_mm", "max_y_mm"};
            double* fields[] = {&t.min_x_mm, &t.min_y_mm, &t.max_x_mm, &t.max_y_mm};
            bool good = true;
            for (int i = 0; i < 4; ++i) {
                const KeyScope limit(errors, keys[i]);
                auto f = it->find(keys[i]);
                if (f == it->end() || !f->is_number() ||
                    !(f->get<double>() >= kPositionRange.min && f->get<double>() <= kPositionRange.max)) {
                    errors.push_back(
                        {Msg::ProfileNeedsNumber,
                         {"\"table\"", keys[i], number_text(kPositionRange.min), number_text(kPositionRange.max)}});
                    good = false;
                } else {
                    *fields[i] = f->get<double>();
                }
            }
            if (good && (t.min_x_mm >= t.max_x_mm || t.min_y_mm >= t.max_y_mm)) {
                errors.push_back({Msg::ProfileTableOrder});
                good = false;
            }
            if (good) p.table = t;
        } else {
            errors.push_back({Msg::ProfileTableNotObject});
        }
    }
    if (auto it = j.find("eia"); it != j.end()) {
        const KeyScope at(errors, "eia");
        apply_eia_keys(*it, p.eia, errors);
    }
    static constexpr const char* kKnownKeys[] = {"name",
                                                 "base",
                                                 "dialect",
                                                 "unit_mm",
                                                 "whitespace",
                                                 "end_codes",
                                                 "end_at_data_end",
                                                 "arc_tolerance",
                                                 "chord_tolerance_mm",
                                                 "torch_direction",
                                                 "optional_ignore",
                                                 "rapid_single_block",
                                                 "kerf_value",
                                                 "kerf",
                                                 "default_dwell_s",
                                                 "dwell_unit_s",
                                                 "feed_mm_min",
                                                 "rapid_mm_min",
                                                 "pierce_time_s",
                                                 "setup_offset_x_mm",
                                                 "setup_offset_y_mm",
                                                 "zero_offsets",
                                                 "zero_offset",
                                                 "plate_rotation_deg",
                                                 "tool_offsets",
                                                 "table",
                                                 "eia",
                                                 "closure_gap_mm",
                                                 "feed_range_mm_min",
                                                 "max_dwell_s",
                                                 "lead_in_required",
                                                 "max_per_code",
                                                 "accel_mm_s2",
                                                 "junction_deviation_mm",
                                                 "material",
                                                 "plate_mm",
                                                 "costs",
                                                 "consumables"};
    for (auto it = j.begin(); it != j.end(); ++it) {
        bool known = false;
        for (const char* k : kKnownKeys) known = known || it.key() == k;
        const KeyScope at(errors, it.key());
        if (!known) errors.push_back({Msg::ProfileUnknownKey, {excerpt(it.key(), kMaxKeyChars)}});
    }
}

}  // namespace

MessageArgs::Arg end_codes_arg(const Profile& p) {
    if (p.end_codes.empty()) return Msg::EndOfData;
    std::vector<std::string> items;
    for (const EndCode& e : p.end_codes) items.push_back(end_code_text(e));
    return MessageArgs::Arg::alternatives(items);
}

std::string_view builtin_profile_json(std::string_view name) {
    for (const BuiltinProfile& b : kBuiltinProfiles)
        if (b.name == name) return b.json;
    return {};
}

std::vector<std::string> builtin_profile_names() {
    std::vector<std::string> names{std::string(kDefaultProfile)};
    for (const BuiltinProfile& b : kBuiltinProfiles)
        if (b.name != kDefaultProfile) names.emplace_back(b.name);
    return names;
}

namespace {

std::string builtin_names_text() {
    std::string s;
    for (const auto& n : builtin_profile_names()) s += (s.empty() ? "" : ", ") + n;
    return s;
}

// What a message quotes of the JSON parser's reason (escaped first: its quote of the text may hold any bytes).
constexpr std::size_t kMaxJsonReasonBytes = 100;

// Where and why the JSON parser stopped: line and column (1-based, bytes) of its last byte read (`byte`, 1-based;
// 0 when the parser does not say: then where the quoted token of its reason first is) and its reason ("number
// overflow parsing '1e999'", "unexpected end of input ...").
Message json_error_message(std::string_view text, const json::exception& e, std::size_t byte) {
    if (byte == 0) {
        const std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        if (open != std::string::npos && close > open + 1) {
            const std::size_t found = text.find(what.substr(open + 1, close - open - 1));
            if (found != std::string_view::npos) byte = found + 1;
        }
    }
    const std::size_t at = std::min<std::size_t>(byte == 0 ? 0 : byte - 1, text.size());
    const profile_detail::TextPosition where = profile_detail::position_of(text, at);
    std::string reason = e.what();
    // ("[json.exception.parse_error.101] parse error at line 1, column 2: REASON", "[json.exception...406] REASON")
    if (const std::size_t c = reason.find("column "); c != std::string::npos) {
        if (const std::size_t colon = reason.find(": ", c); colon != std::string::npos) reason.erase(0, colon + 2);
    } else if (reason.rfind("[json.", 0) == 0) {
        if (const std::size_t end = reason.find("] "); end != std::string::npos) reason.erase(0, end + 2);
    }
    if (const std::size_t last = reason.find("; last read: "); last != std::string::npos) reason.erase(last);
    return {Msg::ProfileNotJsonAt, {where.line, where.column, excerpt(display_text(reason), kMaxJsonReasonBytes)}};
}

// Parses profile JSON onto its base: the built-in named by "base", else `no_base` (the default profile for a
// user's file; Profile{} for the default profile's own file, which sets every key).
ProfileResult parse_onto(std::string_view json_text, const std::function<std::optional<Profile>()>& no_base) {
    ProfileResult result;
    // An E402, at the key it is about when the text names it.
    auto bad = [&](Message m, const std::vector<std::string>& key = {}) {
        std::size_t line = 0, column = 0;
        if (const auto at = profile_detail::key_offset(json_text, key); at && !key.empty()) {
            const profile_detail::TextPosition p = profile_detail::position_of(json_text, *at);
            line = p.line;
            column = p.column;
        }
        result.diagnostics.push_back(
            make_diagnostic(Severity::Error, DiagCode::E402_BadProfile, line, column, m.msg, std::move(m.args)));
    };
    json j;
    try {
        j = json::parse(json_text.begin(), json_text.end());
    } catch (const json::parse_error& e) {
        bad(json_error_message(json_text, e, e.byte));
        return result;
    } catch (const json::exception& e) {  // (a number beyond a double: out_of_range)
        bad(json_error_message(json_text, e, 0));
        return result;
    }
    if (!j.is_object()) {
        bad({Msg::ProfileNotObject});
        return result;
    }
    std::string base(kDefaultProfile);
    std::optional<Profile> profile;
    if (auto it = j.find("base"); it != j.end()) {
        if (!it->is_string()) {
            bad({Msg::ProfileBaseNotString, {builtin_names_text()}}, {"base"});
            return result;
        }
        base = it->get<std::string>();
        profile = builtin_profile(base);
        if (!profile) {
            bad({Msg::ProfileUnknownBase, {excerpt(base, kMaxKeyChars), builtin_names_text()}}, {"base"});
            return result;
        }
    } else {
        profile = no_base();
    }
    if (j.find("name") == j.end()) profile->name = base + "+custom";
    KeyErrors errors;
    apply_keys(j, *profile, errors);
    for (KeyError& e : errors.list) bad(std::move(e.message), e.key);
    if (errors.list.empty()) result.profile = std::move(profile);
    return result;
}

}  // namespace

std::optional<Profile> builtin_profile(std::string_view name) {
    const std::string_view text = builtin_profile_json(name);
    if (text.empty()) return std::nullopt;
    // (every built-in parses: profile_test checks each)
    return parse_onto(text, [] { return std::optional<Profile>(Profile{}); }).profile;
}

ProfileResult parse_profile(std::string_view json_text) {
    return parse_onto(json_text, [] { return builtin_profile(kDefaultProfile); });
}

bool is_valid_profile_name(std::string_view name) {
    return !name.empty() && name.size() <= kMaxProfileNameBytes && display_text(name) == name;
}

std::string profile_to_json(const Profile& p) {
    ordered_json j;
    j["name"] = p.name;
    j["dialect"] = p.dialect == Dialect::Woyda ? "woyda" : p.dialect == Dialect::Hypertherm ? "hypertherm" : "iso6582";
    j["unit_mm"] = p.unit_mm;
    j["whitespace"] = p.whitespace == WhitespacePolicy::Strict ? "strict" : "skip";
    ordered_json ends = ordered_json::array();
    for (const auto& e : p.end_codes) {
        if (e.function >= 0) ends.push_back(e.function);
        else ends.push_back(end_code_text(e));
    }
    j["end_codes"] = ends;
    j["end_at_data_end"] = p.end_at_data_end;
    j["arc_tolerance"] = p.arc_tolerance_units;
    j["chord_tolerance_mm"] = p.chord_tolerance_mm;
    j["optional_ignore"] = p.optional_ignore;
    j["rapid_single_block"] = p.rapid_single_block;
    j["kerf_value"] = p.kerf_value == KerfValueMeaning::Offset ? "offset" : "width";
    j["kerf"] = p.kerf_units;
    j["default_dwell_s"] = p.default_dwell_s;
    j["dwell_unit_s"] = p.dwell_unit_s;
    j["feed_mm_min"] = p.feed_mm_min;
    j["rapid_mm_min"] = p.rapid_mm_min;
    j["pierce_time_s"] = p.pierce_time_s;
    j["accel_mm_s2"] = p.accel_mm_s2 ? ordered_json(*p.accel_mm_s2) : ordered_json(nullptr);
    j["junction_deviation_mm"] = p.junction_deviation_mm;
    j["torch_direction"] = p.torch_direction.x > 0   ? "+x"
                           : p.torch_direction.x < 0 ? "-x"
                           : p.torch_direction.y < 0 ? "-y"
                                                     : "+y";
    const auto offset = [](Point o) { return ordered_json{{"x_mm", o.x}, {"y_mm", o.y}}; };
    ordered_json zeros = ordered_json::object();
    for (const auto& [name, o] : p.zero_offsets) zeros[name] = offset(o);
    j["zero_offsets"] = zeros;
    j["zero_offset"] = p.zero_offset;
    j["plate_rotation_deg"] = p.plate_rotation_deg;
    j["tool_offsets"] = {{"marker", offset(p.marker_offset)}, {"powder_marker", offset(p.powder_marker_offset)}};
    if (p.table) {
        j["table"] = {{"min_x_mm", p.table->min_x_mm},
                      {"min_y_mm", p.table->min_y_mm},
                      {"max_x_mm", p.table->max_x_mm},
                      {"max_y_mm", p.table->max_y_mm}};
    } else {
        j["table"] = nullptr;
    }
    j["closure_gap_mm"] = p.closure_gap_mm;
    j["feed_range_mm_min"] = {p.feed_min_mm_min, p.feed_max_mm_min};
    j["max_dwell_s"] = p.max_dwell_s;
    j["lead_in_required"] = p.lead_in_required;
    j["max_per_code"] = p.max_per_code;
    j["material"] = p.material ? ordered_json{{"name", p.material->name},
                                              {"thickness_mm", p.material->thickness_mm},
                                              {"density_kg_m3", p.material->density_kg_m3}}
                               : ordered_json(nullptr);
    j["plate_mm"] = p.plate ? ordered_json{{"x", p.plate->x_mm}, {"y", p.plate->y_mm}} : ordered_json(nullptr);
    if (p.costs) {
        j["costs"] = {{"currency", p.costs->currency},
                      {"machine_per_hour", p.costs->machine_per_hour},
                      {"per_pierce", p.costs->per_pierce},
                      {"per_m_cut", p.costs->per_m_cut},
                      {"material_per_kg", p.costs->material_per_kg}};
        if (p.costs->currency.empty()) j["costs"].erase("currency");
    } else {
        j["costs"] = nullptr;
    }
    if (p.consumables) {
        j["consumables"] = ordered_json::object();
        if (p.consumables->pierces) j["consumables"]["electrode_pierces"] = *p.consumables->pierces;
        if (p.consumables->arc_s) j["consumables"]["electrode_arc_s"] = *p.consumables->arc_s;
    } else {
        j["consumables"] = nullptr;
    }
    j["eia"] = eia_to_json(p.eia);
    return j.dump(2, ' ', false, ordered_json::error_handler_t::replace);
}

bool mm_to_units(const Profile& p, Point mm, long long& x, long long& y) {
    // (nearbyint: one instruction in WebAssembly, where round is a call; they differ only at halves, which are
    // never on the grid, so the answer is the same)
    const double ux = std::nearbyint(mm.x / p.unit_mm);
    const double uy = std::nearbyint(mm.y / p.unit_mm);
    constexpr double kLimit = 9.0e18;                                       // below 2^63: the cast is defined
    if (!(std::fabs(ux) < kLimit && std::fabs(uy) < kLimit)) return false;  // (NaN too)
    x = static_cast<long long>(ux);
    y = static_cast<long long>(uy);
    return units_to_mm(p, x, y) == mm;
}

}  // namespace essi
