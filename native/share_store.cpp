#include "share_store.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <openssl/rand.h>
#include <sqlite3.h>

#include "essi/sha256.hpp"

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

bool bind_text(sqlite3_stmt* s, int i, std::string_view v) {
    return sqlite3_bind_text(s, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT) == SQLITE_OK;
}

std::int64_t unix_now() {
    return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

// 32 random bytes (OpenSSL's CSPRNG) as 64 hex digits; "" when the generator fails.
std::string random_token() {
    unsigned char bytes[32];
    if (RAND_bytes(bytes, sizeof bytes) != 1) return {};
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    for (unsigned char b : bytes) out += {kHex[b >> 4], kHex[b & 15]};
    return out;
}

const char* const kSchema =
    "CREATE TABLE IF NOT EXISTS shares ("
    " id TEXT PRIMARY KEY NOT NULL,"  // sha256 of the content, 64 hex digits
    " size INTEGER NOT NULL,"
    " created_unix INTEGER NOT NULL,"
    " content BLOB NOT NULL);"
    "CREATE INDEX IF NOT EXISTS shares_by_age ON shares (created_unix);";

// Stores made before delete tokens have no token column: add it (their shares cannot be deleted by token).
bool add_token_column(sqlite3* db, std::string& error) {
    Stmt st;
    if (sqlite3_prepare_v2(db, "SELECT 1 FROM pragma_table_info('shares') WHERE name = 'token_sha256'", -1, &st.s,
                           nullptr) != SQLITE_OK) {
        error = sqlite3_errmsg(db);
        return false;
    }
    if (sqlite3_step(st.s) == SQLITE_ROW) return true;
    return exec(db, "ALTER TABLE shares ADD COLUMN token_sha256 TEXT", error);
}

void rollback(sqlite3* db) {
    std::string ignored;
    exec(db, "ROLLBACK", ignored);
}

}  // namespace

std::string default_data_dir() {
    const char* xdg = std::getenv("XDG_DATA_HOME");
    if (xdg && *xdg) return (std::filesystem::path(xdg) / "essikit").string();
    return "essi-data";
}

std::unique_ptr<ShareStore> ShareStore::open(const std::string& dir, std::string& error, StoreLimits limits) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        error = "cannot create " + dir + ": " + ec.message();
        return nullptr;
    }
    std::unique_ptr<ShareStore> store(new ShareStore());
    store->limits_ = limits;
    store->path_ = (std::filesystem::path(dir) / "shares.sqlite3").string();
    if (sqlite3_open_v2(store->path_.c_str(), &store->db_,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX, nullptr) != SQLITE_OK) {
        error = "cannot open " + store->path_ + ": " + (store->db_ ? sqlite3_errmsg(store->db_) : "out of memory");
        return nullptr;
    }
    sqlite3_busy_timeout(store->db_, 5000);
    // WAL + synchronous FULL: a committed tape survives a crash or power loss; an interrupted write is rolled back.
    if (!exec(store->db_, "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;", error) ||
        !exec(store->db_, kSchema, error) || !add_token_column(store->db_, error)) {
        error = store->path_ + ": " + error;
        return nullptr;
    }
    return store;
}

ShareStore::~ShareStore() { sqlite3_close_v2(db_); }

bool ShareStore::delete_expired(std::int64_t now, std::string& error) {
    Stmt st;
    const bool ok =
        sqlite3_prepare_v2(db_, "DELETE FROM shares WHERE created_unix + ?1 <= ?2", -1, &st.s, nullptr) == SQLITE_OK &&
        sqlite3_bind_int64(st.s, 1, limits_.ttl_s) == SQLITE_OK && sqlite3_bind_int64(st.s, 2, now) == SQLITE_OK &&
        sqlite3_step(st.s) == SQLITE_DONE;
    if (!ok) error = sqlite3_errmsg(db_);
    return ok;
}

// Deletes the oldest shares until the rest fit in max_bytes (newest first; the one just stored is the newest).
bool ShareStore::evict_to_fit(std::string& error) {
    Stmt st;
    const char* sql =
        "DELETE FROM shares WHERE id IN (SELECT id FROM (SELECT id, SUM(size) OVER "
        "(ORDER BY created_unix DESC, rowid DESC) AS kept FROM shares) WHERE kept > ?1)";
    const bool ok = sqlite3_prepare_v2(db_, sql, -1, &st.s, nullptr) == SQLITE_OK &&
                    sqlite3_bind_int64(st.s, 1, static_cast<sqlite3_int64>(limits_.max_bytes)) == SQLITE_OK &&
                    sqlite3_step(st.s) == SQLITE_DONE;
    if (!ok) error = sqlite3_errmsg(db_);
    return ok;
}

