#include "app/App.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

#include "essi/diagnostics.hpp"
#include "essi/geom.hpp"
#include "essi/profile.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer {

namespace {

App* g_app = nullptr;

constexpr float kToolbarHeight = 38;
// The toolbar and the side panels draw no background: the renderer clears the window in their colour (ImGui's
// window background over the drawing's, as they looked), which saves SwiftShader filling a million pixels a frame.
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoBackground;
constexpr float kLeftWidth = 310;
constexpr float kRightWidth = 470;
constexpr double kPickRadiusPx = 6;
constexpr double kSnapRadiusPx = 10;
constexpr std::size_t kBuildMotionsPerFrame = 200000;  // tapes up to this size are drawn in the loading frame
constexpr std::size_t kBuildMotionsPerStep = 4096;  // between two looks at the clock (and texture uploads)
constexpr float kProgressSteps = 50;  // progress is shown in 2 % steps (stepped())
constexpr double kStepBudgetMs = 30;  // work per frame while loading (the page keeps drawing)
// Tapes with at least this many motions get a level-of-detail raster for zoomed-out views (below, drawing every
// segment costs a CPU renderer less than a frame or two).
constexpr std::size_t kLodMinMotions = 100000;
// The first level of detail has the cells the view needs when the tape's own (LodRaster::cells_for) are more than
// this many times those; the finer one follows once the segments are made.
constexpr double kLodRefineRatio = 1.5;
// Share links longer than this are refused (browsers and chat programs cut long URLs).
constexpr std::size_t kMaxShareTapeBytes = 4u << 20;

std::string fmt(const char* format, auto... args) {
    char buf[1024];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

std::string hms(double seconds) {
    const long s = static_cast<long>(std::llround(seconds));
    return fmt("%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
}

// A progress (0..1) as shown: in steps of 1 / kProgressSteps, so that a frame whose panels did not change is not
// drawn again (render()); on a CPU renderer every frame drawn is time the browser's compositor takes from the work.
float stepped(float progress) { return std::floor(progress * kProgressSteps) / kProgressSteps; }

// A file size as people read it: "840 bytes", "12.4 KB", "133.5 MB".
std::string size_text(std::size_t bytes) {
    if (bytes < 1024) return fmt("%zu bytes", bytes);
    if (bytes < 1024 * 1024) return fmt("%.1f KB", static_cast<double>(bytes) / 1024.0);
    return fmt("%.1f MB", static_cast<double>(bytes) / 1048576.0);
}

ImU32 to_u32(Rgba c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }

// What the panels looked like with their own background: ImGui's window background blended over the drawing's
// background, in the 8-bit steps the GPU blends in (the same pixels).
Rgba panel_color() {
    const auto byte = [](float v) { return std::round(std::clamp(v, 0.f, 1.f) * 255.f) / 255.f; };
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    const float a = byte(bg.w);
    const auto over = [&](float top, float below) { return byte(top) * a + byte(below) * (1 - a); };
    return {over(bg.x, kBackground.r), over(bg.y, kBackground.g), over(bg.z, kBackground.b), 1.f};
}

ImVec4 severity_color(Severity s) {
    switch (s) {
        case Severity::Error: return ImVec4(1.0f, 0.4f, 0.35f, 1);
        case Severity::Warning: return ImVec4(1.0f, 0.8f, 0.3f, 1);
        default: return ImVec4(0.6f, 0.8f, 1.0f, 1);
    }
}

// Grid step (mm) so that minor lines are at least `px` apart: 1, 2, 5 x 10^k.
double grid_step(double zoom, double px = 12) {
    const double raw = px / zoom;
    const double e = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * e >= raw) return m * e;
    return 10 * e;
}

double seg_distance(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

// Printable form of a source line (binary files must not break the text renderer).
std::string printable(std::string_view s, std::size_t max = 400) {
    std::string out;
    out.reserve(std::min(s.size(), max));
    for (std::size_t i = 0; i < s.size() && i < max; ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        out.push_back(c == '\t' ? ' ' : (c < 0x20 || c >= 0x7F) ? '?' : static_cast<char>(c));
    }
    if (s.size() > max) out += " ...";
    return out;
}

nlohmann::json box_json(const Box& b) {
    if (b.empty) return nullptr;
    return {{"min_x", b.min_x}, {"min_y", b.min_y}, {"max_x", b.max_x}, {"max_y", b.max_y}};
}

bool looks_binary(std::string_view bytes) {
    const std::size_t n = std::min<std::size_t>(bytes.size(), 4096);
    std::size_t bad = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned char c = static_cast<unsigned char>(bytes[i]);
        if (c == 0) return true;
        if (c < 0x09 || (c > 0x0D && c < 0x20)) ++bad;
    }
    return n > 0 && bad * 20 > n;
}

}  // namespace

App::App(GLFWwindow* window) : window_(window) { g_app = this; }
App::~App() {
    if (g_app == this) g_app = nullptr;
}
App* App::instance() { return g_app; }

bool App::init_graphics() {
    graphics_ok_ = renderer_.init();
    ImGuiIO& io = ImGui::GetIO();
    if (!io.Fonts->IsBuilt()) io.Fonts->Build();  // (renderer_.init() makes the atlas unless the GPU refused it)
    io.IniFilename = nullptr;  // no imgui.ini: the layout is fixed
    ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0;
    st.FrameRounding = 3;
    st.WindowBorderSize = 0;
    return graphics_ok_;
}

// ---------------------------------------------------------------------------------------------------------
// Loading
// ---------------------------------------------------------------------------------------------------------
void App::load(std::string name, std::string bytes, std::optional<ViewRequest> view) {
    auto profile = builtin_profile(profile_name_);
    if (!profile) profile = builtin_profile("iso6582");
    loading_name_ = name;
    loading_bytes_ = bytes.size();
    loader_ = std::make_unique<DocumentLoader>(std::move(name), std::move(bytes), *profile);
    pending_view_ = view;
    frames_since_load_start_ = 0;
    load_started_ = glfwGetTime();
    playing_ = false;
    playback_ = false;
    measure_count_ = 0;
}

void App::step_loading() {
    if (loader_) {
        // First frame: only show the progress bar; then about kStepBudgetMs of work per frame.
        if (frames_since_load_start_++ == 0) return;
        if (loader_->step(kStepBudgetMs)) {
            doc_ = loader_->take();
            loader_.reset();
            finish_loading();
        }
        return;
    }
    const double until = glfwGetTime() + kStepBudgetMs / 1000.0;
    // A big tape's level of detail goes first (one pass over the motions, arcs at a chord of a quarter cell), with
    // the cells the view needs: the fitted view shows the tape from it while the exact segments are made. The
    // finer one (LodRaster::cells_for, for zooms between the fit and the segments) is made after them; a rebuild
    // at another tolerance goes before it.
    if (lod_building_ && (first_build_ || !building_)) {
        bool done = false;
        while (!done && glfwGetTime() < until) done = lod_.step(kBuildMotionsPerStep);
        if (!done) return;
        lod_building_ = false;
        lod_.finish();
        if (graphics_ok_) renderer_.upload_lod(lod_);
        lod_.release();  // the GPU has it
    }
    if (building_) {
        // Flatten and upload in the same slice: the segments go to the GPU a few texture rows at a time, so
        // no frame builds or uploads the whole stream (and no CPU copy of it is kept).
        bool done = false;
        while (!done && glfwGetTime() < until) {
            done = building_->step(kBuildMotionsPerStep);
            if (graphics_ok_) renderer_.append(gpu_building_, *building_);
            else building_->drop_staged(building_->staged_count());
        }
        if (done) {
            buffers_ = std::move(*building_);
            building_.reset();
            buffers_.release_staging();
            renderer_.release(gpu_);
            gpu_ = std::move(gpu_building_);
            gpu_building_ = GpuPath{};
            if (first_build_) {
                first_build_ = false;
                load_seconds_ = glfwGetTime() - load_started_;
                if (lod_cells_ > 0 && lod_cells_ < lod_full_cells_) {  // the finer level of detail
                    lod_.begin(*doc_, lod_full_cells_);
                    lod_cells_ = lod_full_cells_;
                    lod_building_ = lod_.active();
                }
            }
        }
    }
}

bool App::background_step() {
    // Not before the first frame of a load has shown the progress bar.
    if (loader_ && frames_since_load_start_ == 0) return true;
    step_loading();
    return has_background_work();
}

void App::finish_loading() {
    Document& d = *doc_;
    selected_line_ = 0;
    selected_motion_ = npos;
    banner_.clear();
    if (d.bytes.empty()) {
        banner_ = "The file is empty: there is nothing to draw.";
    } else if (looks_binary(d.bytes)) {
        banner_ = "This is a binary file, not an ESSI tape (ESSI tapes are text: + - digits and line ends).";
    } else if (d.motions.empty() && d.has_errors()) {
        banner_ = fmt("This does not look like an ESSI tape: %zu errors and no motion. The first: line %u: %s",
                      d.count(Severity::Error), d.diagnostics.front().line, d.diagnostics.front().message.c_str());
    } else if (d.motions.empty()) {
        banner_ = "The tape has no motion: there is nothing to draw.";
    }
    view_.fit(d.bbox, d.origin);
    if (pending_view_) {
        const ViewRequest v = *pending_view_;
        if (v.zoom > 0) {
            view_.zoom = std::clamp(v.zoom, View::kMinZoom, View::kMaxZoom);
            view_.cx = v.x - d.origin.x;
            view_.cy = v.y - d.origin.y;
        }
        if (v.line > 0) select_line(v.line, false);
        pending_view_.reset();
    }
    play_pos_ = static_cast<double>(d.motions.size());
    renderer_.release(gpu_);
    renderer_.release(gpu_building_);
    buffers_ = PathBuffers{};
    building_ = std::make_unique<PathBuffers>();
    building_->begin(d, desired_tolerance());
    if (graphics_ok_) renderer_.upload_markers(building_->markers);
    building_->markers = std::vector<MarkerInstance>();  // (the GPU has them)
    renderer_.clear_lod();
    lod_ = LodRaster{};
    lod_building_ = false;
    lod_cells_ = lod_full_cells_ = 0;
    if (d.motions.size() >= kLodMinMotions && !d.bbox.empty) {
        // First the cells the view needs (a cell at most a pixel, as the renderer draws it), when that is well
        // below what the tape's motions allow (samples scale with the cells: 0.4 of them for a big tape fitted here).
        const double w = d.bbox.max_x - d.bbox.min_x, h = d.bbox.max_y - d.bbox.min_y;
        lod_full_cells_ = LodRaster::cells_for(w, h, d.motions.size());
        const double scale = ImGui::GetIO().DisplayFramebufferScale.x > 0 ? ImGui::GetIO().DisplayFramebufferScale.x : 1.0;
        const double view_cells = std::max(w, h) * view_.zoom * scale / Renderer::kLodMaxCellPx + 2;
        lod_cells_ = view_cells * kLodRefineRatio < lod_full_cells_
                         ? std::max(LodRaster::kMinCells, static_cast<int>(std::ceil(view_cells)))
                         : lod_full_cells_;
        lod_.begin(d, lod_cells_);
        lod_building_ = lod_.active();
    }
    first_build_ = true;
    shown_seconds_ = 0;
    // Small tapes: build at once so the first frame after loading shows the drawing.
    if (d.motions.size() <= kBuildMotionsPerFrame) step_loading();
}

bool App::loading() const { return loader_ || ((lod_building_ || building_) && first_build_); }

// Reading and checking up to 0.7, then the level of detail (big tapes) and the segments.
float App::load_progress() const {
    if (loader_) return loader_->progress();
    if (lod_building_ && first_build_) return 0.7f + 0.1f * lod_.progress();
    const float from = renderer_.has_lod() ? 0.8f : 0.7f;
    return building_ ? from + (1.f - from) * building_->progress() : 1.f;
}

const char* App::load_stage() const {
    if (loader_) return loader_->stage();
    if (lod_building_ && first_build_) return "drawing the overview";
    return "building the drawing";
}

double App::desired_tolerance() const {
    // A quarter pixel at the current zoom, never finer than the core allows.
    return std::max(0.25 / view_.zoom, kMinChordTolerance);
}

void App::maybe_rebuild() {
    if (!doc_ || loader_ || building_ || doc_->curves == 0) return;
    const double want = desired_tolerance();
    const double have = buffers_.tolerance();
    // Finer when zooming in past 2x; coarser (fewer segments) when zooming out by 16x.
    if (have > want * 2 || have < want / 16) {
        renderer_.release(gpu_building_);
        building_ = std::make_unique<PathBuffers>();
        building_->begin(*doc_, want);
        if (doc_->motions.size() <= kBuildMotionsPerFrame) step_loading();
    }
}

// ---------------------------------------------------------------------------------------------------------
// Frame
// ---------------------------------------------------------------------------------------------------------
void App::frame() {
    ImGuiIO& io = ImGui::GetIO();
    view_.area = Rect{kLeftWidth, kToolbarHeight, std::max(io.DisplaySize.x - kLeftWidth - kRightWidth, 50.f),
                      std::max(io.DisplaySize.y - kToolbarHeight, 50.f)};
    step_loading();
    if (playing_ && doc_) {
        play_pos_ += play_speed_ * io.DeltaTime;
        if (play_pos_ >= static_cast<double>(doc_->motions.size())) {
            play_pos_ = static_cast<double>(doc_->motions.size());
            playing_ = false;
        }
    }
    handle_shortcuts();
    handle_canvas_input();
    maybe_rebuild();

    draw_toolbar();
    draw_left_panel();
    draw_right_panel();
    draw_overlays();
    draw_messages();
    if (show_help_) draw_help();

    // The scene (drawn by render(), below the panels)
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window_, &fb_w, &fb_h);
    scene_.reset();
    if (graphics_ok_ && fb_w > 0 && fb_h > 0) {
        DrawOptions o;
        o.framebuffer_scale = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.f;
        o.layer_mask = layer_mask();
        o.panel_color = panel_color();
        // Zoomed out on a big tape: the level-of-detail raster instead of millions of sub-pixel segments (also
        // while the first build makes the exact segments: the raster is made before them).
        // While a big tape's segments are made again at a new zoom's tolerance (seconds), the raster stands in for
        // them: filling the image with the segments about to be replaced would only delay the new ones.
        o.lod = !playback_ && renderer_.has_lod() &&
                (renderer_.lod_cell_mm() * view_.zoom * o.framebuffer_scale <= Renderer::kLodMaxCellPx || remaking());
        lod_drawn_ = o.lod;
        // While the first build runs nothing else of the new tape is drawn (the frames stay cheap).
        o.marker_mask = first_build_ && !o.lod ? 0 : (show_pierces_ ? 1 : 0) | (show_start_ ? 2 : 0);
        if (doc_ && buffers_.first_segment.size() == doc_->motions.size() + 1) {
            if (playback_) {
                const std::size_t k = playback_limit_motions();
                o.segment_limit = buffers_.first_segment[k];
                const std::size_t cur = std::min<std::size_t>(static_cast<std::size_t>(play_pos_), doc_->motions.size());
                if (!doc_->motions.empty()) {
                    const std::size_t mi = std::min(cur, doc_->motions.size() - 1);
                    const double frac = cur >= doc_->motions.size() ? 1.0 : play_pos_ - std::floor(play_pos_);
                    const Point p = point_at(doc_->record(mi), frac);
                    o.has_tool = true;
                    o.tool = {p.x - doc_->origin.x, p.y - doc_->origin.y};
                }
            }
            const auto [first, count] = selection_segments();
            o.selection_first = first;
            o.selection_count = count;
        }
        const GpuPath* path = first_build_ ? nullptr : &gpu_;
        tape_drawn_ = doc_ && (o.lod || path != nullptr);
        if (tape_drawn_ && shown_seconds_ == 0) shown_seconds_ = glfwGetTime() - load_started_;
        scene_ = SceneFrame{view_, fb_w, fb_h, o, show_grid_ ? grid_step(view_.zoom) : 1e30,
                            doc_ ? doc_->origin : Point{}, path, path ? path->version : 0};
    }
}

