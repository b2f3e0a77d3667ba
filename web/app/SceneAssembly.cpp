#include "app/SceneAssembly.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "app/Problems.hpp"
#include "essi/geom.hpp"

namespace essi::viewer {

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

// The segments [first, count) of the selected motion, or of the selected line's motions.
std::pair<std::size_t, std::size_t> selection_segments(const Document& doc, const PathBuffers& buffers,
                                                       const Selection& sel) {
    std::size_t a = Selection::npos, b = Selection::npos;
    if (sel.motion != Selection::npos) {
        a = sel.motion;
        b = sel.motion + 1;
    } else if (sel.line > 0) {
        const auto [ma, mb] = doc.motions_of_line(sel.line);
        if (ma < mb) {
            a = ma;
            b = mb;
        }
    }
    if (a == Selection::npos) return {0, 0};
    return {buffers.first_segment[a], buffers.first_segment[b] - buffers.first_segment[a]};
}

}  // namespace

// The playback's limit and tool, and the selection's segments (once the segments of every motion are known).
void SceneAssembly::add_playback_and_selection(const SceneInputs& in, DrawOptions& o) {
    const Document* doc = in.load.document();
    const PathBuffers& buffers = in.load.buffers();
    if (!doc || buffers.first_segment.size() != doc->motions.size() + 1) return;
    const std::size_t n = doc->motions.size();
    if (in.playback.active) {
        o.segment_limit = buffers.first_segment[in.playback.limit(n)];
        if (n > 0) {
            const Playback::At at = in.playback.at(n);
            const Point p = point_at(doc->record(at.motion), at.fraction);
            o.has_tool = true;
            o.tool = {p.x - doc->origin.x, p.y - doc->origin.y};
        }
    }
    const auto [first, count] = selection_segments(*doc, buffers, in.selection);
    o.selection_first = first;
    o.selection_count = count;
}

// The diagnostics: the problems-only view's faint rest and full concerned motions, the active ones highlighted.
void SceneAssembly::add_problems(const SceneInputs& in, DrawOptions& o) {
    const Document* doc = in.load.document();
    if (!doc) return;
    o.dim = in.layers.problems_only;  // (a tape without problems: all of it faint)
    if (doc->diagnostics.empty()) return;
    const PathBuffers& buffers = in.load.buffers();
    if (o.dim) o.bright = concerned_runs(*doc, buffers);
    o.highlights = diagnostic_highlights(*doc, buffers, active_diagnostics(*doc, in.hovered_mark, in.selection.line));
}

bool SceneAssembly::prepare(const SceneInputs& in, const Renderer& renderer, bool graphics_ok) {
    scene_.reset();
    if (!graphics_ok || in.fb_w <= 0 || in.fb_h <= 0) return false;
    const View& view = in.view;
    DrawOptions o;
    o.framebuffer_scale = in.framebuffer_scale;
    o.layer_mask = in.layers.kind_mask();
    o.kerf_band_mm = in.load.buffers().kerf_widths;
    o.panel_color = in.panel_color;
    // Zoomed out on a big tape: the level-of-detail raster instead of millions of sub-pixel segments (also while
    // the first build makes the exact segments: the raster is made before them). While a big tape's segments are
    // made again at a new zoom's tolerance (seconds), the raster stands in for them: filling the image with the
    // segments about to be replaced would only delay the new ones.
    o.lod = !in.playback.active && renderer.has_lod() &&
            (renderer.lod_cell_mm() * view.zoom * o.framebuffer_scale <= Renderer::kLodMaxCellPx || in.load.remaking());
    lod_drawn_ = o.lod;
    // While the first build runs nothing else of the new tape is drawn (the frames stay cheap).
    o.marker_mask = in.load.first_build() && !o.lod ? 0 : in.layers.marker_mask();
    add_playback_and_selection(in, o);
    add_problems(in, o);
    const Document* doc = in.load.document();
    const GpuPath* path = in.load.drawn_path();
    tape_drawn_ = doc && (o.lod || path != nullptr);
    // The first frame of a tape loaded at once shows all of it (under 1 MB: at most about half a million segments).
    whole_ = in.load.draw_whole();
    scene_ = SceneFrame{view,
                        in.fb_w,
                        in.fb_h,
                        o,
                        in.layers.grid ? grid_step(view.zoom) : kNoGrid,
                        in.grid_origin,
                        path,
                        path ? path->version : 0};
    return true;
}

void SceneAssembly::render(Renderer& renderer, UiRenderer& ui, int fb_w, int fb_h, bool keep_unchanged,
                           Windows windows) {
    const ImDrawData& data = *ImGui::GetDrawData();
    const std::uint64_t hash = ui_hash(data);
    if (keep_unchanged && scene_ && scene_ == last_scene_ && hash == last_ui_hash_ && !renderer.filling()) {
        ++skipped_frames_;
        return;
    }
    if (scene_) {
        const SceneFrame& s = *scene_;
        renderer.draw(s.view, s.fb_w, s.fb_h, s.options, s.grid_step, s.grid_origin, s.path,
                      whole_ ? Renderer::kWholeImage : Renderer::kSegmentsPerFrame);
    }
    if (windows == Windows::LeftOut) {
        // ImGui lists the background draw list first, then the windows: the first list alone.
        ImDrawList* background = ImGui::GetBackgroundDrawList();
        ImDrawData overlays = data;
        overlays.CmdLists = &background;
        overlays.CmdListsCount = data.CmdListsCount > 0 && data.CmdLists[0] == background ? 1 : 0;
        ui.draw(overlays, fb_w, fb_h);
        last_scene_.reset();  // (the next frame is drawn again, with its windows)
        return;
    }
    ui.draw(data, fb_w, fb_h);
    last_scene_ = scene_;
    last_ui_hash_ = hash;
}

}  // namespace essi::viewer
