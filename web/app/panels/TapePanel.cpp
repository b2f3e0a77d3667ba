// The left panel: the tape's statistics, the layers, the playback and the diagnostics.
#include <algorithm>
#include <cmath>

#include "app/App.hpp"
#include "essi/dialect.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "essi/text.hpp"

namespace essi::viewer::panels {

namespace {

void stats_row(const char* name, const std::string& value) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    ImGui::TableNextColumn();
    ImGui::TextWrapped("%s", value.c_str());
}

void stats_table(const Document& doc) {
    const Stats& s = doc.stats;
    if (!ImGui::BeginTable("stats", 2)) return;
    // The names as wide as the longest; the values in the rest, wrapped (the boxes do not fit a line).
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    stats_row("cut", length_text(s.cut_length_mm));
    stats_row("  compensated", length_text(s.cut_length_compensated_mm));
    stats_row("mark", length_text(s.mark_length_mm));
    stats_row("travel", length_text(s.travel_length_mm));
    stats_row("  of it rapid", length_text(s.rapid_length_mm));
    // The machine's box (§11), where the placement moves it (a profile with zero offsets, a plate rotation ...).
    const Box& mb = s.machine_cut_bbox;
    if (!mb.empty && !(mb.min_x == s.cut_bbox.min_x && mb.min_y == s.cut_bbox.min_y && mb.max_x == s.cut_bbox.max_x &&
                       mb.max_y == s.cut_bbox.max_y))
        stats_row("machine cut box", fmt("(%.1f, %.1f) - (%.1f, %.1f)", mb.min_x, mb.min_y, mb.max_x, mb.max_y));
    stats_row("pierces", fmt("%llu", s.pierces));
    stats_row("blocks", fmt("%llu", s.blocks));
    stats_row("motions", fmt("%llu", s.motions));
    stats_row("time", hms(s.estimated_time_s));
    const Box& c = s.cut_bbox;
    if (!c.empty) {
        stats_row("cut extent", fmt("%.1f x %.1f mm", c.max_x - c.min_x, c.max_y - c.min_y));
        stats_row("cut box", fmt("(%.1f, %.1f) - (%.1f, %.1f)", c.min_x, c.min_y, c.max_x, c.max_y));
    }
    const Box& m = s.motion_bbox;
    if (!m.empty) stats_row("motion box", fmt("(%.1f, %.1f) - (%.1f, %.1f)", m.min_x, m.min_y, m.max_x, m.max_y));
    stats_row("end", fmt("(%.3f, %.3f)", s.end_position.x, s.end_position.y));
    ImGui::EndTable();
}

// How the tape is read: its format, its dialect and why (the evidence of --profile auto), and one click to read it
// with another dialect.
void reading(App& app) {
    const Document* doc = app.document();
    if (!doc) {
        ImGui::TextDisabled("No tape loaded.");
        return;
    }
    const TapeSetup& s = doc->setup;
    ImGui::Text("%s tape, profile %s%s", s.format == InputFormat::Eia ? "EIA (RS-274)" : "ESSI", s.profile.name.c_str(),
                s.auto_profile ? " (auto)" : "");
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (s.evidence.empty()) ImGui::TextWrapped("No dialect's codes in the tape: read as %s.", s.profile.name.c_str());
    for (const std::string& e : s.evidence) ImGui::TextWrapped("%s", e.c_str());
    ImGui::PopStyleColor();
    ImGui::TextUnformatted("Read as:");
    for (const std::string& n : builtin_profile_names()) {
        if (n == s.profile.name) continue;
        ImGui::SameLine();
        if (ImGui::SmallButton(n.c_str())) app.set_profile(n);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Check the tape again with the %s profile", n.c_str());
    }
    if (app.profile_name() != kAutoProfile) {
        ImGui::SameLine();
        if (ImGui::SmallButton("auto")) app.set_profile(std::string(kAutoProfile));
    }
}

void statistics(const App& app) {
    const Document* doc = app.document();
    if (!doc) {
        ImGui::TextDisabled("No tape loaded.");
        return;
    }
    stats_table(*doc);
    const LoadController& load = app.loads();
    const PathBuffers* building = load.building();
    const std::string about =
        building && load.first_build()  // (the segments are still being made: none to count yet)
            ? fmt("%s, %zu lines, segments being made (%.0f %%)", size_text(doc->bytes.size()).c_str(),
                  doc->line_count(), 100.0 * stepped(building->progress()))
            : fmt("%s, %zu lines, %zu segments, loaded in %.2f s", size_text(doc->bytes.size()).c_str(),
                  doc->line_count(), load.buffers().segment_count, load.load_seconds());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", about.c_str());
    ImGui::PopStyleColor();
}

void layers(Layers& layers, const Document* doc) {
    int col = 0;
    for (MotionKind k : {MotionKind::Cut, MotionKind::Mark, MotionKind::Travel, MotionKind::Rapid}) {
        if (col++ % 2 == 1) ImGui::SameLine(150);
        ImGui::ColorButton(fmt("##c%d", static_cast<int>(k)).c_str(), opaque(kind_color(k)), ImGuiColorEditFlags_NoTooltip,
                           ImVec2(14, 14));
        ImGui::SameLine();
        ImGui::Checkbox(motion_kind_name(k), &layers.kind(k));
    }
    ImGui::Checkbox("pierces", &layers.pierces);
    ImGui::SameLine();
    ImGui::Checkbox("start", &layers.start);
    ImGui::SameLine();
    ImGui::Checkbox("grid", &layers.grid);
    ImGui::SameLine();
    ImGui::Checkbox("table", &layers.table);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The machine's table (a profile with a table) and the plate (the box of the cuts)");
    // The kerf layers, where the tape uses compensation (docs/semantics.md §8).
    if (doc && std::any_of(doc->kerfs.begin(), doc->kerfs.end(), [](const auto& k) { return k.second > 0; })) {
        ImGui::ColorButton("##kerf", opaque(kPathColorTable[kKerfPathKind]), ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::SameLine();
        ImGui::Checkbox("kerf path", &layers.kerf);
        ImGui::SameLine(150);
        ImGui::ColorButton("##band", opaque(kPathColorTable[kKerfBandKind]), ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::SameLine();
        ImGui::Checkbox("kerf width", &layers.kerf_band);
    }
}

void playback(App& app) {
    const Document* doc = app.document();
    if (!doc || doc->motions.empty()) {
        ImGui::TextDisabled("No motion.");
        return;
    }
    Playback& p = app.playback();
    const std::size_t n = doc->motions.size();
    if (ImGui::Button(p.playing ? "Pause" : "Play")) p.toggle(n);
    ImGui::SameLine();
    if (ImGui::Button("<")) p.step_back();
    ImGui::SameLine();
    if (ImGui::Button(">")) p.step_forward(n);
    ImGui::SameLine();
    if (ImGui::Button("All")) p.show_all(n);
    int pos = static_cast<int>(std::floor(p.position));
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderInt("##pos", &pos, 0, static_cast<int>(n), "motion %d")) p.seek(pos);
    ImGui::SetNextItemWidth(-1);
    ImGui::SliderFloat("##factor", &p.factor, Playback::kMinFactor, Playback::kMaxFactor, "%.0fx machine speed",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    const double elapsed = p.elapsed_s(*doc), total = p.total_s(*doc);
    ImGui::TextWrapped("machine time %s of %s, %s to go", hms(elapsed).c_str(), hms(total).c_str(),
                       hms(total - elapsed).c_str());
    if (!p.active) return;
    const std::size_t cur = p.at(n).motion;
    const Motion& m = doc->motions[cur];
    ImGui::Text("line %u: %s %s", m.line, motion_kind_name(m.kind), curve_kind_name(m.curve));
    ImGui::Text("tools %s, %.0f mm/min", tools_text(m.tools).c_str(), doc->feed_of(cur));
    const Playback::At at = p.at(n);
    const Coordinates cs = app.coordinates();
    const Point tool = cs.shown(point_at(doc->record(at.motion), at.fraction));
    ImGui::Text("tool at (%.3f, %.3f), %s mm", tool.x, tool.y, cs.name());
    if (ImGui::SmallButton("show line")) app.select_line(m.line, false);
}

void diagnostics(App& app) {
    const Document* doc = app.document();
    if (!doc) {
        ImGui::TextDisabled("-");
        return;
    }
    if (doc->diagnostics.empty()) {
        ImGui::TextColored(to_vec4(kOkColor), "No problems found.");
        return;
    }
    if (ImGui::SmallButton("Copy the report")) app.copy(App::CopyWhat::Report);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Copy the report as essi check prints it (right-click a problem to copy it alone)");
    ImGui::BeginChild("diaglist", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(doc->diagnostics.size()));
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const Diagnostic& d = doc->diagnostics[static_cast<std::size_t>(i)];
            ImGui::PushID(i);
            ImGui::PushStyleColor(ImGuiCol_Text, severity_color(d.severity));
            const std::string label = fmt("%s line %u:%u", code_name(d.code).c_str(), d.line, d.column);
            if (ImGui::Selectable(label.c_str(), d.line != 0 && d.line == app.selection().line)) app.select_line(d.line);
            ImGui::PopStyleColor();
            if (ImGui::BeginPopupContextItem("diagnostic menu")) {
                if (ImGui::Selectable("Copy this problem")) app.copy(App::CopyWhat::Diagnostic, static_cast<std::uint32_t>(i));
                if (ImGui::Selectable("Copy the report")) app.copy(App::CopyWhat::Report);
                ImGui::EndPopup();
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", d.message.c_str());
            ImGui::SameLine();
            ImGui::TextWrapped("%s", d.message.c_str());
            ImGui::PopID();
        }
    }
    ImGui::EndChild();
}

}  // namespace

void tape_panel(App& app) {
    if (!begin_side_panel(app, "Tape", true)) return;
    if (ImGui::CollapsingHeader("Reading", ImGuiTreeNodeFlags_DefaultOpen)) reading(app);
    if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) statistics(app);
    if (ImGui::CollapsingHeader("Layers", ImGuiTreeNodeFlags_DefaultOpen)) layers(app.layers(), app.document());
    if (ImGui::CollapsingHeader("Playback", ImGuiTreeNodeFlags_DefaultOpen)) playback(app);
    if (ImGui::CollapsingHeader("Diagnostics", ImGuiTreeNodeFlags_DefaultOpen)) diagnostics(app);
    ImGui::End();
}

}  // namespace essi::viewer::panels