namespace {
// A fingerprint of ImGui's draw data: the vertices, indices and commands of every list.
std::uint64_t ui_hash(const ImDrawData& data) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over 8-byte words
    const auto mix = [&h](const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        std::uint64_t w = 0;
        for (std::size_t i = 0; i + 8 <= n; i += 8) {
            std::memcpy(&w, b + i, 8);
            h = (h ^ w) * 1099511628211ull;
        }
        for (std::size_t i = n - n % 8; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    };
    mix(&data.DisplaySize, sizeof data.DisplaySize);
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        mix(list.VtxBuffer.Data, static_cast<std::size_t>(list.VtxBuffer.Size) * sizeof(ImDrawVert));
        mix(list.IdxBuffer.Data, static_cast<std::size_t>(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& c : list.CmdBuffer) {
            mix(&c.ClipRect, sizeof c.ClipRect);
            const auto texture = reinterpret_cast<std::uintptr_t>(c.GetTexID());
            mix(&texture, sizeof texture);
            const unsigned counts[2] = {c.ElemCount, c.IdxOffset};
            mix(counts, sizeof counts);
        }
    }
    return h;
}
}  // namespace

void App::render(bool keep_unchanged) {
    if (!graphics_ok_) return;
    const ImDrawData& ui = *ImGui::GetDrawData();
    const std::uint64_t hash = ui_hash(ui);
    if (keep_unchanged && scene_ && scene_ == last_scene_ && hash == last_ui_hash_ && !renderer_.filling()) {
        ++skipped_frames_;
        return;
    }
    if (scene_) {
        const SceneFrame& s = *scene_;
        renderer_.draw(s.view, s.fb_w, s.fb_h, s.options, s.grid_step, s.origin, s.path);
    }
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window_, &fb_w, &fb_h);
    renderer_.draw_ui(ui, fb_w, fb_h);
    last_scene_ = scene_;
    last_ui_hash_ = hash;
}

