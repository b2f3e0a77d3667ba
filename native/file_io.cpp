#include "file_io.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "essi/text_encoding.hpp"

namespace essi::native {

namespace {

constexpr std::size_t kReadChunkBytes = 1 << 16;
// Files of this size and more are read into a buffer of huge pages (file_buffer; not under Emscripten).
[[maybe_unused]] constexpr std::size_t kHugePageBufferBytes = std::size_t{4} << 20;

// Reads what is left of `f` in chunks (for streams whose size is unknown), at most `max_bytes` in all.
bool read_chunks(std::FILE* f, std::string& out, std::string& error, std::uint64_t max_bytes) {
    std::size_t used = out.size();
    for (;;) {
        if (used > max_bytes) {
            out.clear();
            out.shrink_to_fit();
            error = too_large_text(used, max_bytes, false);
            return false;
        }
        out.resize(used + kReadChunkBytes);
        const std::size_t n = std::fread(out.data() + used, 1, kReadChunkBytes, f);
        used += n;
        if (n < kReadChunkBytes) break;
    }
    out.resize(used);
    if (std::ferror(f)) {
        error = std::strerror(errno);
        return false;
    }
    if (used > max_bytes) {
        out.clear();
        error = too_large_text(used, max_bytes, false);
        return false;
    }
    return true;
}

std::string size_text(std::uint64_t bytes) {
    char buf[48];
    if (bytes >= (1ull << 30) && bytes % (1ull << 30) == 0)
        std::snprintf(buf, sizeof buf, "%lluGB", static_cast<unsigned long long>(bytes >> 30));
    else if (bytes >= (1ull << 20) && bytes % (1ull << 20) == 0)
        std::snprintf(buf, sizeof buf, "%lluMB", static_cast<unsigned long long>(bytes >> 20));
    else if (bytes >= (1ull << 10) && bytes % (1ull << 10) == 0)
        std::snprintf(buf, sizeof buf, "%lluKB", static_cast<unsigned long long>(bytes >> 10));
    else std::snprintf(buf, sizeof buf, "%llu", static_cast<unsigned long long>(bytes));
    return buf;
}

}  // namespace

std::string too_large_text(std::uint64_t size, std::uint64_t max_bytes, bool size_known) {
    const std::string limit = "--max-size " + size_text(max_bytes) + " (" + std::to_string(max_bytes) + " bytes)";
    return (size_known ? "the file has " + std::to_string(size) + " bytes, more than " : "the input is larger than ") +
           limit + "; raise --max-size to read it";
}

namespace {

// A buffer of `size` bytes that nothing initialises; null when there is no memory for it. From
// kHugePageBufferBytes on it is a mapping of its own with transparent huge pages asked for (madvise): read() then
// fills 2 MB pages, one fault each, where a heap buffer takes a fault every 4 KB (reading a 100 MB tape cost about
// 24 500 faults and 0.4 s of system time on a VM, a third of its check). Where the kernel has them off, 4 KB pages.
std::shared_ptr<char[]> file_buffer(std::size_t size) {
#if defined(MADV_HUGEPAGE) && !defined(__EMSCRIPTEN__)
    if (size >= kHugePageBufferBytes) {
        void* const p = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) return nullptr;
        ::madvise(p, size, MADV_HUGEPAGE);  // (a refusal leaves 4 KB pages: nothing else changes)
        return {static_cast<char*>(p), [size](char* q) { ::munmap(q, size); }};
    }
#endif
    return std::shared_ptr<char[]>(new (std::nothrow) char[size]);
}

// A regular file of `size` bytes (at stat time), read into one buffer that nothing initialises first. Not mapped: a
// file truncated while it is read would kill the process that reads the mapping (SIGBUS); read() instead returns
// what is there. A file that shrank is taken as it is now; one that grew, up to its size at stat time (which was
// within --max-size).
ReadResult read_regular_file(const std::string& path, std::size_t size) {
    ReadResult r;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        r.error = std::strerror(errno);
        return r;
    }
    std::shared_ptr<char[]> buffer = file_buffer(size);
    if (!buffer) {
        ::close(fd);
        r.error = "file too large for memory";
        return r;
    }
    std::size_t got = 0;
    while (got < size) {
        const ssize_t n = ::read(fd, buffer.get() + got, size - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            r.error = std::strerror(errno);
            ::close(fd);
            return r;
        }
        if (n == 0) break;  // (the file was truncated since stat)
        got += static_cast<std::size_t>(n);
    }
    ::close(fd);
    r.bytes = std::string_view(buffer.get(), got);
    r.storage = std::move(buffer);
    r.ok = true;
    return r;
}

}  // namespace

ReadResult read_whole_file(const std::string& path, std::uint64_t max_bytes) {
    ReadResult r;
    try {
        if (path == "-") {
            r.ok = read_chunks(stdin, r.owned, r.error, max_bytes);
            r.bytes = r.owned;
            return r;
        }
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0) {
            r.error = std::strerror(errno);
            return r;
        }
        if (S_ISDIR(st.st_mode)) {
            r.error = std::strerror(EISDIR);
            return r;
        }
        if (S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) > max_bytes) {
            r.error = too_large_text(static_cast<std::uint64_t>(st.st_size), max_bytes, true);  // not read
            return r;
        }
        if (S_ISREG(st.st_mode) && st.st_size > 0) return read_regular_file(path, static_cast<std::size_t>(st.st_size));
        std::FILE* f = std::fopen(path.c_str(), "rb");
        if (f == nullptr) {
            r.error = std::strerror(errno);
            return r;
        }
        const bool ok = read_chunks(f, r.owned, r.error, max_bytes);
        std::fclose(f);
        r.ok = ok;
        if (!ok) r.owned.clear();
        r.bytes = r.owned;
    } catch (const std::bad_alloc&) {
        r.ok = false;
        r.owned.clear();
        r.owned.shrink_to_fit();
        r.error = "file too large for memory";
    }
    return r;
}

ReadResult read_tape_file(const std::string& path, std::uint64_t max_bytes, Lang lang) {
    ReadResult file = read_whole_file(path, max_bytes);
    if (!file.ok) return file;
    TapeText text = decode_tape_text(file.bytes);
    if (!text.ok()) {
        file.ok = false;
        file.error = text.problem.text(lang);
    } else if (text.decoded) {
        file.owned = std::move(*text.decoded);
        file.bytes = file.owned;
        file.storage.reset();
    }
    return file;
}

}  // namespace essi::native
