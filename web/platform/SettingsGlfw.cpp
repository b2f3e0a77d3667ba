// Viewer settings on the desktop: one line "NAME VALUE" each in $XDG_CONFIG_HOME/essikit/viewer.conf (else
// ~/.config/essikit/viewer.conf), kept across sessions.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "platform/Platform.hpp"

namespace essi::viewer::platform {
namespace {

std::filesystem::path settings_file() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "essikit/viewer.conf";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".config/essikit/viewer.conf";
    return {};
}

std::map<std::string, int> read_all() {
    std::map<std::string, int> all;
    std::ifstream in(settings_file());
    std::string name;
    int value = 0;
    while (in >> name >> value) all[name] = value;
    return all;
}

}  // namespace

std::optional<int> load_setting(const char* name) {
    const auto all = read_all();
    const auto it = all.find(name);
    if (it == all.end()) return std::nullopt;
    return it->second;
}

void save_setting(const char* name, int value) {
    const std::filesystem::path file = settings_file();
    if (file.empty()) return;
    auto all = read_all();
    all[name] = value;
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    std::ofstream out(file, std::ios::trunc);
    for (const auto& [n, v] : all) out << n << ' ' << v << '\n';
}

}  // namespace essi::viewer::platform
