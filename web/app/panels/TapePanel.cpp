// The left panel: the tape's statistics, the job (its sheet's time and cost, parts and plates), the layers, the
// playback and the diagnostics.
#include <algorithm>
#include <cmath>

#include "app/Describe.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "essi/dialect.hpp"
#include "essi/text.hpp"

namespace essi::viewer::panels {

namespace {

void stats_row(Msg name, const std::string& value, bool indent = false) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (indent) ImGui::Indent(ImGui::GetStyle().IndentSpacing / 2);
    ImGui::TextUnformatted(tr(name));
    if (indent) ImGui::Unindent(ImGui::GetStyle().IndentSpacing / 2);
    ImGui::TableNextColumn();
    ImGui::TextWrapped("%s", value.c_str());
}

void stats_table(const Document& doc) {
    const Stats& s = doc.stats;
    if (!ImGui::BeginTable("stats", 2)) return;
    // The names as wide as the longest; the values in the rest, wrapped (the boxes do not fit a line).
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    stats_row(Msg::UiStatCut, length_text(s.cut_length_mm));
    stats_row(Msg::UiStatCompensated, length_text(s.cut_length_compensated_mm), true);
    stats_row(Msg::UiStatMark, length_text(s.mark_length_mm));
    stats_row(Msg::UiStatTravel, length_text(s.travel_length_mm));
    stats_row(Msg::UiStatOfItRapid, length_text(s.rapid_length_mm), true);
    // The machine's box (§12), where the placement moves it (a profile with zero offsets, a plate rotation ...).
    const Box& mb = s.machine_cut_bbox;
    if (!mb.empty && !(mb.min_x == s.cut_bbox.min_x && mb.min_y == s.cut_bbox.min_y && mb.max_x == s.cut_bbox.max_x &&
                       mb.max_y == s.cut_bbox.max_y))
        stats_row(Msg::UiStatMachineCutBox, fmt("(%.1f, %.1f) - (%.1f, %.1f)", mb.min_x, mb.min_y, mb.max_x, mb.max_y));
    stats_row(Msg::UiStatPierces, fmt("%llu", s.pierces));
    stats_row(Msg::UiStatBlocks, fmt("%llu", s.blocks));
    stats_row(Msg::UiStatMotions, fmt("%llu", s.motions));
    stats_row(Msg::UiStatTime, hms(statistics_time_s(s)));  // (the machine time with the profile's accel_mm_s2)
    const Box& c = s.cut_bbox;
    if (!c.empty) {
        stats_row(Msg::UiStatCutExtent, fmt("%.1f x %.1f mm", c.max_x - c.min_x, c.max_y - c.min_y));
        stats_row(Msg::UiStatCutBox, fmt("(%.1f, %.1f) - (%.1f, %.1f)", c.min_x, c.min_y, c.max_x, c.max_y));
    }
    const Box& m = s.motion_bbox;
    if (!m.empty)
        stats_row(Msg::UiStatMotionBox, fmt("(%.1f, %.1f) - (%.1f, %.1f)", m.min_x, m.min_y, m.max_x, m.max_y));
    stats_row(Msg::UiStatEnd, fmt("(%.3f, %.3f)", s.end_position.x, s.end_position.y));
    ImGui::EndTable();
}

// A table of the job sheet (parts, plates): its columns, numbers right-aligned.
void sheet_table(const SheetTable& t) {
    const int columns = static_cast<int>(t.columns.size());
    if (columns == 0 || !ImGui::BeginTable("table", columns, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit))
        return;
    for (const std::string& c : t.columns) ImGui::TableSetupColumn(c.c_str());
    ImGui::TableHeadersRow();
    for (const std::vector<std::string>& row : t.rows) {
        ImGui::TableNextRow();
        for (std::size_t c = 0; c < row.size() && c < t.columns.size(); ++c) {
            ImGui::TableNextColumn();
            if (c < t.numeric.size() && t.numeric[c])
                ImGui::SetCursorPosX(ImGui::GetCursorPosX() + ImGui::GetColumnWidth() -
                                     ImGui::CalcTextSize(row[c].c_str()).x);
            ImGui::TextUnformatted(row[c].c_str());
        }
    }
    ImGui::EndTable();
}

// The text encoding of the comments: detected (auto), or UTF-8 / GB 18030 as the user chooses.
void comment_encoding(CommentText& comments, const Document* doc) {
    const std::optional<TextEncoding> chosen = comments.chosen();
    const std::string detected(text_encoding_name(comments.detected()));
    const std::string auto_label = tr(Msg::UiEncodingAuto, {detected == "gb18030" ? "GB 18030" : "UTF-8"});
    const char* current = !chosen ? auto_label.c_str() : *chosen == TextEncoding::Gb18030 ? "GB 18030" : "UTF-8";
    ImGui::TextUnformatted(tr(Msg::UiComments));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::CalcTextSize(auto_label.c_str()).x + ImGui::GetFrameHeight() * 2);
    if (!ImGui::BeginCombo("##comment_encoding", current)) return;
    if (ImGui::Selectable(auto_label.c_str(), !chosen)) comments.choose(std::nullopt, doc);
    if (ImGui::Selectable("UTF-8", chosen == TextEncoding::Utf8)) comments.choose(TextEncoding::Utf8, doc);
    if (ImGui::Selectable("GB 18030", chosen == TextEncoding::Gb18030)) comments.choose(TextEncoding::Gb18030, doc);
    ImGui::EndCombo();
}