int App::layer_mask() const {
    int m = 0;
    for (int k = 0; k < 4; ++k)
        if (show_kind_[k]) m |= 1 << k;
    return m;
}

std::size_t App::playback_limit_motions() const {
    if (!doc_) return 0;
    const std::size_t n = doc_->motions.size();
    if (!playback_) return n;
    return std::min(n, static_cast<std::size_t>(std::ceil(play_pos_)));
}

std::pair<std::size_t, std::size_t> App::selection_segments() const {
    if (!doc_ || buffers_.first_segment.size() != doc_->motions.size() + 1) return {0, 0};
    std::size_t a = npos, b = npos;
    if (selected_motion_ != npos) {
        a = selected_motion_;
        b = selected_motion_ + 1;
    } else if (selected_line_ > 0) {
        const auto [ma, mb] = doc_->motions_of_line(selected_line_);
        if (ma < mb) {
            a = ma;
            b = mb;
        }
    }
    if (a == npos) return {0, 0};
    return {buffers_.first_segment[a], buffers_.first_segment[b] - buffers_.first_segment[a]};
}

void App::fit() {
    if (doc_) view_.fit(doc_->bbox, doc_->origin);
}

void App::set_view(double x, double y, double zoom) {
    if (loader_ || !doc_) {
        ViewRequest v = pending_view_.value_or(ViewRequest{});
        v.x = x;
        v.y = y;
        v.zoom = zoom;
        pending_view_ = v;
        return;
    }
    view_.zoom = std::clamp(zoom, View::kMinZoom, View::kMaxZoom);
    view_.cx = x - doc_->origin.x;
    view_.cy = y - doc_->origin.y;
}

void App::set_layer(int kind, bool visible) {
    if (kind >= 0 && kind < 4) show_kind_[kind] = visible;
    if (kind == 4) show_pierces_ = visible;
    if (kind == 5) show_start_ = visible;
}

void App::select_line(std::uint32_t line, bool reveal) {
    if (loader_ || !doc_) {
        ViewRequest v = pending_view_.value_or(ViewRequest{});
        v.line = line;
        pending_view_ = v;
        return;
    }
    selected_line_ = line;
    selected_motion_ = npos;
    scroll_source_ = true;
    scroll_diagnostics_ = true;
    const auto [a, b] = doc_->motions_of_line(line);
    if (a < b) {
        selected_motion_ = a;
        if (reveal) {
            Box box;
            for (std::size_t i = a; i < b; ++i) box.add(bounding_box(doc_->record(i)));
            const Point p0 = view_.to_screen({box.min_x - doc_->origin.x, box.max_y - doc_->origin.y});
            const Point p1 = view_.to_screen({box.max_x - doc_->origin.x, box.min_y - doc_->origin.y});
            const Rect& r = view_.area;
            const bool inside = p0.x >= r.x && p0.y >= r.y && p1.x <= r.x + r.w && p1.y <= r.y + r.h;
            if (!inside) {
                view_.cx = (box.min_x + box.max_x) / 2 - doc_->origin.x;
                view_.cy = (box.min_y + box.max_y) / 2 - doc_->origin.y;
            }
        }
    }
}

void App::select_motion(std::size_t motion) {
    if (!doc_ || motion >= doc_->motions.size()) {
        selected_motion_ = npos;
        selected_line_ = 0;
        return;
    }
    selected_motion_ = motion;
    selected_line_ = doc_->motions[motion].line;
    scroll_source_ = true;
    scroll_diagnostics_ = true;
}

void App::notify(std::string text) {
    message_ = std::move(text);
    message_until_ = glfwGetTime() + 4;
}

// ---------------------------------------------------------------------------------------------------------
// Input
// ---------------------------------------------------------------------------------------------------------
// The motion under the cursor, from the exact geometry (the segments live on the GPU only).
std::size_t App::pick(double sx, double sy) const {
    if (!doc_ || doc_->motions.empty()) return npos;
    const Document& d = *doc_;
    const Point w = view_.to_world(sx, sy);
    const Point p{w.x + d.origin.x, w.y + d.origin.y};
    const double tol = kPickRadiusPx / view_.zoom;
    const std::size_t limit = playback_limit_motions();
    const int mask = layer_mask();
    double best = tol;
    std::size_t best_motion = npos;
    std::vector<Point> pts;
    auto consider = [&](std::size_t i, double dist) {
        // Prefer cut and mark over travel when they overlap (<=: a later cut wins ties)
        if (dist < best || (dist <= best + 1e-9 && d.motions[i].kind >= MotionKind::Cut)) {
            best = dist;
            best_motion = i;
        }
    };
    for (std::size_t i = 0; i < limit; ++i) {
        const Motion& m = d.motions[i];
        if (!((mask >> static_cast<int>(m.kind)) & 1)) continue;
        if (m.curve == CurveKind::Line) {
            const Point a = d.start_of(i), e = d.end_of(i);
            if (p.x < std::min(a.x, e.x) - best || p.x > std::max(a.x, e.x) + best) continue;
            if (p.y < std::min(a.y, e.y) - best || p.y > std::max(a.y, e.y) + best) continue;
            consider(i, seg_distance(p.x, p.y, a.x, a.y, e.x, e.y));
            continue;
        }
        if (m.curve == CurveKind::Arc) {  // the ring between the two radii, before the whole record
            const Point c = d.arc_centre(i), a = d.start_of(i), e = d.end_of(i);
            const double rc = std::hypot(p.x - c.x, p.y - c.y);
            const double r0 = std::hypot(a.x - c.x, a.y - c.y), r1 = std::hypot(e.x - c.x, e.y - c.y);
            if (rc < std::min(r0, r1) - best || rc > std::max(r0, r1) + best) continue;
        }
        const MotionRecord r = d.record(i);
        pts.clear();
        flatten(r, std::max(0.25 / view_.zoom, kMinChordTolerance), pts, true);
        double dist = 1e300;
        for (std::size_t k = 1; k < pts.size(); ++k)
            dist = std::min(dist, seg_distance(p.x, p.y, pts[k - 1].x, pts[k - 1].y, pts[k].x, pts[k].y));
        consider(i, dist);
    }
    return best_motion;
}

