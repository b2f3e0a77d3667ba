// Plain values as bytes, to hand data from one instance of a build to another of the same build (the viewer's
// reading worker to its page; a reader's checkpoint). Values are written as they lie in memory: both sides are
// the same program, so there is no versioning and no byte-order conversion. A reader never reads past its
// bytes: every get is checked, and its result must be looked at.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace essi {

// Only values without padding bytes are written as they lie in memory: a padding byte's value is undefined, so
// one value could be written two ways (a struct with padding is written a member at a time). Structs of floating-
// point members, which std::has_unique_object_representations cannot vouch for, say they have none by
// specializing WireFloats next to their definition.
template <class T>
struct WireFloats : std::false_type {};
template <class T>
inline constexpr bool kWirePlain =
    std::is_arithmetic_v<T> || std::is_enum_v<T> || std::has_unique_object_representations_v<T> || WireFloats<T>::value;

class WireWriter {
public:
    template <class T>
    void put(const T& v) {
        static_assert(kWirePlain<T>, "only plain values (no padding) are written as they lie in memory");
        out_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    // Several plain values, one after the other.
    template <class... T>
    void put_all(const T&... v) {
        (put(v), ...);
    }
    void put_string(std::string_view s) {
        put<std::uint64_t>(s.size());
        out_.append(s);
    }
    template <class T>
    void put_vector(const std::vector<T>& v) {
        static_assert(kWirePlain<T>, "only plain values (no padding) are written as they lie in memory");
        put<std::uint64_t>(v.size());
        if (!v.empty()) out_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    // A count, then each item as `write(item)` writes it.
    template <class Items, class Write>
    void put_items(const Items& items, Write write) {
        put<std::uint64_t>(items.size());
        for (const auto& item : items) write(item);
    }
    [[nodiscard]] std::size_t size() const { return out_.size(); }
    [[nodiscard]] std::string take() { return std::move(out_); }

private:
    std::string out_;
};

class WireReader {
public:
    explicit WireReader(std::string_view in) : in_(in) {}

    template <class T>
    [[nodiscard]] bool get(T& v) {
        static_assert(kWirePlain<T>, "only plain values (no padding) are read as they lie in memory");
        if (in_.size() - pos_ < sizeof v) return false;
        std::memcpy(&v, in_.data() + pos_, sizeof v);
        pos_ += sizeof v;
        return true;
    }
    // Several plain values, one after the other: false at the first that fails.
    template <class... T>
    [[nodiscard]] bool get_all(T&... v) {
        return (get(v) && ...);
    }
    [[nodiscard]] bool get_string(std::string& s) {
        std::uint64_t n = 0;
        if (!get(n) || n > in_.size() - pos_) return false;
        s.assign(in_.data() + pos_, static_cast<std::size_t>(n));
        pos_ += static_cast<std::size_t>(n);
        return true;
    }
    template <class T>
    [[nodiscard]] bool get_vector(std::vector<T>& v) {
        static_assert(kWirePlain<T>, "only plain values (no padding) are read as they lie in memory");
        std::uint64_t n = 0;
        if (!get_count(n, sizeof(T))) return false;
        v.resize(static_cast<std::size_t>(n));
        if (n > 0) std::memcpy(v.data(), in_.data() + pos_, static_cast<std::size_t>(n) * sizeof(T));
        pos_ += static_cast<std::size_t>(n) * sizeof(T);
        return true;
    }
    // A count of items that take at least `min_bytes` each: false when the bytes left cannot hold them (so that
    // no count read from bad bytes makes the caller allocate more than the bytes could fill).
    [[nodiscard]] bool get_count(std::uint64_t& n, std::size_t min_bytes) {
        if (!get(n)) return false;
        return min_bytes == 0 || n <= (in_.size() - pos_) / min_bytes;
    }
    // What put_items wrote, into `v` (emptied first): a count of items that take at least `min_bytes` each, then
    // each item as `read(item)` reads it into a new element; false at the first that fails. (Room for the count is
    // made at once: at most sizeof(T) / min_bytes times the bytes left.)
    template <class T, class Read>
    [[nodiscard]] bool get_items(std::vector<T>& v, std::size_t min_bytes, Read read) {
        std::uint64_t n = 0;
        if (!get_count(n, min_bytes)) return false;
        v.clear();
        v.reserve(static_cast<std::size_t>(n));
        for (std::uint64_t k = 0; k < n; ++k)
            if (!read(v.emplace_back())) return false;
        return true;
    }
    // The bytes read so far (where a failed get stopped).
    [[nodiscard]] std::size_t position() const { return pos_; }
    [[nodiscard]] bool at_end() const { return pos_ == in_.size(); }

private:
    std::string_view in_;
    std::size_t pos_ = 0;
};

}  // namespace essi