// How the tape is read: its format, its dialect and why (the evidence of --profile auto), and one click to read it
// with another dialect.
void reading(Session& session, CommentText& comments) {
    const Document* doc = session.document();
    if (!doc) {
        ImGui::TextDisabled("%s", tr(Msg::UiNoTape));
        return;
    }
    const TapeSetup& s = doc->setup;
    ImGui::TextWrapped("%s", tr(Msg::UiReadingLine, {s.format == InputFormat::Eia ? "EIA (RS-274)" : "ESSI",
                                                     s.profile.name, s.auto_profile ? " (auto)" : ""})
                                 .c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (s.evidence.empty()) ImGui::TextWrapped("%s", tr(Msg::UiNoDialectCodes, {s.profile.name}).c_str());
    for (const Message& e : s.evidence_messages) ImGui::TextWrapped("%s", e.text(ui_lang()).c_str());
    ImGui::PopStyleColor();
    ImGui::TextUnformatted(tr(Msg::UiReadAs));
    for (const std::string& n : builtin_profile_names()) {
        if (n == s.profile.name) continue;
        same_line_if_fits(ImGui::CalcTextSize(n.c_str()).x + ImGui::GetStyle().FramePadding.x * 2);
        if (ImGui::SmallButton(n.c_str())) session.set_profile(n);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(Msg::UiReadAsTip, {n}).c_str());
    }
    if (session.profile_name() != kAutoProfile) {
        same_line_if_fits(ImGui::CalcTextSize("auto").x + ImGui::GetStyle().FramePadding.x * 2);
        if (ImGui::SmallButton("auto")) session.set_profile(std::string(kAutoProfile));
    }
    comment_encoding(comments, session.document());
}

void statistics(const Document* doc, const LoadController& load) {
    if (!doc) {
        ImGui::TextDisabled("%s", tr(Msg::UiNoTape));
        return;
    }
    stats_table(*doc);
    const PathBuffers* building = load.building();
    const std::string about =
        building && load.first_build()  // (the segments are still being made: none to count yet)
            ? tr(Msg::UiAboutBuilding,
                 {size_text(doc->bytes.size()), doc->line_count(), fmt("%.0f", 100.0 * stepped(building->progress()))})
            : tr(Msg::UiAboutLoaded, {size_text(doc->bytes.size()), doc->line_count(), load.buffers().segment_count,
                                      fmt("%.2f", load.load_seconds())});
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", about.c_str());
    ImGui::PopStyleColor();
}

// A layer's switch: its colour (when it has one) and its checkbox, on the line before when it fits there (the panel
// may be narrow, the words long).
void layer_switch(const std::string& label, bool& on, const ImVec4* colour, bool first = false) {
    const ImGuiStyle& st = ImGui::GetStyle();
    constexpr float kSwatch = 14;
    const float w = (colour ? kSwatch + st.ItemSpacing.x : 0) + ImGui::GetFrameHeight() + st.ItemInnerSpacing.x +
                    ImGui::CalcTextSize(label.c_str(), nullptr, true).x;
    if (!first) same_line_if_fits(w);
    if (colour) {
        ImGui::PushID(label.c_str());
        ImGui::ColorButton("##swatch", *colour, ImGuiColorEditFlags_NoTooltip, ImVec2(kSwatch, kSwatch));
        ImGui::PopID();
        ImGui::SameLine();
    }
    ImGui::Checkbox(label.c_str(), &on);
}