bool ShareStore::insert(std::string_view bytes, PutResult& r, std::int64_t now) {
    const std::string token = random_token();
    Stmt st;
    const char* sql =
        "INSERT OR IGNORE INTO shares (id, size, created_unix, content, token_sha256) VALUES (?1, ?2, ?3, ?4, ?5)";
    const bool ok = !token.empty() && sqlite3_prepare_v2(db_, sql, -1, &st.s, nullptr) == SQLITE_OK &&
                    bind_text(st.s, 1, r.id) &&
                    sqlite3_bind_int64(st.s, 2, static_cast<sqlite3_int64>(bytes.size())) == SQLITE_OK &&
                    sqlite3_bind_int64(st.s, 3, now) == SQLITE_OK &&
                    sqlite3_bind_blob64(st.s, 4, bytes.data(), bytes.size(), SQLITE_STATIC) == SQLITE_OK &&
                    bind_text(st.s, 5, sha256_hex(token)) && sqlite3_step(st.s) == SQLITE_DONE;
    if (!ok) {
        r.error = token.empty() ? "no random bytes for the delete token" : sqlite3_errmsg(db_);
        return false;
    }
    r.created = sqlite3_changes(db_) > 0;
    if (r.created) r.delete_token = token;
    Stmt age;
    if (sqlite3_prepare_v2(db_, "SELECT created_unix FROM shares WHERE id = ?1", -1, &age.s, nullptr) == SQLITE_OK &&
        bind_text(age.s, 1, r.id) && sqlite3_step(age.s) == SQLITE_ROW) {
        r.expires_unix = sqlite3_column_int64(age.s, 0) + limits_.ttl_s;
    }
    return true;
}

ShareStore::PutResult ShareStore::put(std::string_view bytes) {
    PutResult r;
    r.id = sha256_hex(bytes);
    if (bytes.size() > limits_.max_bytes) {
        r.too_large = true;
        r.error = "the tape is larger than the whole store (--max-store)";
        return r;
    }
    std::lock_guard lock(mutex_);
    if (!exec(db_, "BEGIN IMMEDIATE", r.error)) return r;
    const std::int64_t now = unix_now();
    if (!delete_expired(now, r.error) || !insert(bytes, r, now) || !evict_to_fit(r.error)) {
        rollback(db_);
        r.delete_token.clear();
        return r;
    }
    if (!exec(db_, "COMMIT", r.error)) {
        rollback(db_);
        r.delete_token.clear();
        return r;
    }
    r.ok = true;
    return r;
}

std::optional<std::string> ShareStore::get(std::string_view id) {
    std::lock_guard lock(mutex_);
    std::string ignored;
    delete_expired(unix_now(), ignored);
    Stmt st;
    if (sqlite3_prepare_v2(db_, "SELECT content FROM shares WHERE id = ?1", -1, &st.s, nullptr) != SQLITE_OK)
        return std::nullopt;
    bind_text(st.s, 1, id);
    if (sqlite3_step(st.s) != SQLITE_ROW) return std::nullopt;
    const void* data = sqlite3_column_blob(st.s, 0);
    const int n = sqlite3_column_bytes(st.s, 0);
    return std::string(static_cast<const char*>(data ? data : ""), static_cast<std::size_t>(n));
}

std::optional<std::uint64_t> ShareStore::size_of(std::string_view id) {
    std::lock_guard lock(mutex_);
    std::string ignored;
    delete_expired(unix_now(), ignored);
    Stmt st;
    if (sqlite3_prepare_v2(db_, "SELECT size FROM shares WHERE id = ?1", -1, &st.s, nullptr) != SQLITE_OK)
        return std::nullopt;
    bind_text(st.s, 1, id);
    if (sqlite3_step(st.s) != SQLITE_ROW) return std::nullopt;
    return static_cast<std::uint64_t>(sqlite3_column_int64(st.s, 0));
}

std::int64_t ShareStore::read(std::string_view id, std::uint64_t offset, char* out, std::size_t n) {
    std::lock_guard lock(mutex_);
    Stmt st;
    if (sqlite3_prepare_v2(db_, "SELECT rowid FROM shares WHERE id = ?1", -1, &st.s, nullptr) != SQLITE_OK) return -1;
    bind_text(st.s, 1, id);
    if (sqlite3_step(st.s) != SQLITE_ROW) return -1;
    sqlite3_blob* blob = nullptr;
    if (sqlite3_blob_open(db_, "main", "shares", "content", sqlite3_column_int64(st.s, 0), 0, &blob) != SQLITE_OK) {
        sqlite3_blob_close(blob);
        return -1;
    }
    const auto size = static_cast<std::uint64_t>(sqlite3_blob_bytes(blob));
    const std::size_t take = offset >= size ? 0 : static_cast<std::size_t>(std::min<std::uint64_t>(n, size - offset));
    const bool ok =
        take == 0 || sqlite3_blob_read(blob, out, static_cast<int>(take), static_cast<int>(offset)) == SQLITE_OK;
    sqlite3_blob_close(blob);
    return ok ? static_cast<std::int64_t>(take) : -1;
}

ShareStore::Removal ShareStore::remove(std::string_view id, std::string_view token) {
    std::lock_guard lock(mutex_);
    std::string ignored;
    delete_expired(unix_now(), ignored);
    Stmt find;
    if (sqlite3_prepare_v2(db_, "SELECT token_sha256 FROM shares WHERE id = ?1", -1, &find.s, nullptr) != SQLITE_OK ||
        !bind_text(find.s, 1, id)) {
        return Removal::failed;
    }
    if (sqlite3_step(find.s) != SQLITE_ROW) return Removal::missing;
    const unsigned char* stored = sqlite3_column_text(find.s, 0);
    if (!stored || token.empty() || sha256_hex(token) != reinterpret_cast<const char*>(stored))
        return Removal::wrong_token;
    Stmt del;
    const bool ok = sqlite3_prepare_v2(db_, "DELETE FROM shares WHERE id = ?1", -1, &del.s, nullptr) == SQLITE_OK &&
                    bind_text(del.s, 1, id) && sqlite3_step(del.s) == SQLITE_DONE;
    return ok ? Removal::removed : Removal::failed;
}

}  // namespace essi::native
