// The windows over the middle of the drawing area: loading progress, a view being drawn over frames, the welcome,
// a problem with the whole file, and the share link.
#include <algorithm>

#include "app/App.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer::panels {

namespace {

constexpr ImGuiWindowFlags kMessageFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove;
constexpr std::size_t kShareUrlShown = 600;  // characters of a share link shown
constexpr std::size_t kExamplesPerRow = 3;    // buttons a row on the start screen

void loading(const App& app, const Rect& a, ImVec2 centre, bool tape_drawn) {
    const LoadController& load = app.loads();
    // Over the middle of the drawing area; at its top once the level of detail shows the tape.
    if (tape_drawn) ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 8), ImGuiCond_Always, ImVec2(0.5f, 0.f));
    else ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(420, 0));
    ImGui::Begin("Loading", nullptr, kMessageFlags);
    ImGui::Text("Loading %s (%s): %s", load.loading_name().c_str(), size_text(load.loading_bytes()).c_str(), load.stage());
    ImGui::ProgressBar(stepped(load.progress()), ImVec2(-1, 0));
    ImGui::End();
}

// A zoomed-in view of a big tape is drawn over several frames (Renderer::kSegmentsPerFrame), after its segments
// are made at the zoom's tolerance.
void drawing(const App& app, const Rect& a, ImVec2 centre) {
    const LoadController& load = app.loads();
    ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 8), ImGuiCond_Always, ImVec2(0.5f, 0.f));
    ImGui::Begin("Drawing", nullptr, kMessageFlags | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
    if (load.remaking())
        ImGui::Text("Drawing this view: making the segments for this zoom (%.0f %%)",
                    100.0 * stepped(load.building()->progress()));
    else
        ImGui::Text("Drawing this view: %.1f M segments to go", app.renderer().stats().pending_segments / 1e6);
    ImGui::End();
}

void welcome(App& app, ImVec2 centre) {
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Welcome", nullptr, kMessageFlags | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted("essikit viewer: ESSI cutting tapes (ISO 6582)");
    ImGui::Spacing();
    ImGui::TextUnformatted("Drop a tape here, press Open..., or paste its text (Ctrl+V).");
    ImGui::TextUnformatted("Nothing is uploaded: the tape is read in this page.");
    ImGui::TextDisabled("Press H for the shortcuts.");
    const UiState& ui = app.ui();
    if (!ui.examples.empty()) {
        ImGui::Spacing();
        ImGui::TextUnformatted("Examples on this server (one click opens one):");
        for (std::size_t k = 0; k < ui.examples.size(); ++k) {
            if (k % kExamplesPerRow != 0) ImGui::SameLine();
            if (ImGui::SmallButton(ui.examples[k].c_str())) platform::open_example(app, ui.examples[k]);
        }
    }
    if (!ui.recent.empty()) {
        ImGui::Spacing();
        ImGui::TextDisabled("Opened lately (drop or open them again):");
        for (const std::string& name : ui.recent) ImGui::BulletText("%s", name.c_str());
    }
    if (!app.graphics_ok()) ImGui::TextColored(severity_color(Severity::Error), "Graphics error: %s", program_error());
    ImGui::End();
}

void problem(const Document& doc, const std::string& banner, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 520.f), 0));
    ImGui::Begin("Problem", nullptr, kMessageFlags | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(Severity::Error));
    ImGui::TextWrapped("%s", banner.c_str());
    ImGui::PopStyleColor();
    ImGui::TextWrapped("File: %s (%zu bytes). The diagnostics list on the left says what was found.", doc.name.c_str(),
                       doc.bytes.size());
    ImGui::End();
}

void share_popup(UiState& ui, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 560.f), 0));
    ImGui::Begin("Share link", &ui.share_popup, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
    const std::string& url = ui.share_url;
    ImGui::TextWrapped("%s", url.size() > kShareUrlShown ? (url.substr(0, kShareUrlShown) + " ...").c_str() : url.c_str());
    if (ImGui::Button("Copy again")) platform::copy_text(url);
    ImGui::SameLine();
    if (ImGui::Button("Close")) ui.share_popup = false;
    ImGui::End();
}

// A share link that could not be opened: why, and what to do; over the start screen until closed or a tape loads.
void link_problem(UiState& ui, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 24), ImGuiCond_Appearing, ImVec2(0.5f, 0.f));
    ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 560.f), 0));
    bool open = true;
    ImGui::Begin("Share link problem", &open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(Severity::Error));
    ImGui::TextWrapped("%s", ui.link_problem.c_str());
    ImGui::PopStyleColor();
    ImGui::TextWrapped("Ask the sender for the whole link, or for the file.");
    ImGui::End();
    if (!open) ui.link_problem.clear();
}

}  // namespace

void messages(App& app) {
    const Rect& a = app.view().area;
    const ImVec2 centre(a.x + a.w / 2, a.y + a.h / 2);
    const Document* doc = app.document();
    const LoadController& load = app.loads();
    UiState& ui = app.ui();
    if (load.loading()) loading(app, a, centre, app.tape_drawn());
    else if (doc && (app.renderer().filling() || load.remaking())) drawing(app, a, centre);
    else if (!doc) welcome(app, centre);
    else if (!ui.banner.empty()) problem(*doc, ui.banner, a, centre);
    if (ui.share_popup) share_popup(ui, a, centre);
    if (!ui.link_problem.empty()) link_problem(ui, a, centre);
    compare_window(app);
}

}  // namespace essi::viewer::panels