Point App::snap(double sx, double sy, bool* snapped) const {
    const Point w = view_.to_world(sx, sy);  // relative to origin
    *snapped = false;
    const Point o = doc_ ? doc_->origin : Point{};
    Point result = {w.x + o.x, w.y + o.y};
    if (!doc_) return result;
    double best = kSnapRadiusPx / view_.zoom;
    auto consider = [&](Point p) {
        const double d = std::hypot(p.x - o.x - w.x, p.y - o.y - w.y);
        if (d < best) {
            best = d;
            result = p;
            *snapped = true;
        }
    };
    // End points (every start is the end before it, or a jump) and arc centres.
    const Document& d = *doc_;
    for (std::size_t i = 0; i < d.motions.size(); ++i) consider(d.end_of(i));
    for (const auto& j : d.jumps) consider(j.second);
    for (const UnitPoint& c : d.arc_centres) consider(d.point_mm(c));
    for (const auto& k : d.kept)
        if (k.second.curve == CurveKind::Arc) consider(k.second.centre);
    return result;
}

void App::handle_shortcuts() {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;
    for (int i = 0; i < io.InputQueueCharacters.Size; ++i) {
        const ImWchar c = io.InputQueueCharacters[i];
        switch (c) {
            case 'f': case 'F': fit(); break;
            case 'h': case 'H': case '?': show_help_ = !show_help_; break;
            case 'm': case 'M':
                measure_mode_ = !measure_mode_;
                measure_count_ = 0;
                break;
            case ' ':
                if (doc_) {
                    if (!playback_ || play_pos_ >= static_cast<double>(doc_->motions.size())) play_pos_ = 0;
                    playback_ = true;
                    playing_ = !playing_;
                }
                break;
            case '+': case '=': view_.zoom_at(view_.ox(), view_.oy(), 1.25); break;
            case '-': view_.zoom_at(view_.ox(), view_.oy(), 1 / 1.25); break;
            case 'g': case 'G': show_grid_ = !show_grid_; break;
            case 's': case 'S': start_share(); break;
            case '1': show_kind_[2] = !show_kind_[2]; break;
            case '2': show_kind_[1] = !show_kind_[1]; show_kind_[0] = show_kind_[1]; break;
            case '3': show_kind_[3] = !show_kind_[3]; break;
            case '4': show_pierces_ = !show_pierces_; break;
            default: break;
        }
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        if (measure_mode_) {
            measure_mode_ = false;
            measure_count_ = 0;
        } else if (show_help_) {
            show_help_ = false;
        } else {
            selected_motion_ = npos;
            selected_line_ = 0;
        }
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_F1)) show_help_ = !show_help_;
    if (doc_ && !doc_->motions.empty()) {
        const double n = static_cast<double>(doc_->motions.size());
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) {
            playback_ = true;
            playing_ = false;
            play_pos_ = std::min(n, std::floor(play_pos_) + 1);
        }
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) {
            playback_ = true;
            playing_ = false;
            play_pos_ = std::max(0.0, std::ceil(play_pos_) - 1);
        }
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Home))) {
            playback_ = true;
            play_pos_ = 0;
        }
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_End))) {
            play_pos_ = n;
            playback_ = false;
            playing_ = false;
        }
    }
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_O)) platform::open_file_dialog(*this);
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_V)) platform::paste(*this);
}

void App::handle_canvas_input() {
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 mp = io.MousePos;
    const bool over = view_.area.contains(mp.x, mp.y) && !io.WantCaptureMouse;
    if (over && io.MouseWheel != 0) view_.zoom_at(mp.x, mp.y, std::pow(1.2, io.MouseWheel));
    if (over && ImGui::IsMouseClicked(0)) {
        press_in_canvas_ = true;
        dragging_ = false;
        press_x_ = mp.x;
        press_y_ = mp.y;
    }
    if (press_in_canvas_ && ImGui::IsMouseDown(0)) {
        if (!dragging_ && std::hypot(mp.x - press_x_, mp.y - press_y_) > 3) dragging_ = true;
        if (dragging_) {
            view_.cx -= io.MouseDelta.x / view_.zoom;
            view_.cy += io.MouseDelta.y / view_.zoom;
        }
    }
    if (press_in_canvas_ && ImGui::IsMouseReleased(0)) {
        press_in_canvas_ = false;
        if (!dragging_) {
            if (measure_mode_) {
                bool snapped = false;
                const Point p = snap(mp.x, mp.y, &snapped);
                if (measure_count_ != 1) {
                    measure_a_ = p;
                    measure_count_ = 1;
                } else {
                    measure_b_ = p;
                    measure_count_ = 2;
                }
            } else {
                const std::size_t m = pick(mp.x, mp.y);
                if (m != npos) select_motion(m);
                else {
                    selected_motion_ = npos;
                    selected_line_ = 0;
                }
            }
        }
        dragging_ = false;
    }
    // Right button or middle button drag pans too.
    if (over && (ImGui::IsMouseDragging(1) || ImGui::IsMouseDragging(2))) {
        view_.cx -= io.MouseDelta.x / view_.zoom;
        view_.cy += io.MouseDelta.y / view_.zoom;
    }
}

// ---------------------------------------------------------------------------------------------------------
// Share
// ---------------------------------------------------------------------------------------------------------
std::string App::view_query() const {
    const double x = view_.cx + (doc_ ? doc_->origin.x : 0);
    const double y = view_.cy + (doc_ ? doc_->origin.y : 0);
    return fmt("c=%.6g,%.6g,%.6g&l=%u", x, y, view_.zoom, selected_line_);
}

void App::start_share() {
    if (!doc_) {
        notify("Load a tape first.");
        return;
    }
    if (!platform::has_share_links()) {
        notify("Share links are made by the browser viewer.");
        return;
    }
    if (doc_->bytes.size() > kMaxShareTapeBytes) {
        share_done(false, fmt("This tape (%.1f MB) is too large for a link (at most %.0f MB); send the file instead.",
                              doc_->bytes.size() / 1048576.0, kMaxShareTapeBytes / 1048576.0));
        return;
    }
    platform::share(*this, doc_->name, doc_->bytes, view_query());
}

void App::share_done(bool ok, std::string text) {
    share_url_ = std::move(text);
    share_popup_ = true;
    if (ok) notify("Share link copied to the clipboard.");
    else notify(share_url_);
    if (!ok) share_popup_ = true;
}

// ---------------------------------------------------------------------------------------------------------
// Panels
// ---------------------------------------------------------------------------------------------------------
void App::draw_toolbar() {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kToolbarHeight));
    ImGui::Begin("##toolbar", nullptr, kPanelFlags | ImGuiWindowFlags_NoDecoration);
    if (ImGui::Button("Open...")) platform::open_file_dialog(*this);
    platform::open_button_at(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                             ImGui::GetItemRectSize().y);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Open a tape (Ctrl+O). You can also drop a file or paste text (Ctrl+V).");
    ImGui::SameLine();
    if (ImGui::Button("Paste")) platform::paste(*this);
    ImGui::SameLine();
    if (ImGui::Button("Share link")) start_share();
    ImGui::SameLine();
    if (ImGui::Button("Fit (F)")) fit();
    ImGui::SameLine();
    if (ImGui::Checkbox("Measure (M)", &measure_mode_)) measure_count_ = 0;
    ImGui::SameLine();
    if (ImGui::Button("Help (H)")) show_help_ = !show_help_;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    if (ImGui::BeginCombo("##profile", profile_name_.c_str())) {
        for (const std::string& n : builtin_profile_names()) {
            if (ImGui::Selectable(n.c_str(), n == profile_name_) && n != profile_name_) {
                profile_name_ = n;
                if (doc_) {
                    const ViewRequest keep{view_.cx + doc_->origin.x, view_.cy + doc_->origin.y, view_.zoom, selected_line_};
                    load(doc_->name, doc_->bytes, keep);
                }
            }
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Machine and dialect profile");
    ImGui::SameLine();
    if (doc_) {
        const std::size_t e = doc_->count(Severity::Error), w = doc_->count(Severity::Warning);
        ImGui::TextUnformatted(doc_->name.c_str());
        ImGui::SameLine();
        if (e == 0 && w == 0) ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1), "ok");
        else if (e == 0) ImGui::TextColored(severity_color(Severity::Warning), "ok, %zu warning%s", w, w == 1 ? "" : "s");
        else ImGui::TextColored(severity_color(Severity::Error), "%zu error%s, %zu warning%s", e, e == 1 ? "" : "s", w, w == 1 ? "" : "s");
    }
    if (!message_.empty() && glfwGetTime() < message_until_) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(0.6f, 0.85f, 1, 1), "  %s", message_.c_str());
    }
    ImGui::End();
}

