// A deterministic EIA (RS-274, Woyda table) nesting tape for benchmarks and tests: the generated ESSI nesting
// tape (nest_generator.hpp) written as a Woyda controller reads EIA, block for block: functions as their G/M
// words (5 G05, 6 G06, 7 M70, 8 M71, 29 M67, 38 M69, 0 M00, 63 M02), 39+v as F, lines as X Y in mm with one
// decimal, arcs as G02/G03 X Y I J with the direction written only when it changes (modal, as Woyda allows), the
// 3/4 header as ( ) comments. It checks with no error under the woyda profile and has the ESSI tape's motion.
#pragma once

#include <charconv>
#include <string>
#include <string_view>

#include "nest_generator.hpp"

namespace essi::bench {

namespace detail {

// "-12.3" from -123 tenths.
inline void append_tenths(std::string& out, long long tenths) {
    if (tenths < 0) {
        out += '-';
        tenths = -tenths;
    }
    char buf[24];
    auto r = std::to_chars(buf, buf + sizeof buf, tenths / 10);
    out.append(buf, r.ptr);
    out += '.';
    out += static_cast<char>('0' + tenths % 10);
}

// The signed words of an ESSI motion line ("+100-20+0+5-": 100, -20, 0, 5 and the last sign).
inline int essi_words(std::string_view line, long long (&w)[6], bool& last_negative) {
    int n = 0;
    for (std::size_t i = 0; i < line.size() && n < 6;) {
        const bool neg = line[i] == '-';
        ++i;
        long long v = 0;
        while (i < line.size() && line[i] >= '0' && line[i] <= '9') v = v * 10 + (line[i++] - '0');
        w[n++] = neg ? -v : v;
        last_negative = neg;
    }
    return n;
}

inline const char* woyda_word(int function) {
    switch (function) {
        case 0: return "M00";
        case 5: return "G05";
        case 6: return "G06";
        case 7: return "M70";
        case 8: return "M71";
        case 29: return "M67";
        case 38: return "M69";
        case 63: return "M02";
        default: return nullptr;
    }
}

}  // namespace detail

inline std::string generate_eia_nest_tape(std::size_t target_bytes, unsigned seed) {
    // The ESSI tape is some 40 % shorter than its EIA form: generate a little less of it.
    const std::string essi = generate_nest_tape(target_bytes * 10 / 17, seed, LineEnding::Lf);
    std::string out;
    out.reserve(target_bytes + target_bytes / 4);
    out += "%\n";
    bool comment = false;
    int arc = 0;  // 0 none, 2 or 3: the G in force
    std::size_t pos = 0;
    while (pos < essi.size()) {
        std::size_t end = essi.find('\n', pos);
        if (end == std::string::npos) end = essi.size();
        const std::string_view line(essi.data() + pos, end - pos);
        pos = end + 1;
        if (line.empty()) continue;
        if (comment || line == "3") {
            if (line == "4") comment = false;
            else if (line != "3") out.append("(").append(line).append(")\n");
            else comment = true;
            continue;
        }
        if (line[0] == '+' || line[0] == '-') {
            long long w[6];
            bool ccw_negative = false;
            const int n = detail::essi_words(line, w, ccw_negative);
            if (n == 5) {
                const int g = ccw_negative ? 2 : 3;  // TC '-' clockwise: G02
                if (g != arc) out += g == 2 ? "G02 " : "G03 ";
                arc = g;
            }
            out += 'X';
            detail::append_tenths(out, w[0]);
            out += " Y";
            detail::append_tenths(out, w[1]);
            if (n == 5) {
                out += " I";
                detail::append_tenths(out, w[2]);
                out += " J";
                detail::append_tenths(out, w[3]);
            }
            out += '\n';
            continue;
        }
        const std::size_t plus = line.find('+');
        int function = 0;
        std::from_chars(line.data(), line.data() + (plus == std::string_view::npos ? line.size() : plus), function);
        if (plus != std::string_view::npos && function == 39) {
            out.append("F").append(line.substr(plus + 1)).append("\n");
        } else if (const char* word = detail::woyda_word(function)) {
            out.append(word).append("\n");
        }
    }
    return out;
}

}  // namespace essi::bench