// Colour by: the choice, and the legend of the colours drawn (ColourBy.hpp).
void colour_by(Layers& layers, const LoadController& load) {
    ImGui::TextUnformatted(tr(Msg::UiColourBy));
    ImGui::SameLine();
    const std::string current = tr(colour_by_label(layers.colour_by));
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##colour_by", current.c_str())) {
        for (const ColourBy by : kColourByModes)
            if (ImGui::Selectable(tr_id(colour_by_label(by), std::string(colour_by_name(by)).c_str()).c_str(),
                                  by == layers.colour_by))
                layers.colour_by = by;
        ImGui::EndCombo();
    }
    const float swatch = ImGui::GetTextLineHeight();
    for (const ColourLegendEntry& e : load.buffers().colour_legend(ui_lang())) {
        ImDrawList* dl = ImGui::GetWindowDrawList();
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const int bins = e.last_bin - e.first_bin + 1;
        for (int b = 0; b < bins; ++b) {
            const float x0 = at.x + swatch * 2 * static_cast<float>(b) / static_cast<float>(bins);
            const float x1 = at.x + swatch * 2 * static_cast<float>(b + 1) / static_cast<float>(bins);
            dl->AddRectFilled(
                ImVec2(x0, at.y + 2), ImVec2(x1, at.y + swatch - 2),
                ImGui::ColorConvertFloat4ToU32(opaque(kColourRamp[static_cast<std::size_t>(e.first_bin + b)])));
        }
        ImGui::Dummy(ImVec2(swatch * 2, swatch));
        ImGui::SameLine();
        ImGui::TextUnformatted(e.text.c_str());
    }
}

void layers(Layers& layers, Preferences& preferences, const Document* doc, const LoadController& load) {
    bool first = true;
    for (MotionKind k : {MotionKind::Cut, MotionKind::Mark, MotionKind::Travel, MotionKind::Rapid}) {
        const ImVec4 c = opaque(kind_color(k));
        layer_switch(std::string(motion_kind_text(k, ui_lang())) + "###" + motion_kind_name(k), layers.kind(k), &c,
                     first);
        first = false;
    }
    colour_by(layers, load);
    layer_switch(tr_id(Msg::UiLayerPierces, "pierces"), layers.pierces, nullptr);
    layer_switch(tr_id(Msg::UiLayerStart, "start"), layers.start, nullptr);
    layer_switch(tr_id(Msg::UiLayerGrid, "grid"), layers.grid, nullptr);
    layer_switch(tr_id(Msg::UiLayerTable, "table"), layers.table, nullptr);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(Msg::UiLayerTableTip));
    layer_switch(tr_id(Msg::UiLayerParts, "parts"), layers.parts, nullptr);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(Msg::UiLayerPartsTip));
    // The kerf layers, where the tape uses compensation (docs/semantics.md §8).
    if (doc && std::any_of(doc->kerfs.begin(), doc->kerfs.end(), [](const auto& k) { return k.second > 0; })) {
        const ImVec4 path = opaque(kPathColorTable[kKerfPathKind]), band = opaque(kPathColorTable[kKerfBandKind]);
        layer_switch(tr_id(Msg::UiLayerKerfPath, "kerf path"), layers.kerf, &path);
        layer_switch(tr_id(Msg::UiLayerKerfWidth, "kerf width"), layers.kerf_band, &band);
    }
    bool problems = preferences.problems_only();  // (kept across sessions: through Preferences)
    layer_switch(tr_id(Msg::UiProblemsOnly, "problems only"), problems, nullptr);
    if (problems != preferences.problems_only()) preferences.set_problems_only(problems);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(Msg::UiProblemsOnlyTip));
}