void App::draw_left_panel() {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, kToolbarHeight));
    ImGui::SetNextWindowSize(ImVec2(kLeftWidth, io.DisplaySize.y - kToolbarHeight));
    ImGui::Begin("Tape", nullptr, kPanelFlags | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (!doc_) {
            ImGui::TextDisabled("No tape loaded.");
        } else {
            const Stats& s = doc_->stats;
            if (ImGui::BeginTable("stats", 2)) {
                // The names as wide as the longest; the values in the rest, wrapped (the boxes do not fit a line).
                ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
                ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
                auto row = [](const char* k, const std::string& v) {
                    ImGui::TableNextRow();
                    ImGui::TableNextColumn();
                    ImGui::TextUnformatted(k);
                    ImGui::TableNextColumn();
                    ImGui::TextWrapped("%s", v.c_str());
                };
                row("cut", fmt("%.3f mm", s.cut_length_mm));
                row("mark", fmt("%.3f mm", s.mark_length_mm));
                row("travel", fmt("%.3f mm", s.travel_length_mm));
                row("  of it rapid", fmt("%.3f mm", s.rapid_length_mm));
                row("pierces", fmt("%llu", s.pierces));
                row("blocks", fmt("%llu", s.blocks));
                row("motions", fmt("%llu", s.motions));
                row("time", hms(s.estimated_time_s));
                if (!s.cut_bbox.empty) {
                    row("cut extent", fmt("%.1f x %.1f mm", s.cut_bbox.max_x - s.cut_bbox.min_x, s.cut_bbox.max_y - s.cut_bbox.min_y));
                    row("cut box", fmt("(%.1f, %.1f) - (%.1f, %.1f)", s.cut_bbox.min_x, s.cut_bbox.min_y, s.cut_bbox.max_x, s.cut_bbox.max_y));
                }
                if (!s.motion_bbox.empty)
                    row("motion box", fmt("(%.1f, %.1f) - (%.1f, %.1f)", s.motion_bbox.min_x, s.motion_bbox.min_y, s.motion_bbox.max_x, s.motion_bbox.max_y));
                row("end", fmt("(%.3f, %.3f)", s.end_position.x, s.end_position.y));
                row("profile", doc_->profile.name);
                ImGui::EndTable();
            }
            const std::string about =
                building_ && first_build_  // (the segments are still being made: none to count yet)
                    ? fmt("%s, %zu lines, segments being made (%.0f %%)", size_text(doc_->bytes.size()).c_str(),
                          doc_->line_count(), 100.0 * stepped(building_->progress()))
                    : fmt("%s, %zu lines, %zu segments, loaded in %.2f s", size_text(doc_->bytes.size()).c_str(),
                          doc_->line_count(), buffers_.segment_count, load_seconds_);
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            ImGui::TextWrapped("%s", about.c_str());
            ImGui::PopStyleColor();
        }
    }
    if (ImGui::CollapsingHeader("Layers", ImGuiTreeNodeFlags_DefaultOpen)) {
        static const char* names[4] = {"rapid", "travel", "cut", "mark"};
        int col = 0;
        for (int k : {2, 3, 1, 0}) {
            const Rgba c = kKindColors[k];
            if (col++ % 2 == 1) ImGui::SameLine(150);
            ImGui::ColorButton(fmt("##c%d", k).c_str(), ImVec4(c.r, c.g, c.b, 1), ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
            ImGui::SameLine();
            ImGui::Checkbox(names[k], &show_kind_[k]);
        }
        ImGui::Checkbox("pierces", &show_pierces_);
        ImGui::SameLine();
        ImGui::Checkbox("start", &show_start_);
        ImGui::SameLine();
        ImGui::Checkbox("grid", &show_grid_);
    }
    if (ImGui::CollapsingHeader("Playback", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (!doc_ || doc_->motions.empty()) {
            ImGui::TextDisabled("No motion.");
        } else {
            const int n = static_cast<int>(doc_->motions.size());
            if (ImGui::Button(playing_ ? "Pause" : "Play")) {
                if (!playback_ || play_pos_ >= n) play_pos_ = 0;
                playback_ = true;
                playing_ = !playing_;
            }
            ImGui::SameLine();
            if (ImGui::Button("<")) {
                playback_ = true;
                playing_ = false;
                play_pos_ = std::max(0.0, std::ceil(play_pos_) - 1);
            }
            ImGui::SameLine();
            if (ImGui::Button(">")) {
                playback_ = true;
                playing_ = false;
                play_pos_ = std::min<double>(n, std::floor(play_pos_) + 1);
            }
            ImGui::SameLine();
            if (ImGui::Button("All")) {
                playback_ = false;
                playing_ = false;
                play_pos_ = n;
            }
            int pos = static_cast<int>(std::floor(play_pos_));
            ImGui::SetNextItemWidth(-1);
            if (ImGui::SliderInt("##pos", &pos, 0, n, "motion %d")) {
                playback_ = true;
                play_pos_ = pos;
            }
            ImGui::SetNextItemWidth(-1);
            ImGui::SliderFloat("##speed", &play_speed_, 1, 100000, "%.0f motions/s", ImGuiSliderFlags_Logarithmic);
            if (playback_) {
                const std::size_t cur = std::min<std::size_t>(static_cast<std::size_t>(play_pos_), doc_->motions.size() - 1);
                const Motion& m = doc_->motions[cur];
                ImGui::Text("line %u: %s %s", m.line, motion_kind_name(m.kind), curve_kind_name(m.curve));
                ImGui::Text("tools %s, %.0f mm/min", tools_text(m.tools).c_str(), doc_->feed_of(cur));
                if (ImGui::SmallButton("show line")) select_line(m.line, false);
            }
        }
    }
    if (ImGui::CollapsingHeader("Diagnostics", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (!doc_) {
            ImGui::TextDisabled("-");
        } else if (doc_->diagnostics.empty()) {
            ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1), "No problems found.");
        } else {
            ImGui::BeginChild("diaglist", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
            ImGuiListClipper clipper;
            clipper.Begin(static_cast<int>(doc_->diagnostics.size()));
            while (clipper.Step()) {
                for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                    const Diagnostic& d = doc_->diagnostics[static_cast<std::size_t>(i)];
                    ImGui::PushID(i);
                    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(d.severity));
                    const std::string label = fmt("%s line %u:%u", code_name(d.code).c_str(), d.line, d.column);
                    if (ImGui::Selectable(label.c_str(), d.line != 0 && d.line == selected_line_)) select_line(d.line);
                    ImGui::PopStyleColor();
                    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", d.message.c_str());
                    ImGui::SameLine();
                    ImGui::TextWrapped("%s", d.message.c_str());
                    ImGui::PopID();
                }
            }
            ImGui::EndChild();
        }
    }
    ImGui::End();
}

void App::draw_right_panel() {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kRightWidth, kToolbarHeight));
    ImGui::SetNextWindowSize(ImVec2(kRightWidth, io.DisplaySize.y - kToolbarHeight));
    ImGui::Begin("Source", nullptr, kPanelFlags | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    const float inspector_h = 220;
    ImGui::BeginChild("source", ImVec2(0, -inspector_h), true, ImGuiWindowFlags_HorizontalScrollbar);
    draw_source();
    ImGui::EndChild();
    ImGui::BeginChild("inspector", ImVec2(0, 0), true);
    draw_inspector();
    ImGui::EndChild();
    ImGui::End();
}

