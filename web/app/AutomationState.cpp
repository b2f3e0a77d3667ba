#include <algorithm>
#include <cmath>
#include <span>
#include <nlohmann/json.hpp>

#include "app/Automation.hpp"
#include "app/Describe.hpp"
#include "app/ProblemList.hpp"
#include "app/Problems.hpp"
#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/placement.hpp"
#include "essi/report_json.hpp"

namespace essi::viewer {

namespace {

using nlohmann::json;

constexpr std::size_t kStateMarks = 100;  // marks listed in state().marks.items at most (the count is all of them)

// The document's part of the state: statistics, diagnostics, sizes, memory, level of detail.
void add_document(json& j, const Document& doc, const LoadController& load, const Renderer& renderer, bool lod_drawn) {
    j["stats"] = stats_to_json(doc.stats);  // the report's own writer (essi/report_json.hpp)
    j["ok"] = !doc.has_errors();
    j["bytes"] = doc.bytes.size();
    j["lines"] = doc.line_count();
    j["motions"] = doc.motions.size();
    j["segments"] = load.buffers().segment_count;
    json widths = json::array();
    for (std::size_t k = 0; k < load.buffers().kerf_width_count; ++k) widths.push_back(load.buffers().kerf_widths[k]);
    j["kerf"] = {{"segments", load.buffers().kerf_segments}, {"widths_mm", widths}};
    // The machine's table where it lies under the program (the Table overlay), corners in program mm; null without
    // a table in the profile.
    if (doc.profile.table) {
        json corners = json::array();
        for (const Point& c : Placement(doc.profile).table_in_program(*doc.profile.table))
            corners.push_back({c.x, c.y});
        j["table_mm"] = corners;
    } else {
        j["table_mm"] = nullptr;
    }
    j["pierce_markers"] = doc.pierces.size();
    j["bbox_mm"] = box_to_json(doc.bbox);
    j["memory_bytes"] = doc.memory_bytes() + load.segment_index_bytes();
    json parts = json::object();
    for (const auto& [part, n] : doc.memory_parts()) parts[part] = n;
    parts["segment_index"] = load.segment_index_bytes();
    j["memory_parts"] = std::move(parts);
    j["gpu_bytes"] = load.gpu_bytes() + renderer.lod_gpu_bytes();
    j["lod"] = {{"available", renderer.has_lod()}, {"drawn", lod_drawn}, {"cell_mm", renderer.lod_cell_mm()}};
    j["tape_memory_bytes"] = doc.core_tape_bytes();
    j["blocks_read"] = doc.blocks;
    j["kept_records"] = doc.kept.size();
    j["load_seconds"] = load.load_seconds();
    j["chord_tolerance_mm"] = load.buffers().tolerance();
}

// What the Playback panel shows: the motion at the scrubber, its line, the tools and where the tool is.
json playback_json(const Playback& playback, const Document* doc, const MotionTimesSource& times,
                   const Coordinates& cs) {
    json p = {{"active", playback.active},
              {"playing", playback.playing},
              {"position", playback.position},
              {"factor", playback.factor}};
    if (doc) {
        const double elapsed = playback.elapsed_s(*doc, times), total = Playback::total_s(*doc);
        p["elapsed_s"] = elapsed;
        p["total_s"] = total;
        p["remaining_s"] = total - elapsed;
    }
    if (!playback.active || !doc || doc->motions.empty()) return p;
    const std::size_t n = doc->motions.size();
    const Playback::At at = playback.at(n);
    const Motion& m = doc->motions[at.motion];
    const Point tool = point_at(doc->record(at.motion), at.fraction);
    p["motion"] = at.motion;
    p["line"] = m.line;
    p["kind"] = motion_kind_name(m.kind);
    p["tools"] = tools_text(m.tools);
    p["feed_mm_min"] = doc->feed_of(at.motion);
    p["tool_mm"] = {tool.x, tool.y};
    const Point shown = cs.shown(tool);
    p["tool_shown_mm"] = {shown.x, shown.y};  // (in the shown coordinates, as the Playback panel says it)
    p["drawn_motions"] = playback.limit(n);
    return p;
}

// The measure as its window shows it: in the shown coordinates.
json measure_json(const Measure& m, const Coordinates& cs) {
    json j = {{"active", m.active}, {"points", m.points}, {"coordinates", cs.name()}};
    const Point a = cs.shown(m.a), b = cs.shown(m.b);
    if (m.points >= 1) j["a_mm"] = {a.x, a.y};
    if (m.points == 2) {
        j["b_mm"] = {b.x, b.y};
        j["distance_mm"] = std::hypot(b.x - a.x, b.y - a.y);
        j["dx_mm"] = b.x - a.x;
        j["dy_mm"] = b.y - a.y;
    }
    return j;
}

// The block inspector's sentences for the selected line (blocks, then motions).
json inspector_json(const Document* doc, std::uint32_t line) {
    json insp = json::array();
    if (doc)
        for (const InspectorLine& l : inspector_lines(*doc, line, ui_lang())) insp.push_back(l.text);
    return insp;
}

json render_json(const RenderStats& rs, std::uint64_t unchanged_frames) {
    return {{"frames", rs.frames},
            {"full_redraws", rs.full_redraws},
            {"partial_redraws", rs.partial_redraws},
            {"cached_frames", rs.cached_frames},
            {"filling_frames", rs.filling_frames},
            {"pending_segments", rs.pending_segments},
            {"unchanged_frames", unchanged_frames}};
}

json rect(const Rect& r) { return json{{"x", r.x}, {"y", r.y}, {"w", r.w}, {"h", r.h}}; }

// The toolbar's items as the last frame drew them: where each is, in the bar or in its overflow menu ("more").
json toolbar_json(const UiState& ui) {
    json items = json::array();
    for (const ToolbarItem& t : ui.toolbar)
        items.push_back({{"id", t.id}, {"in_menu", t.in_menu}, {"rect", rect(t.rect)}});
    return {{"items", items},
            {"more", ui.toolbar_more.w > 0 ? rect(ui.toolbar_more) : json(nullptr)},
            {"menu_open", ui.toolbar_menu_open}};
}

// One diagnostic as a mark's tooltip says it: as the report writes it (essi/report_json.hpp), in the viewer's
// language, with its index in the document's diagnostics and the count of its overlap polygons.
json mark_diagnostic_json(const Diagnostic& d, std::size_t index) {
    json j = diagnostic_to_json(d, ui_lang());
    j["diagnostic"] = index;
    j["overlap_polygons"] = d.overlap().size();
    return j;
}

// The diagnostics' marks (docs/viewer.md, "Problems on the drawing"): where each is (program mm and page pixels),
// the one under the mouse, the diagnostics highlighted.
json marks_json(const Document& doc, const View& view, std::size_t hovered, std::uint32_t selected_line) {
    json items = json::array();
    for (std::size_t k = 0; k < doc.marks.size() && k < kStateMarks; ++k) {
        const DiagnosticMark& m = doc.marks[k];
        const Diagnostic& d = doc.diagnostics[m.diagnostic];
        const Point px = mark_screen(doc, view, m);
        items.push_back({{"mark", k},
                         {"diagnostic", m.diagnostic},
                         {"code", code_name(d.code)},
                         {"severity", severity_name(d.severity)},
                         {"line", d.line},
                         {"at_mm", {m.at.x, m.at.y}},
                         {"px", {px.x, px.y}},
                         {"in_view", view.area.contains(static_cast<float>(px.x), static_cast<float>(px.y))}});
    }
    std::size_t overlaps = 0;
    for (const Diagnostic& d : doc.diagnostics) overlaps += d.overlap().empty() ? 0 : 1;
    json active = json::array();
    for (const std::size_t k : active_diagnostics(doc, hovered, selected_line)) active.push_back(k);
    return {{"count", doc.marks.size()},
            {"radius_px", Renderer::kMarkRadiusPx},
            {"hit_radius_px", kMarkHitRadiusPx},
            {"hovered",
             hovered < doc.marks.size()
                 ? mark_diagnostic_json(doc.diagnostics[doc.marks[hovered].diagnostic], doc.marks[hovered].diagnostic)
                 : json(nullptr)},
            {"active", active},
            {"overlaps", overlaps},
            {"concerned_motion_runs", doc.concerned_motions.size()},
            {"items", items}};
}

json selection_json(const Selection& s) {
    if (s.line == 0) return nullptr;
    return {{"line", s.line}, {"motion", s.motion == Selection::npos ? json(nullptr) : json(s.motion)}};
}

json layers_json(const Layers& l) {
    json j = {{"pierces", l.pierces},     {"start", l.start}, {"grid", l.grid},  {"kerf", l.kerf},
              {"kerf_band", l.kerf_band}, {"table", l.table}, {"parts", l.parts}};
    for (std::size_t k = 0; k < kMotionKinds; ++k) j[motion_kind_name(static_cast<MotionKind>(k))] = l.kinds[k];
    return j;
}

// Colour by: the choice, the one drawn (the segments are made again after a change) and its legend, each line
// with its bins' colours (0-255).
json colour_by_json(const Layers& l, const LoadController& load) {
    json legend = json::array();
    for (const ColourLegendEntry& e : load.buffers().colour_legend(ui_lang())) {
        json colors = json::array();
        for (std::size_t b = e.first_bin; b <= e.last_bin; ++b) {
            const Rgba& c = kColourRamp[b];
            colors.push_back({std::lround(c.r * 255), std::lround(c.g * 255), std::lround(c.b * 255)});
        }
        legend.push_back({{"text", e.text}, {"colors", colors}});
    }
    return {{"mode", colour_by_name(l.colour_by)},
            {"drawn", colour_by_name(load.buffers().colour_by())},
            {"legend", legend}};
}

// How the last load went in frame numbers (LoadController::LoadFrames): a tape loaded at once (under 1 MB) handed
// over after frame N is drawable before frame N + 1 and shown by it.
json load_frames_json(const LoadController::LoadFrames& lf) {
    return {{"at_once", lf.at_once},
            {"handed_frame", lf.handed},
            {"drawable_frame", lf.drawable},
            {"shown_frame", lf.shown},
            {"complete_frame", lf.complete},
            {"planned_frame", lf.planned},
            {"frames_to_show", lf.shown > 0 ? lf.shown - lf.handed : 0},
            {"steps", lf.steps},
            {"progress_frames", lf.progress_frames}};
}

// The view: its centre (program mm, and in the shown coordinates), zoom, turns, rotation and area.
// Screen position of a program point (x, y) in mm: d = R(rotation) (x - x_mm, y - y_mm);
// px = origin_px.x + d.x * zoom, py = origin_px.y - d.y * zoom (Automation::project).
json view_json(const View& view, Point o, const Coordinates& cs, const std::string& query) {
    const Rotation r = view.rotation();
    const Point shown_centre = cs.shown({view.cx + o.x, view.cy + o.y});
    return {{"x_mm", view.cx + o.x},
            {"y_mm", view.cy + o.y},
            {"zoom", view.zoom},
            {"turns", view.turns},
            {"coordinates", cs.name()},
            {"shown_mm", {shown_centre.x, shown_centre.y}},
            {"rotation", {r.c, r.s}},
            {"origin_px", {view.ox(), view.oy()}},
            {"area", {view.area.x, view.area.y, view.area.w, view.area.h}},
            {"query", query}};
}

// Compare mode's result: B's name, the summary, the differences (null: not comparing).
json compare_json(const Compare* c) {
    if (!c) return nullptr;
    json diffs = json::array();
    for (const ContourDiff& d : c->diff.contours) {
        if (d.change == ContourChange::Same) continue;
        const auto lines = [](const Contour& k) { return json::array({k.first_line, k.last_line}); };
        diffs.push_back({{"change", contour_change_name(d.change)},
                         {"a_lines", d.a >= 0 ? lines(c->a.contours[static_cast<std::size_t>(d.a)]) : json()},
                         {"b_lines", d.b >= 0 ? lines(c->b.contours[static_cast<std::size_t>(d.b)]) : json()},
                         {"offset_mm", {d.offset.x, d.offset.y}}});
    }
    return {{"name", c->name}, {"summary", c->summary}, {"differences", diffs}};
}

json encoding_json(const CommentText& comments) {
    return {{"detected", text_encoding_name(comments.detected())},
            {"chosen", comments.chosen() ? std::string(text_encoding_name(*comments.chosen())) : "auto"},
            {"used", text_encoding_name(comments.used())}};
}

// The panels' font atlas (render/UiFonts.hpp): its font size in device pixels, the ratio it was made for, its
// glyphs (of them from the CJK font), characters no font has, and the CJK font's state.
json fonts_json(const UiFonts& fonts, const UiRenderer& ui_renderer) {
    const UiFonts::Counts fc = fonts.counts();
    return {{"pixel_size", fonts.pixel_size()},
            {"ratio", fonts.pixel_ratio()},
            {"css_size", fonts.real_font() ? UiFonts::kCssPixels : fonts.pixel_size()},
            {"font", fonts.real_font() ? "DejaVu Sans" : "ProggyClean"},
            {"glyphs", fc.glyphs},
            {"cjk_glyphs", fc.cjk_glyphs},
            {"missing", fc.missing},
            {"cjk", UiFonts::cjk_name(fonts.cjk())},
            {"cjk_loads", fonts.cjk_loads()},
            {"builds", fonts.builds()},
            {"pending", fonts.pending()},
            {"texture", {ui_renderer.font_texture_size()[0], ui_renderer.font_texture_size()[1]}}};
}

json layout_json(const panels::PanelLayout& l) {
    return {{"left", l.left}, {"right", l.right}, {"left_shown", l.left_shown}, {"right_shown", l.right_shown}};
}

json kind_colors_json() {
    json colors = json::array();
    for (const Rgba& c : kKindColors)
        colors.push_back({std::lround(c.r * 255), std::lround(c.g * 255), std::lround(c.b * 255)});
    return colors;
}

// Where the load is: its status and progress, whether the tape is drawn, the frames begun so far.
void add_loading(json& j, const LoadController& load, bool has_document, const SceneAssembly& scene,
                 std::uint64_t frames) {
    j["status"] = load.loading() ? "loading" : has_document ? "ready" : "empty";
    if (load.loading()) {
        j["progress"] = load.progress();
        j["stage"] = tr(load.stage());
    }
    // The last frame drew the tape (its segments, or its level of detail while the segments are made), and how
    // long after the start of the load the first such frame came.
    j["drawn"] = scene.tape_drawn();
    // Work left after "ready" too: the finer level of detail of a big tape, a rebuild at another tolerance.
    j["busy"] = load.busy();
    j["shown_seconds"] = load.shown_seconds();
    j["frame"] = frames;
    j["load"] = load_frames_json(load.load_frames());
    // Where the last tape loaded in slices was read: "worker" (the reading worker), "page" (no worker, or it
    // failed: worker_failure says why).
    j["load"]["read_in"] = load.read_by_worker() && load.worker_failure().empty() ? "worker" : "page";
    j["load"]["worker_failure"] = load.worker_failure();
}

// The tape and how it is read (as `essi check --format json` says it), its document's numbers, its banner.
void add_reading(json& j, const Automation::Parts& p) {
    const Document* doc = p.session.document();
    const LoadController& load = p.load;
    j["name"] = doc ? doc->name : (load.reading() ? load.loading_name() : "");
    j["profile"] = p.session.profile_name();  // as asked: a built-in name or "auto"
    if (!doc) return;
    j["input"] = input_format_name(doc->setup.format);
    j["dialect"] = doc->profile.name;
    j["dialect_evidence"] = doc->setup.evidence;
    add_document(j, *doc, load, p.renderer, p.scene.lod_drawn());
    j["banner"] = p.session.banner_text();
}

// A page of the diagnostics (`diagnostics`, as the report writes them) and what the problems list shows of them:
// {total, offset, limit, shown, groups: [{code, severity, findings, kept, open, rect}]}.
void add_problems(json& j, const Document& doc, const UiState& ui, const LoadController& load, std::size_t shown,
                  ProblemPage page) {
    const std::size_t total = doc.diagnostics.size(), end = page.end(total);
    const std::size_t first = std::min(page.offset, total);
    j["diagnostics"] = diagnostics_to_json(std::span<const Diagnostic>(doc.diagnostics).subspan(first, end - first));
    json groups = json::array();
    const bool current = ui.problems_of == UiState::ProblemsOf{&doc, load.load_frames().handed, total};  // (as drawn)
    for (std::size_t g = 0; current && g < ui.problems.groups().size(); ++g) {
        const ProblemGroup& group = ui.problems.groups()[g];
        const Rect r = g < ui.group_rects.size() ? ui.group_rects[g] : Rect{0, 0, 0, 0};
        groups.push_back({{"code", code_name(group.code)},
                          {"severity", severity_name(group.severity)},
                          {"findings", group.total},
                          {"kept", group.members.size()},
                          {"open", g < ui.open_groups.size() && ui.open_groups[g]},
                          {"rect", {r.x, r.y, r.w, r.h}}});
    }
    j["problems"] = {{"total", total},
                     {"offset", page.offset},
                     {"limit", page.limit},
                     {"shown", shown < total ? json(shown) : json(nullptr)},
                     {"groups", std::move(groups)}};
}

// The windows, the messages and the panels' layout.
void add_panels(json& j, const Automation::Parts& p) {
    const UiState& ui = p.ui;
    j["help"] = ui.help;
    static constexpr const char* kKeyboardModes[] = {"mouse", "drawing", "panels"};
    j["keyboard"] = {{"mode", kKeyboardModes[static_cast<int>(ui.keyboard)]},
                     {"window", ui.keyboard_window},
                     {"list", ui.keyboard_list}};
    j["share_url"] = p.shares.text();
    j["link_problem"] = p.session.link_problem().text();
    j["copied"] = p.exports.copied();
    j["examples"] = ui.examples;
    j["recent"] = p.session.recent();
    j["theme"] = p.preferences.light_theme() ? "light" : "dark";
    j["layout"] = layout_json(ui.layout);
    j["message"] = p.notices.message().text();
    j["toolbar"] = toolbar_json(ui);
    j["compact"] = ui.compact;
    j["sheet"] = {{"open", ui.sheet.open}, {"tab", sheet_tab_name(ui.sheet.tab)}};
    json controls = json::object();
    for (const auto& [id, r] : ui.controls) controls[id] = {r.x, r.y, r.w, r.h};
    j["controls"] = std::move(controls);
    j["tooltip"] = ui.tooltip.w > 0 ? json{ui.tooltip.x, ui.tooltip.y, ui.tooltip.w, ui.tooltip.h} : json(nullptr);
}

// The Job panel's sections as they are shown: [{id, title, fields: [[label, value] ...], table: {columns, rows}}].
json job_json(Exports& exports) {
    json sections = json::array();
    for (const SheetSection& s : exports.job_sections()) {
        json fields = json::array();
        for (const SheetField& f : s.fields) fields.push_back({f.label, f.value});
        json section = {{"id", s.id}, {"title", s.title}, {"fields", fields}};
        if (s.table) section["table"] = {{"columns", s.table->columns}, {"rows", s.table->rows}};
        sections.push_back(std::move(section));
    }
    return sections;
}

}  // namespace

std::string Automation::state_json(ProblemPage page) const {
    json j;
    const Document* doc = p_.session.document();
    add_loading(j, p_.load, doc != nullptr, p_.scene, p_.session.frames());
    const WarmUp& w = p_.warm_up;
    j["warm_up"] = {{"state", warm_up_state_name(w.state())},
                    {"tapes", w.tapes()},
                    {"bytes", w.bytes()},
                    {"ms", std::lround(w.seconds() * 1000)}};
    add_reading(j, p_);
    if (doc) add_problems(j, *doc, p_.ui, p_.load, p_.navigation.problem(), page);
    const Selection& selection = p_.navigation.selection();
    const Coordinates cs = p_.navigation.coordinates();
    j["selection"] = selection_json(selection);
    j["view"] = view_json(p_.navigation.view(), p_.navigation.origin(), cs, p_.shares.query());
    j["layers"] = layers_json(p_.layers);
    j["problems_only"] = p_.layers.problems_only;
    j["colour_by"] = colour_by_json(p_.layers, p_.load);
    j["marks"] = doc ? marks_json(*doc, p_.navigation.view(), p_.ui.hovered_mark, selection.line) : json(nullptr);
    j["playback"] = playback_json(p_.playback, doc, p_.tape_facts, cs);
    j["measure"] = measure_json(p_.measure, cs);
    j["measure"]["window"] = p_.ui.measure_window.w > 0 ? rect(p_.ui.measure_window) : json(nullptr);
    j["inspector"] = inspector_json(doc, selection.line);
    j["render"] = render_json(p_.renderer.stats(), p_.scene.skipped_frames());
    add_panels(j, p_);
    j["compare"] = compare_json(p_.compare.result());
    j["compare_pending"] = p_.compare.pending();
    j["comment_encoding"] = encoding_json(p_.comments);
    if (doc && selection.line > 0) j["line_text"] = p_.comments.line_text(*doc, selection.line);
    j["fonts"] = fonts_json(p_.fonts, p_.ui_renderer);
    j["lang"] = lang_code(ui_lang());
    j["kind_colors"] = kind_colors_json();
    j["job"] = doc ? job_json(p_.exports) : json(nullptr);
    return j.dump();
}

std::string Automation::motion_json(std::size_t i) const {
    const Document* doc = p_.session.document();
    if (!doc || i >= doc->motions.size()) return "null";
    const MotionRecord r = doc->record(i);
    json j = {{"index", i},
              {"line", r.line},
              {"block", doc->block_of(i)},
              {"kind", motion_kind_name(r.kind)},
              {"curve", curve_kind_name(r.curve)},
              {"start", {r.start.x, r.start.y}},
              {"end", {r.end.x, r.end.y}},
              {"mid", {point_at(r, 0.5).x, point_at(r, 0.5).y}},
              {"length_mm", r.length_mm},
              {"centre", r.curve == CurveKind::Arc ? json{r.centre.x, r.centre.y} : json(nullptr)},
              {"text", describe_motion(r, ui_lang())}};
    return j.dump();
}

Point Automation::project(double x, double y) const {
    const Point o = p_.navigation.origin();
    return p_.navigation.view().to_screen({x - o.x, y - o.y});
}

}  // namespace essi::viewer
