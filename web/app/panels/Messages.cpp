// The windows over the middle of the drawing area: loading progress, a view being drawn over frames, the welcome,
// a problem with the whole file, and the share link.
#include <algorithm>

#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"

namespace essi::viewer::panels {

namespace {

constexpr ImGuiWindowFlags kMessageFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove;
constexpr std::size_t kShareUrlShown = 600;  // characters of a share link shown
constexpr std::size_t kExamplesPerRow = 3;   // buttons a row on the start screen
constexpr float kWelcomeMarginPx = 24;       // the start screen inside the drawing area, this much to spare

void loading(const LoadController& load, ShownProgress& bar, const Rect& a, ImVec2 centre, bool tape_drawn) {
    // Over the middle of the drawing area; at its top once the level of detail shows the tape.
    if (tape_drawn) ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 8), ImGuiCond_Always, ImVec2(0.5f, 0.f));
    else ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(420, 0));
    ImGui::Begin("##loading", nullptr, kMessageFlags);
    ImGui::TextWrapped(
        "%s", tr(Msg::UiLoadingLine, {load.loading_name(), size_text(load.loading_bytes()), load.stage()}).c_str());
    ImGui::ProgressBar(bar.update(stepped(load.progress()), ImGui::GetTime()), ImVec2(-1, 0));
    ImGui::End();
}

// A zoomed-in view of a big tape is drawn over several frames (Renderer::kSegmentsPerFrame), after its segments
// are made at the zoom's tolerance.
void drawing(const LoadController& load, const Renderer& renderer, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 8), ImGuiCond_Always, ImVec2(0.5f, 0.f));
    ImGui::Begin("##drawing", nullptr, kMessageFlags | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
    if (load.remaking())
        ImGui::TextUnformatted(
            tr(Msg::UiDrawingRemake, {fmt("%.0f", 100.0 * stepped(load.building()->progress()))}).c_str());
    else
        ImGui::TextUnformatted(
            tr(Msg::UiDrawingPending, {fmt("%.1f", renderer.stats().pending_segments / 1e6)}).c_str());
    ImGui::End();
}

void welcome(const Panels::Parts& p, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("##welcome", nullptr, kMessageFlags | ImGuiWindowFlags_AlwaysAutoResize);
    // (wrapped inside the drawing area: a phone's is narrower than the texts)
    const float wrap = std::max(a.w - kWelcomeMarginPx - 2 * ImGui::GetStyle().WindowPadding.x, 120.f);
    ImGui::PushTextWrapPos(wrap);
    ImGui::TextUnformatted(tr(Msg::UiWelcomeTitle));
    ImGui::Spacing();
    ImGui::TextUnformatted(tr(Msg::UiWelcomeDrop));
    ImGui::TextUnformatted(tr(Msg::UiWelcomeLocal));
    ImGui::TextDisabled("%s", tr(Msg::UiWelcomeHelp));
    const UiState& ui = p.ui;
    if (!ui.examples.empty()) {
        ImGui::Spacing();
        ImGui::TextUnformatted(tr(Msg::UiWelcomeExamples));
        for (std::size_t k = 0; k < ui.examples.size(); ++k) {
            const float w = ImGui::CalcTextSize(ui.examples[k].c_str()).x + ImGui::GetStyle().FramePadding.x * 2;
            if (k % kExamplesPerRow != 0 &&
                ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w - ImGui::GetWindowPos().x <= wrap)
                ImGui::SameLine();
            if (ImGui::SmallButton(ui.examples[k].c_str())) p.platform.open_example(ui.examples[k]);
        }
    }
    if (!p.session.recent().empty()) {
        ImGui::Spacing();
        ImGui::TextDisabled("%s", tr(Msg::UiWelcomeRecent));
        for (const std::string& name : p.session.recent()) ImGui::BulletText("%s", name.c_str());
    }
    if (!p.graphics_ok)
        ImGui::TextColored(severity_color(Severity::Error), "%s", tr(Msg::UiGraphicsError, {program_error()}).c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void problem(const Document& doc, const std::string& banner, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 520.f), 0));
    ImGui::Begin("##problem", nullptr, kMessageFlags | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(Severity::Error));
    ImGui::TextWrapped("%s", banner.c_str());
    ImGui::PopStyleColor();
    ImGui::TextWrapped("%s", tr(Msg::UiProblemFile, {doc.name, doc.bytes.size()}).c_str());
    ImGui::End();
}

void share_popup(UiState& ui, const ShareLinks& shares, PlatformServices& platform, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 560.f), 0));
    ImGui::Begin(tr_id(Msg::UiShareLink, "Share link").c_str(), &ui.share_popup,
                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
    const std::string url = shares.text();  // (the link, or why there is none)
    ImGui::TextWrapped("%s",
                       url.size() > kShareUrlShown ? (url.substr(0, kShareUrlShown) + " ...").c_str() : url.c_str());
    if (ImGui::Button(tr_id(Msg::UiCopyAgain, "copy again").c_str())) platform.copy_text(url);
    ImGui::SameLine();
    if (ImGui::Button(tr_id(Msg::UiClose, "close").c_str())) ui.share_popup = false;
    ImGui::End();
}

// A share link that could not be opened: why, and what to do; over the start screen until closed or a tape loads.
void link_problem(Session& session, const Rect& a, ImVec2 centre) {
    ImGui::SetNextWindowPos(ImVec2(centre.x, a.y + 24), ImGuiCond_Appearing, ImVec2(0.5f, 0.f));
    ImGui::SetNextWindowSize(ImVec2(std::min(a.w - 40, 560.f), 0));
    bool open = true;
    ImGui::Begin(tr_id(Msg::UiLinkProblemTitle, "Share link problem").c_str(), &open,
                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(Severity::Error));
    ImGui::TextWrapped("%s", session.link_problem().text().c_str());
    ImGui::PopStyleColor();
    ImGui::TextWrapped("%s", tr(Msg::UiLinkAskSender));
    ImGui::End();
    if (!open) session.close_link_problem();
}

}  // namespace

void Panels::messages() {
    const Rect& a = p_.navigation.view().area;
    const ImVec2 centre(a.x + a.w / 2, a.y + a.h / 2);
    const Document* doc = p_.session.document();
    const LoadController& load = p_.load;
    if (load.loading()) {
        // (a tape loaded at once has none: it is read and drawn before the next frame's panels)
        if (!load.at_once()) loading(load, p_.ui.loading_progress, a, centre, p_.scene.tape_drawn());
    } else if (doc && (p_.renderer.filling() || load.remaking())) drawing(load, p_.renderer, a, centre);
    else if (!doc) welcome(p_, a, centre);
    else if (p_.session.banner() != Msg::None) problem(*doc, p_.session.banner_text(), a, centre);
    if (p_.ui.share_popup) share_popup(p_.ui, p_.shares, p_.platform, a, centre);
    if (!p_.session.link_problem().empty()) link_problem(p_.session, a, centre);
    compare_window();
}

}  // namespace essi::viewer::panels