void App::draw_source() {
    if (!doc_) {
        ImGui::TextDisabled("The tape's text appears here.");
        return;
    }
    const Document& d = *doc_;
    const float lh = ImGui::GetTextLineHeightWithSpacing();
    if (scroll_source_ && selected_line_ > 0) {
        const float target = (static_cast<float>(selected_line_) - 1) * lh;
        const float top = ImGui::GetScrollY(), h = ImGui::GetWindowHeight();
        if (target < top || target > top + h - 2 * lh) ImGui::SetScrollY(std::max(0.f, target - h / 3));
        scroll_source_ = false;
    }
    const int digits = static_cast<int>(std::to_string(d.line_count()).size());
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(d.line_count()), lh);
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const std::uint32_t line = static_cast<std::uint32_t>(i + 1);
            // diagnostics on this line
            auto it = std::lower_bound(d.diagnostics.begin(), d.diagnostics.end(), line,
                                       [](const Diagnostic& x, std::uint32_t l) { return x.line < l; });
            auto end = it;
            Severity worst = Severity::Note;
            bool any = false;
            while (end != d.diagnostics.end() && end->line == line) {
                any = true;
                worst = std::max(worst, end->severity);
                ++end;
            }
            ImGui::PushID(i);
            const ImVec2 pos = ImGui::GetCursorScreenPos();
            if (ImGui::Selectable("##line", line == selected_line_, ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap,
                                  ImVec2(0, ImGui::GetTextLineHeight())))
                select_line(line);
            if (any && ImGui::IsItemHovered()) {
                ImGui::BeginTooltip();
                for (auto k = it; k != end; ++k)
                    ImGui::TextColored(severity_color(k->severity), "%s %u:%u %s", code_name(k->code).c_str(), k->line,
                                       k->column, k->message.c_str());
                ImGui::EndTooltip();
            }
            ImGui::SetCursorScreenPos(pos);
            if (any) {
                ImGui::GetWindowDrawList()->AddRectFilled(pos, ImVec2(pos.x + 4, pos.y + ImGui::GetTextLineHeight()),
                                                          ImGui::ColorConvertFloat4ToU32(severity_color(worst)));
            }
            ImGui::TextColored(any ? severity_color(worst) : ImVec4(0.5f, 0.5f, 0.55f, 1), " %*u ", digits, line);
            ImGui::SameLine(0, 4);
            const std::string text = printable(d.line(line));
            ImGui::TextUnformatted(text.c_str());
            if (any) {
                ImGui::SameLine(0, 12);
                ImGui::TextColored(severity_color(worst), "<- %s", code_name(it->code).c_str());
            }
            ImGui::PopID();
        }
    }
}

void App::draw_inspector() {
    if (!doc_ || selected_line_ == 0) {
        ImGui::TextDisabled("Click a segment or a source line to inspect its block.");
        return;
    }
    const Document& d = *doc_;
    ImGui::Text("Line %u", selected_line_);
    ImGui::SameLine();
    ImGui::TextDisabled("%s", printable(d.line(selected_line_), 80).c_str());
    ImGui::Separator();
    const LineBlocks blocks = d.blocks_of_line(selected_line_);
    for (std::size_t b = blocks.first; b < blocks.last; ++b)
        ImGui::TextWrapped("%s", describe_block(*blocks.chunk, b, d.profile).c_str());
    const auto [m0, m1] = d.motions_of_line(selected_line_);
    for (std::size_t m = m0; m < m1 && m < m0 + 8; ++m) {
        const MotionRecord r = d.record(m);
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(kKindColors[static_cast<int>(r.kind)].r, kKindColors[static_cast<int>(r.kind)].g,
                                                    kKindColors[static_cast<int>(r.kind)].b, 1));
        ImGui::TextWrapped("%s", describe_motion(r).c_str());
        ImGui::PopStyleColor();
    }
    if (blocks.empty() && m0 == m1) ImGui::TextDisabled("No block on this line (comment, empty line or part of a block).");
    auto it = std::lower_bound(d.diagnostics.begin(), d.diagnostics.end(), selected_line_,
                               [](const Diagnostic& x, std::uint32_t l) { return x.line < l; });
    for (; it != d.diagnostics.end() && it->line == selected_line_; ++it) {
        ImGui::PushStyleColor(ImGuiCol_Text, severity_color(it->severity));
        ImGui::TextWrapped("%s %s: %s", std::string(severity_name(it->severity)).c_str(), code_name(it->code).c_str(),
                           it->message.c_str());
        ImGui::PopStyleColor();
    }
}

void App::draw_overlays() {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const Rect& a = view_.area;
    const ImVec2 a0(a.x, a.y), a1(a.x + a.w, a.y + a.h);
    dl->PushClipRect(a0, a1, true);
    const Point o = doc_ ? doc_->origin : Point{};
    // Grid labels on the major lines, along the bottom and left edges
    if (show_grid_) {
        const double step = grid_step(view_.zoom) * 10;
        const Point w0 = view_.to_world(a.x, a.y + a.h), w1 = view_.to_world(a.x + a.w, a.y);
        const ImU32 col = IM_COL32(150, 160, 170, 160);
        const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step)));
        for (double gx = std::ceil((w0.x + o.x) / step) * step; gx <= w1.x + o.x; gx += step) {
            const Point s = view_.to_screen({gx - o.x, 0});
            dl->AddText(ImVec2(static_cast<float>(s.x) + 3, a.y + a.h - 18), col,
                        fmt("%.*f", decimals, std::fabs(gx) < step * 1e-6 ? 0.0 : gx).c_str());
        }
        for (double gy = std::ceil((w0.y + o.y) / step) * step; gy <= w1.y + o.y; gy += step) {
            const Point s = view_.to_screen({0, gy - o.y});
            dl->AddText(ImVec2(a.x + 4, static_cast<float>(s.y) - 16), col,
                        fmt("%.*f", decimals, std::fabs(gy) < step * 1e-6 ? 0.0 : gy).c_str());
        }
        // scale bar
        const float bar = static_cast<float>(step * view_.zoom);
        const ImVec2 p(a.x + a.w - bar - 20, a.y + a.h - 30);
        dl->AddLine(p, ImVec2(p.x + bar, p.y), IM_COL32(230, 230, 230, 220), 2);
        dl->AddLine(p, ImVec2(p.x, p.y - 5), IM_COL32(230, 230, 230, 220), 2);
        dl->AddLine(ImVec2(p.x + bar, p.y), ImVec2(p.x + bar, p.y - 5), IM_COL32(230, 230, 230, 220), 2);
        dl->AddText(ImVec2(p.x + bar / 2 - 20, p.y - 20), IM_COL32(230, 230, 230, 220), fmt("%g mm", step).c_str());
    }
    // Direction arrows on the selection
    if (doc_ && (selected_motion_ != npos || selected_line_ > 0)) {
        auto [m0, m1] = doc_->motions_of_line(selected_line_);
        if (selected_motion_ != npos && (selected_motion_ < m0 || selected_motion_ >= m1)) {
            m0 = selected_motion_;
            m1 = selected_motion_ + 1;
        }
        for (std::size_t m = m0; m < m1 && m < m0 + 64; ++m) {
            const MotionRecord r = doc_->record(m);
            for (double f : {0.5}) {
                const Point p = point_at(r, f), q = point_at(r, std::min(1.0, f + 0.01));
                const Point ps = view_.to_screen({p.x - o.x, p.y - o.y});
                const Point qs = view_.to_screen({q.x - o.x, q.y - o.y});
                double dx = qs.x - ps.x, dy = qs.y - ps.y;
                const double len = std::hypot(dx, dy);
                if (len < 1e-9) continue;
                dx /= len;
                dy /= len;
                const float s = 9;
                const ImVec2 tip(static_cast<float>(ps.x + dx * s), static_cast<float>(ps.y + dy * s));
                const ImVec2 l(static_cast<float>(ps.x - dx * s - dy * s * 0.7), static_cast<float>(ps.y - dy * s + dx * s * 0.7));
                const ImVec2 rr(static_cast<float>(ps.x - dx * s + dy * s * 0.7), static_cast<float>(ps.y - dy * s - dx * s * 0.7));
                dl->AddTriangleFilled(tip, l, rr, to_u32(kSelectionColor));
            }
        }
    }
    // Measure
    if (measure_mode_) {
        const ImGuiIO& io = ImGui::GetIO();
        bool snapped = false;
        const Point hover = snap(io.MousePos.x, io.MousePos.y, &snapped);
        const Point hs = view_.to_screen({hover.x - o.x, hover.y - o.y});
        if (snapped) dl->AddCircle(ImVec2(static_cast<float>(hs.x), static_cast<float>(hs.y)), 7, IM_COL32(255, 255, 0, 255), 16, 2);
        const Point b = measure_count_ == 2 ? measure_b_ : hover;
        if (measure_count_ >= 1) {
            const Point as = view_.to_screen({measure_a_.x - o.x, measure_a_.y - o.y});
            const Point bs = view_.to_screen({b.x - o.x, b.y - o.y});
            dl->AddLine(ImVec2(static_cast<float>(as.x), static_cast<float>(as.y)),
                        ImVec2(static_cast<float>(bs.x), static_cast<float>(bs.y)), IM_COL32(255, 255, 0, 255), 1.5f);
            dl->AddCircleFilled(ImVec2(static_cast<float>(as.x), static_cast<float>(as.y)), 3.5f, IM_COL32(255, 255, 0, 255));
            dl->AddCircleFilled(ImVec2(static_cast<float>(bs.x), static_cast<float>(bs.y)), 3.5f, IM_COL32(255, 255, 0, 255));
        }
        ImGui::SetNextWindowPos(ImVec2(a.x + 10, a.y + 10));
        ImGui::SetNextWindowBgAlpha(0.85f);
        ImGui::Begin("Measure", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                             ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing);
        if (measure_count_ == 0) ImGui::TextUnformatted("Click the first point (snaps to end points and arc centres).");
        else {
            const double dx = b.x - measure_a_.x, dy = b.y - measure_a_.y;
            ImGui::Text("A (%.3f, %.3f)", measure_a_.x, measure_a_.y);
            ImGui::Text("B (%.3f, %.3f)%s", b.x, b.y, measure_count_ == 2 ? "" : "  (click to fix)");
            ImGui::Text("distance %.3f mm", std::hypot(dx, dy));
            ImGui::Text("dx %.3f mm   dy %.3f mm", dx, dy);
        }
        ImGui::TextDisabled("Esc or M: leave the measure mode");
        ImGui::End();
    }
    dl->PopClipRect();
}

