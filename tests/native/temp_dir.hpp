// A fresh, empty folder for one native test: <tmp>/essi_native_test_NAME_PID, emptied first.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

inline std::filesystem::path temp_dir(const std::string& name) {
    const std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("essi_native_test_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}