void playback(Playback& p, Navigation& navigation, const Document* doc, const MotionTimesSource& times) {
    if (!doc || doc->motions.empty()) {
        ImGui::TextDisabled("%s", tr(Msg::UiNoMotion));
        return;
    }
    const std::size_t n = doc->motions.size();
    if (ImGui::Button(tr_id(p.playing ? Msg::UiPause : Msg::UiPlay, "play").c_str())) p.toggle(n);
    ImGui::SameLine();
    if (ImGui::Button("<")) p.step_back();
    ImGui::SameLine();
    if (ImGui::Button(">")) p.step_forward(n);
    ImGui::SameLine();
    if (ImGui::Button(tr_id(Msg::UiAll, "all").c_str())) p.show_all(n);
    int pos = static_cast<int>(std::floor(p.position));
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderInt("##pos", &pos, 0, static_cast<int>(n), tr_format(Msg::UiSliderMotion, "%d").c_str()))
        p.seek(pos);
    ImGui::SetNextItemWidth(-1);
    ImGui::SliderFloat("##factor", &p.factor, Playback::kMinFactor, Playback::kMaxFactor,
                       tr_format(Msg::UiSliderSpeed, "%.0f").c_str(),
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    const double elapsed = p.elapsed_s(*doc, times), total = Playback::total_s(*doc);
    ImGui::TextWrapped("%s", tr(Msg::UiMachineTime, {hms(elapsed), hms(total), hms(total - elapsed)}).c_str());
    if (!p.active) return;
    const std::size_t cur = p.at(n).motion;
    const Motion& m = doc->motions[cur];
    const Lang lang = ui_lang();
    ImGui::TextWrapped(
        "%s",
        tr(Msg::UiPlaybackLine, {m.line, motion_kind_text(m.kind, lang), curve_kind_text(m.curve, lang)}).c_str());
    ImGui::TextWrapped("%s",
                       tr(Msg::UiPlaybackTools, {tools_label(m.tools, lang), fmt("%.0f", doc->feed_of(cur))}).c_str());
    const Playback::At at = p.at(n);
    const Coordinates cs = navigation.coordinates();
    const Point tool = cs.shown(point_at(doc->record(at.motion), at.fraction));
    ImGui::TextWrapped("%s", tr(Msg::UiToolAt, {fmt("%.3f", tool.x), fmt("%.3f", tool.y),
                                                cs.machine() ? Msg::UiCoordsMachineShort : Msg::UiCoordsProgramShort})
                                 .c_str());
    if (ImGui::SmallButton(tr_id(Msg::UiShowLine, "show line").c_str())) navigation.select_line(m.line, false);
}

// The job sheet's sections (Exports::job_sections: what `essi report` prints, in the UI's language) and its print
// view.
void job(const Document* doc, Exports& exports) {
    if (!doc) {
        ImGui::TextDisabled("%s", tr(Msg::UiNoTape));
        return;
    }
    for (const SheetSection& s : exports.job_sections()) {
        ImGui::PushID(s.id.c_str());
        ImGui::Separator();
        ImGui::TextUnformatted(s.title.c_str());
        if (!s.fields.empty() && ImGui::BeginTable("fields", 2)) {
            ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthFixed);
            ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
            for (const SheetField& f : s.fields) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(f.label.c_str());
                ImGui::TableNextColumn();
                ImGui::TextWrapped("%s", f.value.c_str());
            }
            ImGui::EndTable();
        }
        if (s.table) sheet_table(*s.table);
        if (!s.note.empty()) ImGui::TextDisabled("%s", s.note.c_str());
        ImGui::PopID();
    }
    if (ImGui::SmallButton(tr_id(Msg::UiJobPrint, "print view").c_str())) exports.print_job_sheet();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(Msg::UiJobPrintTip));
}

}  // namespace

void Panels::statistics_section() { statistics(p_.session.document(), p_.load); }

void Panels::tape_panel() {
    if (!begin_side_panel(p_.ui.layout, p_.ui.layout_changed, tr_id(Msg::UiTapePanel, "Tape").c_str(), true)) return;
    const Document* doc = p_.session.document();
    // In a short window the sections between the reading and the diagnostics start closed, so that the problems
    // list is on the screen.
    const bool short_window = ImGui::GetIO().DisplaySize.y < kShortWindowPx;
    const auto header = [short_window](Msg title, const char* id, bool closed_when_short = false) {
        if (short_window && closed_when_short) ImGui::SetNextItemOpen(false, ImGuiCond_Once);
        return ImGui::CollapsingHeader(tr_id(title, id).c_str(), ImGuiTreeNodeFlags_DefaultOpen);
    };
    if (header(Msg::UiReading, "Reading")) reading(p_.session, p_.comments);
    if (header(Msg::UiStatistics, "Statistics", true)) statistics(doc, p_.load);
    if (header(Msg::UiJob, "Job", true)) job(doc, p_.exports);
    if (header(Msg::UiLayers, "Layers", true)) layers(p_.layers, p_.preferences, doc, p_.load);
    if (header(Msg::UiPlayback, "Playback", true)) playback(p_.playback, p_.navigation, doc, p_.tape_facts);
    if (header(Msg::UiDiagnostics, "Diagnostics")) problems_list();
    ImGui::End();
}

}  // namespace essi::viewer::panels
