#include "app/App.hpp"

#include <imgui.h>

#include "app/Display.hpp"
#include "app/Language.hpp"
#include "app/panels/Layout.hpp"

namespace essi::viewer {

App::App(PlatformServices& platform)
    : platform_(platform), fonts_(platform), notices_(fonts_), load_(renderer_), tape_facts_(load_),
      preferences_(platform, renderer_, layers_, ui_), navigation_(load_, platform), comments_(fonts_, platform),
      compare_(navigation_, notices_, fonts_),
      session_({load_, navigation_, playback_, measure_, compare_, comments_, notices_, fonts_, ui_, platform}),
      exports_(session_, tape_facts_, navigation_, notices_, platform),
      shares_(session_, navigation_, notices_, ui_, platform),
      input_({session_, navigation_, layers_, playback_, measure_, shares_, preferences_, ui_, platform}),
      parts_{session_,  load_,     navigation_,  layers_, playback_,    measure_, compare_,
             comments_, exports_,  tape_facts_,  shares_, preferences_, notices_, ui_,
             fonts_,    renderer_, ui_renderer_, scene_,  warm_up_,     platform, graphics_ok_},
      panels_(parts_), automation_(parts_) {}

bool App::init_graphics() {
    fonts_.update(framebuffer_scale());  // (the atlas, before ui_renderer_ uploads it)
    graphics_ok_ = renderer_.init() && ui_renderer_.init();
    load_.set_graphics(graphics_ok_);
    load_.set_reading_worker(platform_.reading_worker());
    ImGuiIO& io = ImGui::GetIO();
    if (!io.Fonts->IsBuilt()) io.Fonts->Build();  // (ui_renderer_.init() makes the atlas unless the GPU refused it)
    io.IniFilename = nullptr;                     // no imgui.ini: the layout is fixed
    keyboard_.init();
    preferences_.graphics_ready(graphics_ok_);
    return graphics_ok_;
}

void App::load(std::string name, std::string bytes) { session_.load(std::move(name), std::move(bytes)); }

bool App::background_step() {
    if (load_.has_work()) return session_.background_step() || warm_up_.has_work();
    const bool warming = warm_up_.has_work();
    warm_up_.step(LoadController::kStepBudgetMs);
    // (the page's code is warm: the reading worker's turn, while the page waits for a tape)
    if (warming && warm_up_.state() == WarmUp::State::Done) load_.prepare_reading_worker();
    return has_background_work();
}

void App::frame() {
    const ImGuiIO& io = ImGui::GetIO();
    preferences_.keep_dragged_layout();
    View& view = navigation_.view();
    ui_.compact = compact_layout(io.DisplaySize.x);
    view.area = ui_.compact
                    ? compact_drawing_area(io.DisplaySize.x, io.DisplaySize.y, panels::kToolbarHeight, ui_.sheet)
                    : panels::drawing_area(io.DisplaySize.x, io.DisplaySize.y, ui_.layout);
    session_.begin_frame();
    view.plate = navigation_.coordinates().plate();
    if (const Document* d = session_.document(); d && playback_.playing) {
        if (const MotionTimes* times = tape_facts_.motion_times()) playback_.advance(io.DeltaTime, *times);
        navigation_.follow(*d, playback_);
    }
    keyboard_.begin_frame();
    input_.handle_shortcuts();
    input_.handle_canvas();
    load_.set_colour_by(layers_.colour_by, &tape_facts_);
    load_.maybe_rebuild(view.chord_tolerance_mm());
    panels_.draw();
    keyboard_.end_frame(view.area);
    prepare_scene();  // (drawn by render(), below the panels)
    session_.end_frame();
    announce_selection();
    announce_mirror();
}

void App::prepare_scene() {
    const auto [fb_w, fb_h] = framebuffer_size();
    const SceneInputs in{navigation_.view(),
                         fb_w,
                         fb_h,
                         framebuffer_scale(),
                         panels::panel_color(renderer_.theme().background),
                         layers_,
                         playback_,
                         navigation_.selection(),
                         load_,
                         navigation_.coordinates().shown(navigation_.origin()),
                         ui_.hovered_mark};
    const bool prepared = scene_.prepare(in, renderer_, graphics_ok_);
    load_.note_frame(prepared && scene_.tape_drawn());
}

void App::announce_selection() {
    const Selection& s = navigation_.selection();
    if (s.line == announced_.line && s.motion == announced_.motion) return;
    announced_ = s;
    platform_.selection_changed(s.line, s.motion == Selection::npos ? -1 : static_cast<long long>(s.motion));
}

void App::announce_mirror() {
    const std::string* loading = load_.loading() ? &load_.loading_name() : nullptr;
    bool changed = false;
    const PageMirror& m =
        mirror_.update(session_.document(), load_.load_frames().handed, navigation_.selection(), loading, &changed);
    if (changed) platform_.show_mirror(m);
}

void App::render(bool keep_unchanged) {
    if (!graphics_ok_) return;
    const auto [fb_w, fb_h] = framebuffer_size();
    if (exports_.png_pending()) save_view_png(fb_w, fb_h);
    scene_.render(renderer_, ui_renderer_, fb_w, fb_h, keep_unchanged && !fonts_changed_);
    load_.note_rendered(scene_.tape_drawn(), renderer_.filling());
    // Between frames: the atlas at the screen's pixel ratio, with the glyphs asked for (UiFonts); the next frame
    // draws with it.
    fonts_.require_language(ui_lang());
    fonts_changed_ = fonts_.update(framebuffer_scale());
    if (fonts_changed_) ui_renderer_.upload_fonts();
}

// The view as a picture: this frame's scene and its overlays without the windows (an open menu, a tooltip), its
// drawing area taken in the framebuffer's pixels (top-left origin); the frame is then drawn again with them.
void App::save_view_png(int fb_w, int fb_h) {
    scene_.render(renderer_, ui_renderer_, fb_w, fb_h, false, SceneAssembly::Windows::LeftOut);
    const float s = framebuffer_scale();
    const Rect& a = navigation_.view().area;
    exports_.save_view_png({a.x * s, a.y * s, a.w * s, a.h * s});
}

}  // namespace essi::viewer