void App::draw_messages() {
    const Rect& a = view_.area;
    const ImVec2 centre(a.x + a.w / 2, a.y + a.h / 2);
    if (loading()) {
        // Over the middle of the drawing area; at its top once the level of detail shows the tape.
        if (tape_drawn_) ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 8), ImGuiCond_Always, ImVec2(0.5f, 0.f));
        else ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::SetNextWindowSize(ImVec2(420, 0));
        ImGui::Begin("Loading", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove);
        ImGui::Text("Loading %s (%s): %s", loading_name_.c_str(), size_text(loading_bytes_).c_str(), load_stage());
        ImGui::ProgressBar(stepped(load_progress()), ImVec2(-1, 0));
        ImGui::End();
    } else if (doc_ && (renderer_.filling() || remaking())) {
        // A zoomed-in view of a big tape is drawn over several frames (Renderer::kSegmentsPerFrame), after its
        // segments are made at the zoom's tolerance.
        ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 8), ImGuiCond_Always, ImVec2(0.5f, 0.f));
        ImGui::Begin("Drawing", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                             ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                             ImGuiWindowFlags_NoInputs);
        if (remaking())
            ImGui::Text("Drawing this view: making the segments for this zoom (%.0f %%)",
                        100.0 * stepped(building_->progress()));
        else
            ImGui::Text("Drawing this view: %.1f M segments to go", renderer_.stats().pending_segments / 1e6);
        ImGui::End();
    } else if (!doc_) {
        ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::Begin("Welcome", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                             ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove);
        ImGui::TextUnformatted("essikit viewer: ESSI cutting tapes (ISO 6582)");
        ImGui::Spacing();
        ImGui::TextUnformatted("Drop a tape here, press Open..., or paste its text (Ctrl+V).");
        ImGui::TextUnformatted("Nothing is uploaded: the tape is read in this page.");
        ImGui::TextDisabled("Press H for the shortcuts.");
        if (!graphics_ok_) ImGui::TextColored(severity_color(Severity::Error), "Graphics error: %s", renderer_.error());
        ImGui::End();
    } else if (!banner_.empty()) {
        ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 520.f), 0));
        ImGui::Begin("Problem", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                             ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing);
        ImGui::PushStyleColor(ImGuiCol_Text, severity_color(Severity::Error));
        ImGui::TextWrapped("%s", banner_.c_str());
        ImGui::PopStyleColor();
        ImGui::TextWrapped("File: %s (%zu bytes). The diagnostics list on the left says what was found.", doc_->name.c_str(),
                           doc_->bytes.size());
        ImGui::End();
    }
    if (share_popup_) {
        ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 560.f), 0));
        ImGui::Begin("Share link", &share_popup_, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
        ImGui::TextWrapped("%s", share_url_.size() > 600 ? (share_url_.substr(0, 600) + " ...").c_str() : share_url_.c_str());
        if (ImGui::Button("Copy again")) platform::copy_text(share_url_);
        ImGui::SameLine();
        if (ImGui::Button("Close")) share_popup_ = false;
        ImGui::End();
    }
}

void App::draw_help() {
    ImGui::SetNextWindowPos(ImVec2(view_.area.x + view_.area.w / 2, view_.area.y + 40), ImGuiCond_Appearing, ImVec2(0.5f, 0));
    ImGui::Begin("Help: shortcuts", &show_help_, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    static const char* rows[][2] = {
        {"drag (left, right or middle)", "pan"},
        {"mouse wheel", "zoom at the cursor"},
        {"+ / -", "zoom in / out at the centre"},
        {"F", "fit the whole tape"},
        {"click a segment", "select it and show its source line"},
        {"click a source line / diagnostic", "select its block and segment"},
        {"Esc", "clear the selection / leave measure / close help"},
        {"M", "measure: click two points (snaps to end points and arc centres)"},
        {"Space", "play / pause the playback"},
        {"Left / Right", "step the playback one motion"},
        {"Home / End", "playback from the start / show everything"},
        {"1 2 3 4", "toggle cut, travel+rapid, mark, pierces"},
        {"G", "toggle the grid"},
        {"S", "share link (tape and view in the URL)"},
        {"Ctrl+O", "open a tape"},
        {"Ctrl+V", "paste a tape's text"},
        {"drop a file", "load it"},
        {"H, ? or F1", "this help"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        for (auto& r : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(0.6f, 0.85f, 1, 1), "%s", r[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r[1]);
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::TextUnformatted("Colours:");
    static const char* names[4] = {"rapid", "travel", "cut", "mark"};
    for (int k = 0; k < 4; ++k) {
        ImGui::SameLine();
        const Rgba c = kKindColors[k];
        ImGui::TextColored(ImVec4(c.r, c.g, c.b, 1), "%s", names[k]);
    }
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.25f, 0.2f, 1), "pierce");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.3f, 0.95f, 0.4f, 1), "start");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(kSelectionColor.r, kSelectionColor.g, kSelectionColor.b, 1), "selection");
    ImGui::End();
}

