#include "share_store.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <sqlite3.h>

#include "sha256.hpp"

namespace essi::native {

namespace {

struct Stmt {
    sqlite3_stmt* s = nullptr;
    ~Stmt() { sqlite3_finalize(s); }
};

bool exec(sqlite3* db, const char* sql, std::string& error) {
    char* msg = nullptr;
    if (sqlite3_exec(db, sql, nullptr, nullptr, &msg) != SQLITE_OK) {
        error = msg ? msg : sqlite3_errmsg(db);
        sqlite3_free(msg);
        return false;
    }
    return true;
}

}  // namespace

std::string default_data_dir() {
    const char* xdg = std::getenv("XDG_DATA_HOME");
    if (xdg && *xdg) return (std::filesystem::path(xdg) / "essikit").string();
    return "essi-data";
}

std::unique_ptr<ShareStore> ShareStore::open(const std::string& dir, std::string& error) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        error = "cannot create " + dir + ": " + ec.message();
        return nullptr;
    }
    std::unique_ptr<ShareStore> store(new ShareStore());
    store->path_ = (std::filesystem::path(dir) / "shares.sqlite3").string();
    if (sqlite3_open_v2(store->path_.c_str(), &store->db_,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX, nullptr) != SQLITE_OK) {
        error = "cannot open " + store->path_ + ": " + (store->db_ ? sqlite3_errmsg(store->db_) : "out of memory");
        return nullptr;
    }
    sqlite3_busy_timeout(store->db_, 5000);
    // WAL + synchronous FULL: a committed tape survives a crash or power loss; an interrupted write is rolled back.
    if (!exec(store->db_, "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;", error) ||
        !exec(store->db_,
              "CREATE TABLE IF NOT EXISTS shares ("
              " id TEXT PRIMARY KEY NOT NULL,"   // sha256 of the content, 64 hex digits
              " size INTEGER NOT NULL,"
              " created_unix INTEGER NOT NULL,"
              " content BLOB NOT NULL)",
              error)) {
        error = store->path_ + ": " + error;
        return nullptr;
    }
    return store;
}

ShareStore::~ShareStore() { sqlite3_close_v2(db_); }

ShareStore::PutResult ShareStore::put(std::string_view bytes) {
    PutResult r;
    r.id = sha256_hex(bytes);
    std::lock_guard lock(mutex_);
    if (!exec(db_, "BEGIN IMMEDIATE", r.error)) return r;
    Stmt st;
    const char* sql = "INSERT OR IGNORE INTO shares (id, size, created_unix, content) VALUES (?1, ?2, ?3, ?4)";
    const auto now = std::chrono::duration_cast<std::chrono::seconds>(
                         std::chrono::system_clock::now().time_since_epoch()).count();
    bool ok = sqlite3_prepare_v2(db_, sql, -1, &st.s, nullptr) == SQLITE_OK &&
              sqlite3_bind_text(st.s, 1, r.id.data(), static_cast<int>(r.id.size()), SQLITE_TRANSIENT) == SQLITE_OK &&
              sqlite3_bind_int64(st.s, 2, static_cast<sqlite3_int64>(bytes.size())) == SQLITE_OK &&
              sqlite3_bind_int64(st.s, 3, now) == SQLITE_OK &&
              sqlite3_bind_blob64(st.s, 4, bytes.data(), bytes.size(), SQLITE_STATIC) == SQLITE_OK &&
              sqlite3_step(st.s) == SQLITE_DONE;
    if (!ok) {
        r.error = sqlite3_errmsg(db_);
        std::string ignored;
        exec(db_, "ROLLBACK", ignored);
        return r;
    }
    r.created = sqlite3_changes(db_) > 0;
    if (!exec(db_, "COMMIT", r.error)) {
        std::string ignored;
        exec(db_, "ROLLBACK", ignored);
        return r;
    }
    r.ok = true;
    return r;
}

std::optional<std::string> ShareStore::get(std::string_view id) {
    std::lock_guard lock(mutex_);
    Stmt st;
    if (sqlite3_prepare_v2(db_, "SELECT content FROM shares WHERE id = ?1", -1, &st.s, nullptr) != SQLITE_OK) return std::nullopt;
    sqlite3_bind_text(st.s, 1, id.data(), static_cast<int>(id.size()), SQLITE_TRANSIENT);
    if (sqlite3_step(st.s) != SQLITE_ROW) return std::nullopt;
    const void* data = sqlite3_column_blob(st.s, 0);
    const int n = sqlite3_column_bytes(st.s, 0);
    return std::string(static_cast<const char*>(data ? data : ""), static_cast<std::size_t>(n));
}

}  // namespace essi::native
