// The store of shared tapes behind `essi serve`'s /api/share: an SQLite database (Debian libsqlite3-dev) in the
// data folder, tapes content-addressed by SHA-256. Each write is one transaction: a crash leaves the tape either
// fully stored or absent, never half written (WAL, synchronous=FULL: an acknowledged share survives kill -9).
// Bounded: a share lives `ttl_s` seconds from its first upload (expired ones are deleted on the next put or get),
// and the stored bytes stay under `max_bytes` (expired shares go first, then the oldest).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

struct sqlite3;

namespace essi::native {

struct StoreLimits {
    std::int64_t ttl_s = 30ll * 24 * 3600;  // 30 days
    std::uint64_t max_bytes = 1ull << 30;   // 1 GiB of tapes
};

class ShareStore {
public:
    // Opens (creates) DIR/shares.sqlite3, creating DIR when needed. nullptr with `error` set on failure.
    static std::unique_ptr<ShareStore> open(const std::string& dir, std::string& error, StoreLimits limits = {});
    ~ShareStore();
    ShareStore(const ShareStore&) = delete;
    ShareStore& operator=(const ShareStore&) = delete;

    struct PutResult {
        bool ok = false;
        bool created = false;      // false: the same content was already stored
        bool too_large = false;    // the tape alone is over max_bytes (not stored)
        std::string id;            // sha256_hex(bytes)
        std::string delete_token;  // only when created: DELETE /api/share/ID needs it
        std::int64_t expires_unix = 0;
        std::string error;
    };
    PutResult put(std::string_view bytes);
    // The tape stored under `id`, nullopt when there is none (or it expired: then it is deleted).
    std::optional<std::string> get(std::string_view id);
    // The size of the tape stored under `id`, as get() finds it (without reading the tape).
    std::optional<std::uint64_t> size_of(std::string_view id);
    // Reads up to `n` bytes of the tape `id` from `offset` into `out` (SQLite's incremental blob I/O: never the
    // whole tape in memory); the count read, 0 at the end, -1 when the tape is no longer there.
    std::int64_t read(std::string_view id, std::uint64_t offset, char* out, std::size_t n);
    enum class Removal { removed, missing, wrong_token, failed };
    // Deletes the share `id` when `token` is the delete token its upload returned.
    Removal remove(std::string_view id, std::string_view token);
    [[nodiscard]] const std::string& path() const { return path_; }

private:
    ShareStore() = default;
    bool delete_expired(std::int64_t now, std::string& error);
    bool evict_to_fit(std::string& error);
    bool insert(std::string_view bytes, PutResult& r, std::int64_t now);
    sqlite3* db_ = nullptr;
    std::string path_;
    StoreLimits limits_;
    std::mutex mutex_;
};

// The default data folder: $XDG_DATA_HOME/essikit when XDG_DATA_HOME is set, else ./essi-data.
[[nodiscard]] std::string default_data_dir();

}  // namespace essi::native
