// Lines of a tape (essi/lines.hpp): the line-end rule and the line index.
#include "essi/lines.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace essi {

namespace {

constexpr std::uint64_t bytes_of(unsigned char c) { return 0x0101010101010101ULL * c; }

}  // namespace

std::uint32_t column_of(std::string_view bytes, std::uint32_t offset) {
    std::uint32_t begin = offset;
    while (begin > 0 && !is_line_end(bytes[begin - 1])) --begin;
    return offset - begin + 1;
}

std::string_view line_text(std::string_view bytes, std::uint32_t offset) {
    if (offset > bytes.size()) return {};
    std::size_t begin = offset;
    while (begin > 0 && !is_line_end(bytes[begin - 1])) --begin;
    std::size_t end = offset;
    while (end < bytes.size() && !is_line_end(bytes[end])) ++end;
    return bytes.substr(begin, end - begin);
}

bool LineIndex::build(std::string_view bytes, std::size_t max_bytes) {
    const char* p = bytes.data();
    const std::size_t n = bytes.size();
    if (!started_) {
        started_ = true;
        starts_.assign(1, 0);
        lines_ = n == 0 ? 0 : 1;
        signed_lines_ = n > 0 && (p[0] == '+' || p[0] == '-');
        pos_ = 0;
    }
    std::size_t i = pos_;
    const std::size_t stop = n - i > max_bytes ? i + max_bytes : n;
    while (i < stop) {
        // Eight bytes at a time to the next control character (a byte below 0x0E: CR, LF, and rarely a tab or
        // worse): the lowest flagged byte is always one (the others may be borrows of it).
        if (i + 8 <= n) {
            std::uint64_t w;
            std::memcpy(&w, p + i, 8);
            const std::uint64_t below = (w - bytes_of(0x0E)) & ~w & bytes_of(0x80);
            if (below == 0) {
                i += 8;
                continue;
            }
            i += static_cast<std::size_t>(std::countr_zero(below)) / 8;  // (little-endian: WASM, x86, ARM)
        }
        const char c = p[i++];
        if (!is_line_end(c)) continue;
        if (i < n && is_line_end_pair(c, p[i])) ++i;
        if (i < n) {
            if (lines_ % kStride == 0) starts_.push_back(static_cast<std::uint32_t>(i));
            ++lines_;
            signed_lines_ += p[i] == '+' || p[i] == '-';
        }
    }
    pos_ = i;
    return pos_ >= n;
}

std::string_view LineIndex::line(std::string_view bytes, std::size_t n) const {
    if (n == 0 || n > lines_) return {};
    std::size_t i = starts_[(n - 1) / kStride];
    for (std::size_t skip = (n - 1) % kStride; skip > 0; --skip) {
        while (i < bytes.size() && !is_line_end(bytes[i])) ++i;
        if (i >= bytes.size()) return {};
        const char c = bytes[i++];
        if (i < bytes.size() && is_line_end_pair(c, bytes[i])) ++i;
    }
    std::size_t end = i;
    while (end < bytes.size() && !is_line_end(bytes[end])) ++end;
    return bytes.substr(i, end - i);
}

}  // namespace essi
