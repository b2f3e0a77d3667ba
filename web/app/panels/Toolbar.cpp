// The toolbar: Open, Paste, Share, Export, Fit, Measure, Help, the View (panels) menu, Compare, the profile, the
// orientation, the coordinates, the language, the tape's name and verdict, the message. Items that do not fit in
// the window's width (German is longer; a 1024 px screen) go, in their order, into the overflow menu (») at the end
// of the bar, where they work as in the bar (docs/viewer.md, "Languages"); the verdict is always in the bar.

#include <algorithm>
#include <array>
#include <initializer_list>
#include <vector>

#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "app/Language.hpp"
#include "app/PageMirror.hpp"
#include "essi/dialect.hpp"
#include "essi/profile.hpp"
#include "render/UiFonts.hpp"

namespace essi::viewer::panels {

namespace {

enum class Item {
    Open,
    Paste,
    Share,
    Export,
    Fit,
    Measure,
    Help,
    Panels,
    Compare,
    Profile,
    Orientation,
    Coordinates,
    Language,
    Verdict
};
struct ItemInfo {
    Item item;
    const char* id;  // in state().toolbar
};
constexpr ItemInfo kItems[] = {
    {Item::Open, "open"},
    {Item::Paste, "paste"},
    {Item::Share, "share"},
    {Item::Export, "export"},
    {Item::Fit, "fit"},
    {Item::Measure, "measure"},
    {Item::Help, "help"},
    {Item::Panels, "panels"},
    {Item::Compare, "compare"},
    {Item::Profile, "profile"},
    {Item::Orientation, "orientation"},
    {Item::Coordinates, "coordinates"},
    {Item::Language, "language"},
    {Item::Verdict, "verdict"},
};
constexpr const char* kMoreLabel = "\xC2\xBB###more";  // » (no words: its tooltip says what it is)

constexpr std::array<Msg, 4> kOrientations = {Msg::UiOrientIso, Msg::UiOrientWoyda, Msg::UiOrientLeftDown,
                                              Msg::UiOrientDownRight};
constexpr std::array<Msg, 2> kCoordinates = {Msg::UiProgramCoordinates, Msg::UiMachineCoordinates};

// Widths as ImGui will lay the widgets out (the label's text before "###").
float text_width(const char* s) { return ImGui::CalcTextSize(s, nullptr, true).x; }
float button_width(const std::string& label) {
    return text_width(label.c_str()) + ImGui::GetStyle().FramePadding.x * 2;
}
float checkbox_width(const std::string& label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + text_width(label.c_str());
}
// A combo as wide as its longest choice and its arrow.
float combo_width(std::initializer_list<std::string_view> choices) {
    float w = 0;
    for (const std::string_view c : choices) w = std::max(w, ImGui::CalcTextSize(c.data(), c.data() + c.size()).x);
    return w + ImGui::GetStyle().FramePadding.x * 2 + ImGui::GetFrameHeight();
}

// An item's tooltip. A tooltip follows the mouse: in the bar it would cover the items beside the one hovered, so
// there it opens under the bar (as far along as the mouse is across the window, so it stays inside it).
void tooltip(Msg tip) {
    if (!ImGui::IsItemHovered()) return;
    const ImGuiIO& io = ImGui::GetIO();
    if (io.MousePos.y < kToolbarHeight && io.DisplaySize.x > 0)
        ImGui::SetNextWindowPos(ImVec2(io.MousePos.x, kToolbarHeight + 2), ImGuiCond_Always,
                                ImVec2(std::clamp(io.MousePos.x / io.DisplaySize.x, 0.f, 1.f), 0.f));
    wrapped_tooltip(tr(tip));
}

using Parts = Panels::Parts;

std::string profile_shown(const Session& session) {
    // "auto: woyda" while the tape's evidence chose the dialect
    const Document* doc = session.document();
    return session.profile_name() == kAutoProfile && doc ? "auto: " + doc->profile.name : session.profile_name();
}

std::vector<std::string> profile_choices(const Session& session) {
    std::vector<std::string> names{std::string(kAutoProfile)};
    for (const std::string& n : builtin_profile_names()) names.push_back(n);
    if (session.dropped_profile())
        names.push_back(session.dropped_profile()->name);  // (a profile file dropped on the page)
    return names;
}

Msg compare_label(const CompareMode& compare) {
    return compare.result() ? Msg::UiEndCompare : compare.pending() ? Msg::UiCompareDropB : Msg::UiCompare;
}

float item_width(const Parts& p, Item item) {
    switch (item) {
        case Item::Open: return button_width(tr(Msg::UiOpen));
        case Item::Paste: return button_width(tr(Msg::UiPaste));
        case Item::Share: return button_width(tr(Msg::UiShareLink));
        case Item::Export: return button_width(tr(Msg::UiExport));
        case Item::Fit: return button_width(tr(Msg::UiFit));
        case Item::Measure: return checkbox_width(tr(Msg::UiMeasure));
        case Item::Help: return button_width(tr(Msg::UiHelp));
        case Item::Panels: return button_width(tr(Msg::UiPanels));
        case Item::Compare: return button_width(tr(compare_label(p.compare)));
        case Item::Profile: {
            float w = combo_width({profile_shown(p.session)});
            for (const std::string& n : profile_choices(p.session)) w = std::max(w, combo_width({n}));
            return w;
        }
        case Item::Orientation:
            return combo_width(
                {tr(kOrientations[0]), tr(kOrientations[1]), tr(kOrientations[2]), tr(kOrientations[3])});
        case Item::Coordinates: return combo_width({tr(kCoordinates[0]), tr(kCoordinates[1])});
        case Item::Language:
            return combo_width({lang_native_name(Lang::En), lang_native_name(Lang::De), lang_native_name(Lang::Zh)});
        case Item::Verdict: {
            const Document* doc = p.session.document();
            if (!doc) return 0;
            return text_width(doc->name.c_str()) + ImGui::GetStyle().ItemSpacing.x +
                   text_width(verdict_text(*doc).c_str());
        }
    }
    return 0;
}

// Downloads: the tape as ESSI, EIA or G-code (essi convert), its drawing as DXF, its report, the view.
void export_menu(Exports& exports) {
    if (!ImGui::BeginPopup("export")) return;
    // (format names are no words: they stay as they are)
    const std::pair<std::string, const char*> formats[] = {{"ESSI (.esi)", "essi"},
                                                           {"EIA, RS-274 (.eia)", "eia"},
                                                           {tr(Msg::UiExportGcode), "gcode"},
                                                           {tr(Msg::UiExportDxf), "dxf"},
                                                           {tr(Msg::UiExportReportText), "report-text"},
                                                           {tr(Msg::UiExportReportJson), "report-json"},
                                                           {tr(Msg::UiExportProblemsCsv), "report-csv"},
                                                           {tr(Msg::UiExportViewSvg), "view-svg"},
                                                           {tr(Msg::UiExportJobSheet), "job-html"}};
    for (const auto& [label, format] : formats)
        if (ImGui::Selectable(label.c_str())) exports.export_file(format);
    if (ImGui::Selectable(tr(Msg::UiExportViewPng))) exports.export_view_png();
    ImGui::EndPopup();
}

// The side panels: shown or hidden ([ and ]), the theme, the problems-only view (P), the widths back to their defaults.
void panels_menu(Preferences& preferences, const PanelLayout& layout) {
    if (!ImGui::BeginPopup("panels")) return;
    PanelLayout l = layout;
    bool changed = ImGui::Checkbox((std::string(tr(Msg::UiPanelLeft)) + "  [###left").c_str(), &l.left_shown);
    changed |= ImGui::Checkbox((std::string(tr(Msg::UiPanelRight)) + "  ]###right").c_str(), &l.right_shown);
    bool light = preferences.light_theme();
    if (ImGui::Checkbox(tr_id(Msg::UiLightTheme, "light").c_str(), &light)) preferences.set_light_theme(light);
    bool problems = preferences.problems_only();
    if (ImGui::Checkbox((std::string(tr(Msg::UiProblemsOnly)) + "  P###problems").c_str(), &problems))
        preferences.set_problems_only(problems);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(Msg::UiProblemsOnlyTip));
    if (ImGui::Selectable(tr_id(Msg::UiDefaultLayout, "default").c_str())) {
        l = PanelLayout{};
        changed = true;
    }
    if (changed) preferences.set_layout(l);
    ImGui::EndPopup();
}

// A button with its tooltip (none: Msg::None); true when it was clicked.
bool button(Msg label, const char* id, Msg tip) {
    const bool clicked = ImGui::Button(tr_id(label, id).c_str());
    if (tip != Msg::None) tooltip(tip);
    return clicked;
}

bool open_button(PlatformServices& platform) {
    const bool clicked = ImGui::Button(tr_id(Msg::UiOpen, "open").c_str());
    if (clicked) platform.open_file_dialog();
    // (the page opens the file picker in the click on this rectangle: FilesEmscripten.cpp)
    platform.open_button_at(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                            ImGui::GetItemRectSize().y);
    tooltip(Msg::UiOpenTip);
    return clicked;
}

void profile_combo(Session& session, float width) {
    ImGui::SetNextItemWidth(width);
    if (ImGui::BeginCombo("##profile", profile_shown(session).c_str())) {
        for (const std::string& n : profile_choices(session))
            if (ImGui::Selectable(n.c_str(), n == session.profile_name()) && n != session.profile_name())
                session.set_profile(n);
        ImGui::EndCombo();
    }
    tooltip(Msg::UiProfileTip);
}

// The machine's view orientation (View::turns): where the tape's +x points on the screen; kept.
void orientation_combo(Navigation& navigation, float width) {
    const int turns = navigation.view().turns;
    ImGui::SetNextItemWidth(width);
    if (ImGui::BeginCombo("##orientation", tr(kOrientations[static_cast<std::size_t>(turns)]))) {
        for (int q = 0; q < 4; ++q)
            if (ImGui::Selectable(tr(kOrientations[static_cast<std::size_t>(q)]), q == turns) && q != turns)
                navigation.set_orientation(q);
        ImGui::EndCombo();
    }
    tooltip(Msg::UiOrientTip);
}

// Program or machine coordinates (Coordinates): the numbers, the grid and the drawing's turn; kept.
void coordinates_combo(Navigation& navigation, float width) {
    const int machine = navigation.machine_coordinates() ? 1 : 0;
    ImGui::SetNextItemWidth(width);
    if (ImGui::BeginCombo("##coordinates", tr(kCoordinates[static_cast<std::size_t>(machine)]))) {
        for (int k = 0; k < 2; ++k)
            if (ImGui::Selectable(tr(kCoordinates[static_cast<std::size_t>(k)]), k == machine) && k != machine)
                navigation.set_machine_coordinates(k == 1);
        ImGui::EndCombo();
    }
    tooltip(Msg::UiCoordinatesTip);
}

// Each language by its own name; kept across sessions (Preferences::set_language).
void language_combo(Preferences& preferences, float width) {
    const Lang now = preferences.language();
    ImGui::SetNextItemWidth(width);
    if (ImGui::BeginCombo("##language", std::string(lang_native_name(now)).c_str())) {
        for (const Lang l : kLanguages)
            if (ImGui::Selectable(std::string(lang_native_name(l)).c_str(), l == now) && l != now)
                preferences.set_language(l);
        ImGui::EndCombo();
    }
    tooltip(Msg::UiLanguageTip);
}

// The tape's name (when `with_name`) and its verdict.
void verdict(const Document* doc, bool with_name = true) {
    if (!doc) return;
    if (with_name) {
        ImGui::TextUnformatted(doc->name.c_str());
        ImGui::SameLine();
    }
    const std::size_t e = doc->count(Severity::Error), w = doc->count(Severity::Warning);
    const ImVec4 colour = e > 0   ? severity_color(Severity::Error)
                          : w > 0 ? severity_color(Severity::Warning)
                                  : to_vec4(kOkColor);
    ImGui::TextColored(colour, "%s", verdict_text(*doc).c_str());
}

// One item, in the bar or in the overflow menu (the same widgets). True when a button did what it does (the menu
// closes then).
bool draw_item(const Parts& p, Item item, float width) {
    switch (item) {
        case Item::Open: return open_button(p.platform);
        case Item::Paste:
            if (!button(Msg::UiPaste, "paste", Msg::UiPasteTip)) return false;
            p.platform.paste();
            return true;
        case Item::Share:
            if (!button(Msg::UiShareLink, "share", Msg::UiShareTip)) return false;
            p.shares.share();
            return true;
        case Item::Export:
            if (button(Msg::UiExport, "export", Msg::UiExportTip)) ImGui::OpenPopup("export");
            export_menu(p.exports);
            return false;
        case Item::Fit:
            if (!button(Msg::UiFit, "fit", Msg::UiFitTip)) return false;
            p.navigation.fit();
            return true;
        case Item::Measure: {
            const bool clicked = ImGui::Checkbox(tr_id(Msg::UiMeasure, "measure").c_str(), &p.measure.active);
            if (clicked) p.measure.points = 0;
            return clicked;
        }
        case Item::Help:
            if (!button(Msg::UiHelp, "help", Msg::None)) return false;
            p.ui.help = !p.ui.help;
            return true;
        case Item::Panels:
            if (button(Msg::UiPanels, "panels", Msg::UiPanelsTip)) ImGui::OpenPopup("panels");
            panels_menu(p.preferences, p.ui.layout);
            return false;
        case Item::Compare:
            if (!button(compare_label(p.compare), "compare", Msg::UiCompareTip)) return false;
            if (p.compare.result()) p.compare.end();
            else p.compare.begin(p.session.document());
            return true;
        case Item::Profile: profile_combo(p.session, width); return false;
        case Item::Orientation: orientation_combo(p.navigation, width); return false;
        case Item::Coordinates: coordinates_combo(p.navigation, width); return false;
        case Item::Language: language_combo(p.preferences, width); return false;
        case Item::Verdict: verdict(p.session.document()); return false;
    }
    return false;
}

// Draws one item in a group and notes where it is (state().toolbar).
bool placed_item(const Parts& p, const ItemInfo& info, float width, bool in_menu) {
    ImGui::BeginGroup();
    const bool acted = draw_item(p, info.item, width);
    ImGui::EndGroup();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    p.ui.toolbar.push_back({info.id, Rect{a.x, a.y, b.x - a.x, b.y - a.y}, in_menu});
    return acted;
}

// The message (Notices): in the bar when it fits after the items (which end at `bar_end`), else over the top of
// the drawing area `area`.
void message(const Notices& notices, const Rect& area, float bar_end, float right) {
    if (!notices.shown()) return;
    const std::string text = notices.message().text();
    const float gap = ImGui::GetStyle().ItemSpacing.x * 2;
    if (bar_end + gap + text_width(text.c_str()) <= right) {
        ImGui::SameLine(0, gap);
        ImGui::TextColored(to_vec4(kMessageColor), "%s", text.c_str());
        return;
    }
    ImGui::SetNextWindowPos(ImVec2(area.x + area.w / 2, area.y + 8), ImGuiCond_Always, ImVec2(0.5f, 0.f));
    ImGui::Begin("##toolbar message", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + std::max(area.w - 60, 180.f));
    ImGui::TextColored(to_vec4(kMessageColor), "%s", text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

// How many items fit in the bar, in their order (with room for the overflow button when some do not), the bar
// ending at `right`.
std::size_t items_that_fit(const std::vector<float>& widths, float right) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const auto row_end = [&](std::size_t count) {  // where `count` items end
        float x = style.WindowPadding.x;
        for (std::size_t k = 0; k < count; ++k) x += widths[k] + (k > 0 ? style.ItemSpacing.x : 0);
        return x;
    };
    const std::size_t n = widths.size();
    std::size_t fit = n;
    if (row_end(n) > right)
        while (fit > 0 && row_end(fit) + (fit > 0 ? style.ItemSpacing.x : 0) + button_width(kMoreLabel) > right) --fit;
    return fit;
}

// The overflow button (») and its menu, with items [first, end); where the bar ends now.
float overflow_menu(const Parts& p, const std::vector<ItemInfo>& items, const std::vector<float>& widths,
                    std::size_t first) {
    UiState& ui = p.ui;
    if (ImGui::Button(kMoreLabel)) ImGui::OpenPopup("more");
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    ui.toolbar_more = Rect{a.x, a.y, b.x - a.x, b.y - a.y};
    tooltip(Msg::UiMoreTip);
    const bool open = ImGui::BeginPopup("more");
    for (std::size_t k = first; k < items.size(); ++k) {
        if (!open) {
            ui.toolbar.push_back({items[k].id, Rect{0, 0, 0, 0}, true});
            continue;
        }
        if (placed_item(p, items[k], widths[k], true)) ImGui::CloseCurrentPopup();
    }
    if (open) {
        ui.toolbar_menu_open = true;
        ImGui::EndPopup();
    }
    return b.x;
}

}  // namespace

void Panels::toolbar() {
    ImGuiIO& io = ImGui::GetIO();
    const ImGuiStyle& style = ImGui::GetStyle();
    p_.fonts.require_glyphs(lang_native_name(Lang::Zh));  // (the language switch names 中文 in every language)
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kToolbarHeight));
    ImGui::Begin("##toolbar", nullptr, kPanelFlags | ImGuiWindowFlags_NoDecoration);
    UiState& ui = p_.ui;
    ui.toolbar.clear();
    ui.toolbar_more = Rect{0, 0, 0, 0};
    ui.toolbar_menu_open = false;

    // The verdict is always in the bar, after the items that fit and before the overflow button: without the tape's
    // name when the bar is too narrow for both.
    std::vector<ItemInfo> items(std::begin(kItems), std::end(kItems));
    std::erase_if(items, [](const ItemInfo& i) { return i.item == Item::Verdict; });
    std::vector<float> widths(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) widths[k] = item_width(p_, items[k].item);
    const float right = io.DisplaySize.x - style.WindowPadding.x;
    const Document* doc = p_.session.document();
    const float least = widths.front() + button_width(kMoreLabel) + style.ItemSpacing.x * 3;  // (Open and »)
    float verdict_w = doc ? item_width(p_, Item::Verdict) : 0;
    const bool with_name = verdict_w + least <= right - style.WindowPadding.x;
    if (doc && !with_name) verdict_w = text_width(verdict_text(*doc).c_str());
    const std::size_t fit = items_that_fit(widths, right - (doc ? verdict_w + style.ItemSpacing.x : 0));
    float bar_end = style.WindowPadding.x;
    for (std::size_t k = 0; k < fit; ++k) {
        if (k > 0) ImGui::SameLine();
        placed_item(p_, items[k], widths[k], false);
        bar_end = ImGui::GetItemRectMax().x;
    }
    if (doc) {
        if (fit > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        verdict(doc, with_name);
        ImGui::EndGroup();
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        ui.toolbar.push_back({"verdict", Rect{a.x, a.y, b.x - a.x, b.y - a.y}, false});
        bar_end = b.x;
    }
    if (fit < items.size()) {
        if (fit > 0 || doc) ImGui::SameLine();
        bar_end = overflow_menu(p_, items, widths, fit);
    }
    message(p_.notices, p_.navigation.view().area, bar_end, right);
    ImGui::End();
}

}  // namespace essi::viewer::panels
