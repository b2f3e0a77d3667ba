// printf into a std::string, for the document's sentences and the panels.
#pragma once

#include <cstdio>
#include <string>

namespace essi::viewer {

// printf into a std::string (at most 1023 characters).
template <class... Args>
std::string fmt(const char* format, Args... args) {
    char buf[1024];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

}  // namespace essi::viewer
