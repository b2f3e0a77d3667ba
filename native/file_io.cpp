#include "file_io.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace essi::native {

namespace {

constexpr std::size_t kReadChunkBytes = 1 << 16;

// Reads what is left of `f` in chunks (for streams whose size is unknown).
bool read_chunks(std::FILE* f, std::string& out, std::string& error) {
    std::size_t used = out.size();
    for (;;) {
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
    return true;
}

}  // namespace

ReadResult read_whole_file(const std::string& path) {
    ReadResult r;
    try {
        if (path == "-") {
            r.ok = read_chunks(stdin, r.owned, r.error);
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
        if (S_ISREG(st.st_mode) && st.st_size > 0) {
            // Regular file: map it read-only. A tape of 100 MB costs no copy and no allocation.
            const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
            if (fd < 0) {
                r.error = std::strerror(errno);
                return r;
            }
            const auto size = static_cast<std::size_t>(st.st_size);
            void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
            ::close(fd);
            if (p != MAP_FAILED) {
                r.mapping = std::shared_ptr<const void>(p, [size](const void* q) { ::munmap(const_cast<void*>(q), size); });
                r.bytes = std::string_view(static_cast<const char*>(p), size);
                r.ok = true;
                return r;
            }
            // mmap refused (some special file systems): fall through to reading.
        }
        std::FILE* f = std::fopen(path.c_str(), "rb");
        if (f == nullptr) {
            r.error = std::strerror(errno);
            return r;
        }
        bool ok = true;
        if (S_ISREG(st.st_mode) && st.st_size > 0) {
            // Regular file: one allocation, one read.
            const auto size = static_cast<std::size_t>(st.st_size);
            r.owned.resize(size);
            const std::size_t n = std::fread(r.owned.data(), 1, size, f);
            r.owned.resize(n);
            if (n < size && std::ferror(f)) {
                r.error = std::strerror(errno);
                ok = false;
            } else if (n == size) {
                // The file may have grown since stat(): take the rest too (rare, so only then
                // does the string grow past the size we allocated).
                const int c = std::fgetc(f);
                if (c != EOF) {
                    r.owned.push_back(static_cast<char>(c));
                    ok = read_chunks(f, r.owned, r.error);
                }
            }
        } else {
            ok = read_chunks(f, r.owned, r.error);
        }
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

}  // namespace essi::native
