// The store of shared tapes behind `essi serve`'s /api/share: an SQLite database (Debian libsqlite3-dev) in the
// data folder, tapes content-addressed by SHA-256. Each write is one transaction: a crash leaves the tape either
// fully stored or absent, never half written.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

struct sqlite3;

namespace essi::native {

class ShareStore {
public:
    // Opens (creates) DIR/shares.sqlite3, creating DIR when needed. nullptr with `error` set on failure.
    static std::unique_ptr<ShareStore> open(const std::string& dir, std::string& error);
    ~ShareStore();
    ShareStore(const ShareStore&) = delete;
    ShareStore& operator=(const ShareStore&) = delete;

    struct PutResult {
        bool ok = false;
        bool created = false;  // false: the same content was already stored
        std::string id;        // sha256_hex(bytes)
        std::string error;
    };
    PutResult put(std::string_view bytes);
    // The tape stored under `id`, nullopt when there is none.
    std::optional<std::string> get(std::string_view id);
    [[nodiscard]] const std::string& path() const { return path_; }

private:
    ShareStore() = default;
    sqlite3* db_ = nullptr;
    std::string path_;
    std::mutex mutex_;
};

// The default data folder: $XDG_DATA_HOME/essikit when XDG_DATA_HOME is set, else ./essi-data.
[[nodiscard]] std::string default_data_dir();

}  // namespace essi::native
