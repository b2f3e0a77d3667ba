// The toolbar: Open, Paste, Share, Fit, Measure, Help, the profile, the tape's name and verdict, the message.
#include <GLFW/glfw3.h>

#include "app/App.hpp"
#include "app/panels/Panels.hpp"
#include "app/panels/UiText.hpp"
#include "essi/dialect.hpp"
#include "essi/profile.hpp"
#include "platform/Platform.hpp"

namespace essi::viewer::panels {

namespace {

void open_button(App& app) {
    if (ImGui::Button("Open...")) platform::open_file_dialog(app);
    platform::open_button_at(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                             ImGui::GetItemRectSize().y);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Open a tape (Ctrl+O). You can also drop a file or paste text (Ctrl+V).");
}

void profile_combo(App& app) {
    ImGui::SetNextItemWidth(110);
    // "auto: woyda" while the tape's evidence chose the dialect
    const Document* doc = app.document();
    const std::string shown = app.profile_name() == kAutoProfile && doc ? "auto: " + doc->profile.name : app.profile_name();
    ImGui::SetNextItemWidth(140);
    if (ImGui::BeginCombo("##profile", shown.c_str())) {
        std::vector<std::string> names{std::string(kAutoProfile)};
        for (const std::string& n : builtin_profile_names()) names.push_back(n);
        if (app.dropped_profile()) names.push_back(app.dropped_profile()->name);  // (a profile file dropped on the page)
        for (const std::string& n : names) {
            if (ImGui::Selectable(n.c_str(), n == app.profile_name()) && n != app.profile_name()) app.set_profile(n);
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Machine and dialect profile; auto: the dialect the tape's codes show (see the Tape panel); drop a profile file (.json) to add yours");
}

// The machine's view orientation (View::turns): where the tape's +x points on the screen; kept across sessions.
void orientation_combo(App& app) {
    static constexpr const char* kNames[4] = {"x right, y up (ISO)", "x up, y left (Woyda)", "x left, y down",
                                              "x down, y right"};
    const int turns = app.view().turns;
    ImGui::SetNextItemWidth(170);
    if (ImGui::BeginCombo("##orientation", kNames[turns])) {
        for (int q = 0; q < 4; ++q)
            if (ImGui::Selectable(kNames[q], q == turns) && q != turns) app.set_orientation(q);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The machine's view: where the tape's x and y axes point on the screen (Woyda: x to the back, y left)");
}

// Program or machine coordinates (Coordinates): the numbers, the grid and the drawing's turn; kept across sessions.
void coordinates_combo(App& app) {
    static constexpr const char* kNames[2] = {"program coordinates", "machine coordinates"};
    const int machine = app.machine_coordinates() ? 1 : 0;
    ImGui::SetNextItemWidth(170);
    if (ImGui::BeginCombo("##coordinates", kNames[machine])) {
        for (int k = 0; k < 2; ++k)
            if (ImGui::Selectable(kNames[k], k == machine) && k != machine) app.set_machine_coordinates(k == 1);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Machine: the program placed on the table by the profile (zero offset, plate rotation); the grid, "
                          "the measure and the labels in machine millimetres");
}

// Downloads: the tape as ESSI, EIA or G-code (essi convert) and its drawing as DXF.
void export_menu(App& app) {
    if (ImGui::Button("Export...")) ImGui::OpenPopup("export");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Download the tape converted (ESSI, EIA, G-code for LinuxCNC) or drawn (DXF), or its report");
    if (!ImGui::BeginPopup("export")) return;
    static constexpr std::pair<const char*, const char*> kFormats[] = {
        {"ESSI (.esi)", "essi"}, {"EIA, RS-274 (.eia)", "eia"}, {"G-code for LinuxCNC (.ngc)", "gcode"}, {"DXF drawing (.dxf)", "dxf"},
        {"Report as text (.txt)", "report-text"}, {"Report as JSON, essi check's (.json)", "report-json"},
        {"Problems as CSV (.csv)", "report-csv"}, {"View as SVG (.svg)", "view-svg"}};
    for (const auto& [label, format] : kFormats)
        if (ImGui::Selectable(label)) app.export_file(format);
    if (ImGui::Selectable("View as PNG (.png)")) app.export_view_png();
    ImGui::EndPopup();
}

// The side panels: shown or hidden ([ and ]), the widths back to their defaults.
void layout_menu(App& app) {
    if (ImGui::Button("Panels")) ImGui::OpenPopup("panels");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show or hide the side panels ([ and ]); drag a panel's inner edge to resize it");
    if (!ImGui::BeginPopup("panels")) return;
    PanelLayout l = app.ui().layout;
    bool changed = ImGui::Checkbox("Tape panel (left)  [", &l.left_shown);
    changed |= ImGui::Checkbox("Source and inspector (right)  ]", &l.right_shown);
    bool light = app.light_theme();
    if (ImGui::Checkbox("Light theme", &light)) app.set_light_theme(light);
    if (ImGui::Selectable("Default layout")) {
        l = PanelLayout{};
        changed = true;
    }
    if (changed) app.set_layout(l);
    ImGui::EndPopup();
}

// The tape's name and "ok" or its error and warning counts.
void verdict(const Document& doc) {
    const std::size_t e = doc.count(Severity::Error), w = doc.count(Severity::Warning);
    ImGui::TextUnformatted(doc.name.c_str());
    ImGui::SameLine();
    if (e == 0 && w == 0) ImGui::TextColored(to_vec4(kOkColor), "ok");
    else if (e == 0) ImGui::TextColored(severity_color(Severity::Warning), "ok, %zu warning%s", w, w == 1 ? "" : "s");
    else ImGui::TextColored(severity_color(Severity::Error), "%zu error%s, %zu warning%s", e, e == 1 ? "" : "s", w, w == 1 ? "" : "s");
}

}  // namespace

void toolbar(App& app) {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kToolbarHeight));
    ImGui::Begin("##toolbar", nullptr, kPanelFlags | ImGuiWindowFlags_NoDecoration);
    open_button(app);
    ImGui::SameLine();
    if (ImGui::Button("Paste")) platform::paste(app);
    ImGui::SameLine();
    if (ImGui::Button("Share link")) app.share();
    ImGui::SameLine();
    export_menu(app);
    ImGui::SameLine();
    if (ImGui::Button("Fit (F)")) app.fit();
    ImGui::SameLine();
    Measure& measure = app.input().measure;
    if (ImGui::Checkbox("Measure (M)", &measure.active)) measure.points = 0;
    ImGui::SameLine();
    if (ImGui::Button("Help (H)")) app.ui().help = !app.ui().help;
    ImGui::SameLine();
    layout_menu(app);
    ImGui::SameLine();
    if (app.compare()) {
        if (ImGui::Button("End compare")) app.end_compare();
    } else if (ImGui::Button(app.compare_pending() ? "Compare: drop B" : "Compare...")) {
        app.begin_compare();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Compare this tape with another revision: drop or open it after this");
    ImGui::SameLine();
    profile_combo(app);
    ImGui::SameLine();
    orientation_combo(app);
    ImGui::SameLine();
    coordinates_combo(app);
    ImGui::SameLine();
    if (const Document* doc = app.document()) verdict(*doc);
    const UiState& ui = app.ui();
    if (!ui.message.empty() && glfwGetTime() < ui.message_until) {
        ImGui::SameLine();
        ImGui::TextColored(to_vec4(kMessageColor), "  %s", ui.message.c_str());
    }
    ImGui::End();
}

}  // namespace essi::viewer::panels