// ---------------------------------------------------------------------------------------------------------
// Automation
// ---------------------------------------------------------------------------------------------------------
std::string App::state_json() const {
    nlohmann::json j;
    j["status"] = loading() ? "loading" : doc_ ? "ready" : "empty";
    if (loading()) {
        j["progress"] = load_progress();
        j["stage"] = load_stage();
    }
    // The last frame drew the tape (its segments, or its level of detail while the segments are made), and how
    // long after the start of the load the first such frame came.
    j["drawn"] = tape_drawn_;
    // Work left after "ready" too: the finer level of detail of a big tape, a rebuild at another tolerance.
    j["busy"] = has_background_work();
    j["shown_seconds"] = shown_seconds_;
    j["name"] = doc_ ? doc_->name : (loader_ ? loading_name_ : "");
    j["profile"] = profile_name_;
    if (doc_) {
        const Stats& s = doc_->stats;
        j["stats"] = {
            {"cut_length_mm", s.cut_length_mm},
            {"mark_length_mm", s.mark_length_mm},
            {"travel_length_mm", s.travel_length_mm},
            {"rapid_length_mm", s.rapid_length_mm},
            {"pierces", s.pierces},
            {"blocks", s.blocks},
            {"motions", s.motions},
            {"estimated_time_s", s.estimated_time_s},
            {"cut_bbox_mm", box_json(s.cut_bbox)},
            {"end_position_mm", {{"x", s.end_position.x}, {"y", s.end_position.y}}},
        };
        nlohmann::json diags = nlohmann::json::array();
        for (const Diagnostic& d : doc_->diagnostics)
            diags.push_back({{"severity", std::string(severity_name(d.severity))}, {"code", code_name(d.code)},
                             {"line", d.line}, {"column", d.column}, {"message", d.message}});
        j["diagnostics"] = std::move(diags);
        j["ok"] = !doc_->has_errors();
        j["banner"] = banner_;
        j["bytes"] = doc_->bytes.size();
        j["lines"] = doc_->line_count();
        j["motions"] = doc_->motions.size();
        j["segments"] = buffers_.segment_count;
        j["pierce_markers"] = doc_->pierces.size();
        j["bbox_mm"] = box_json(doc_->bbox);
        j["memory_bytes"] = doc_->memory_bytes() + buffers_.memory_bytes() + (building_ ? building_->memory_bytes() : 0);
        nlohmann::json parts = nlohmann::json::object();
        for (const auto& [part, n] : doc_->memory_parts()) parts[part] = n;
        parts["segment_index"] = buffers_.memory_bytes() + (building_ ? building_->memory_bytes() : 0);
        j["memory_parts"] = std::move(parts);
        j["gpu_bytes"] = gpu_.gpu_bytes() + gpu_building_.gpu_bytes() + renderer_.lod_gpu_bytes();
        j["lod"] = {{"available", renderer_.has_lod()}, {"drawn", lod_drawn_}, {"cell_mm", renderer_.lod_cell_mm()}};
        j["tape_memory_bytes"] = doc_->core_tape_bytes();
        j["blocks_read"] = doc_->blocks;
        j["kept_records"] = doc_->kept.size();
        j["load_seconds"] = load_seconds_;
        j["chord_tolerance_mm"] = buffers_.tolerance();
    }
    j["selection"] = selected_line_ == 0 ? nlohmann::json(nullptr)
                                         : nlohmann::json{{"line", selected_line_},
                                                          {"motion", selected_motion_ == npos ? nlohmann::json(nullptr)
                                                                                              : nlohmann::json(selected_motion_)}};
    const Point o = doc_ ? doc_->origin : Point{};
    // Screen position of machine point (x, y): px = origin_px.x + (x - x_mm) * zoom, py = origin_px.y - (y - y_mm) * zoom
    j["view"] = {{"x_mm", view_.cx + o.x},
                 {"y_mm", view_.cy + o.y},
                 {"zoom", view_.zoom},
                 {"origin_px", {view_.ox(), view_.oy()}},
                 {"area", {view_.area.x, view_.area.y, view_.area.w, view_.area.h}},
                 {"query", view_query()}};
    j["layers"] = {{"rapid", show_kind_[0]}, {"travel", show_kind_[1]}, {"cut", show_kind_[2]}, {"mark", show_kind_[3]},
                   {"pierces", show_pierces_}, {"start", show_start_}, {"grid", show_grid_}};
    j["playback"] = {{"active", playback_}, {"playing", playing_}, {"position", play_pos_}};
    if (playback_ && doc_ && !doc_->motions.empty()) {
        // What the Playback panel shows: the motion at the scrubber, its line, the tools and where the tool is.
        const std::size_t n = doc_->motions.size();
        const std::size_t cur = std::min<std::size_t>(static_cast<std::size_t>(play_pos_), n - 1);
        const Motion& m = doc_->motions[cur];
        const double frac = static_cast<std::size_t>(play_pos_) >= n ? 1.0 : play_pos_ - std::floor(play_pos_);
        const Point p = point_at(doc_->record(cur), frac);
        j["playback"]["motion"] = cur;
        j["playback"]["line"] = m.line;
        j["playback"]["kind"] = motion_kind_name(m.kind);
        j["playback"]["tools"] = tools_text(m.tools);
        j["playback"]["feed_mm_min"] = doc_->feed_of(cur);
        j["playback"]["tool_mm"] = {p.x, p.y};
        j["playback"]["drawn_motions"] = playback_limit_motions();
    }
    j["measure"] = {{"active", measure_mode_}, {"points", measure_count_}};
    if (measure_count_ >= 1) j["measure"]["a_mm"] = {measure_a_.x, measure_a_.y};
    if (measure_count_ == 2) {
        j["measure"]["b_mm"] = {measure_b_.x, measure_b_.y};
        j["measure"]["distance_mm"] = std::hypot(measure_b_.x - measure_a_.x, measure_b_.y - measure_a_.y);
        j["measure"]["dx_mm"] = measure_b_.x - measure_a_.x;
        j["measure"]["dy_mm"] = measure_b_.y - measure_a_.y;
    }
    // The block inspector's sentences for the selected line (blocks, then motions).
    nlohmann::json insp = nlohmann::json::array();
    if (doc_ && selected_line_ > 0) {
        const LineBlocks blocks = doc_->blocks_of_line(selected_line_);
        for (std::size_t b = blocks.first; b < blocks.last; ++b)
            insp.push_back(describe_block(*blocks.chunk, b, doc_->profile));
        const auto [m0, m1] = doc_->motions_of_line(selected_line_);
        for (std::size_t m = m0; m < m1 && m < m0 + 8; ++m) insp.push_back(describe_motion(doc_->record(m)));
    }
    j["inspector"] = std::move(insp);
    const RenderStats& rs = renderer_.stats();
    j["render"] = {{"frames", rs.frames}, {"full_redraws", rs.full_redraws}, {"partial_redraws", rs.partial_redraws},
                   {"cached_frames", rs.cached_frames}, {"filling_frames", rs.filling_frames},
                   {"pending_segments", rs.pending_segments}, {"unchanged_frames", skipped_frames_}};
    j["help"] = show_help_;
    j["share_url"] = share_url_;
    j["message"] = message_;
    j["kind_colors"] = nlohmann::json::array();
    for (const Rgba& c : kKindColors)
        j["kind_colors"].push_back({std::lround(c.r * 255), std::lround(c.g * 255), std::lround(c.b * 255)});
    return j.dump();
}

std::string App::motion_json(std::size_t i) const {
    if (!doc_ || i >= doc_->motions.size()) return "null";
    const MotionRecord r = doc_->record(i);
    nlohmann::json j = {{"index", i},
                        {"line", r.line},
                        {"block", doc_->block_of(i)},
                        {"kind", motion_kind_name(r.kind)},
                        {"curve", curve_kind_name(r.curve)},
                        {"start", {r.start.x, r.start.y}},
                        {"end", {r.end.x, r.end.y}},
                        {"mid", {point_at(r, 0.5).x, point_at(r, 0.5).y}},
                        {"length_mm", r.length_mm},
                        {"centre", r.curve == CurveKind::Arc ? nlohmann::json{r.centre.x, r.centre.y} : nlohmann::json(nullptr)},
                        {"text", describe_motion(r)}};
    return j.dump();
}

}  // namespace essi::viewer
