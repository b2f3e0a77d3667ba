// Lines of a tape (essi/lines.hpp): the line-end rule and the line index.
#include "essi/lines.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace essi {

namespace {

constexpr std::uint64_t bytes_of(unsigned char c) { return 0x0101010101010101ULL * c; }

// The first control character (a byte below 0x0E: CR, LF, and rarely a tab or worse) of the eight bytes at p + i
// (all there to read), or i + 8 when none of them is one. The lowest flagged byte is always one (the others may
// be borrows of it).
std::size_t next_control_byte(const char* p, std::size_t i) {
    std::uint64_t w;
    std::memcpy(&w, p + i, 8);
    const std::uint64_t below = (w - bytes_of(0x0E)) & ~w & bytes_of(0x80);
    if (below == 0) return i + 8;
    return i + static_cast<std::size_t>(std::countr_zero(below)) / 8;  // (little-endian: WASM, x86, ARM)
}

}  // namespace

std::size_t find_line_end(std::string_view bytes, std::size_t pos) {
    const char* p = bytes.data();
    const std::size_t n = bytes.size();
    while (pos < n) {
        if (pos + 8 <= n) {
            const std::size_t at = next_control_byte(p, pos);
            if (at == pos + 8) {
                pos = at;
                continue;
            }
            pos = at;
        }
        if (is_line_end(p[pos])) return pos;
        ++pos;
    }
    return n;
}

std::uint32_t column_of(std::string_view bytes, std::uint32_t offset) {
    return offset - static_cast<std::uint32_t>(find_line_start(bytes, offset)) + 1;
}

std::string_view line_text(std::string_view bytes, std::uint32_t offset) {
    if (offset > bytes.size()) return {};
    const std::size_t begin = find_line_start(bytes, offset);
    return bytes.substr(begin, find_line_end(bytes, offset) - begin);
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
        if (i + 8 <= n) {  // eight bytes at a time to the next control character
            const std::size_t at = next_control_byte(p, i);
            if (at == i + 8) {
                i = at;
                continue;
            }
            i = at;
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
        i = find_line_end(bytes, i);
        if (i >= bytes.size()) return {};
        const char c = bytes[i++];
        if (i < bytes.size() && is_line_end_pair(c, bytes[i])) ++i;
    }
    return bytes.substr(i, find_line_end(bytes, i) - i);
}

void LineIndex::save(WireWriter& out) const {
    out.put_vector(starts_);
    out.put<std::uint64_t>(lines_);
    out.put<std::uint64_t>(signed_lines_);
    out.put<std::uint64_t>(pos_);
    out.put(started_);
}

bool LineIndex::restore(WireReader& in) {
    std::uint64_t lines = 0, signed_lines = 0, pos = 0;
    if (!in.get_vector(starts_) || !in.get(lines) || !in.get(signed_lines) || !in.get(pos) || !in.get(started_))
        return false;
    lines_ = static_cast<std::size_t>(lines);
    signed_lines_ = static_cast<std::size_t>(signed_lines);
    pos_ = static_cast<std::size_t>(pos);
    return starts_.size() * kStride >= lines_;  // (line() finds a start for every line)
}

}  // namespace essi
