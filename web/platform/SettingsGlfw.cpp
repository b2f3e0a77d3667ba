// Viewer settings on the desktop: one line "NAME VALUE" each (the value the rest of the line) in
// $XDG_CONFIG_HOME/essikit/viewer.conf (else
// ~/.config/essikit/viewer.conf), kept across sessions.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {
namespace {

std::filesystem::path settings_file() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "essikit/viewer.conf";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".config/essikit/viewer.conf";
    return {};
}

std::map<std::string, std::string> read_all() {
    std::map<std::string, std::string> all;
    std::ifstream in(settings_file());
    std::string line;
    while (std::getline(in, line)) {
        const std::size_t space = line.find(' ');
        if (space != std::string::npos && space > 0) all[line.substr(0, space)] = line.substr(space + 1);
    }
    return all;
}

}  // namespace

std::optional<std::string> Platform::load_setting(const char* name) {
    const auto all = read_all();
    const auto it = all.find(name);
    if (it == all.end()) return std::nullopt;
    return it->second;
}

void Platform::save_setting(const char* name, const std::string& text) {
    const std::filesystem::path file = settings_file();
    if (file.empty()) return;
    std::string value = text;
    std::replace(value.begin(), value.end(), '\n', ' ');  // (one line)
    std::replace(value.begin(), value.end(), '\r', ' ');
    auto all = read_all();
    all[name] = value;
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    std::ofstream out(file, std::ios::trunc);
    for (const auto& [n, v] : all) out << n << ' ' << v << '\n';
}

// The environment's (LC_ALL, LC_MESSAGES, LANG); essi_viewer --lang sets the language after this (not kept).
Lang Platform::system_language() {
    return lang_from_environment(std::getenv("LC_ALL"), std::getenv("LC_MESSAGES"), std::getenv("LANG"));
}

void Platform::show_language(Lang) {}

}  // namespace essi::viewer::platform
