// The share store (native/share_store.cpp): delete tokens, expiry, the size bound, reading a tape in pieces,
// and stores made before delete tokens existed.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "serve_limits.hpp"
#include "essi/sha256.hpp"
#include "share_store.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using namespace essi::native;

namespace {

std::unique_ptr<ShareStore> open_store(const fs::path& dir, StoreLimits limits = {}) {
    std::string error;
    auto store = ShareStore::open(dir.string(), error, limits);
    EXPECT_TRUE(store) << error;
    return store;
}

}  // namespace

TEST(ShareStoreLimits, DeleteNeedsTheUploadersToken) {
    const fs::path d = temp_dir("token");
    auto store = open_store(d);
    const auto put = store->put("+100+0\n63\n");
    ASSERT_TRUE(put.ok) << put.error;
    ASSERT_EQ(put.delete_token.size(), 64u);
    EXPECT_TRUE(store->put("+100+0\n63\n").delete_token.empty());  // a second uploader gets no token
    EXPECT_EQ(store->remove(put.id, ""), ShareStore::Removal::wrong_token);
    EXPECT_EQ(store->remove(put.id, essi::sha256_hex("guess")), ShareStore::Removal::wrong_token);
    EXPECT_EQ(store->remove(put.id, put.delete_token), ShareStore::Removal::removed);
    EXPECT_FALSE(store->get(put.id));
    EXPECT_EQ(store->remove(put.id, put.delete_token), ShareStore::Removal::missing);
    fs::remove_all(d);
}

TEST(ShareStoreLimits, ATapeIsReadInPieces) {
    const fs::path d = temp_dir("pieces");
    auto store = open_store(d);
    std::string tape;
    for (int i = 0; i < 30000; ++i) tape += "+" + std::to_string(i) + "+0\n";
    const auto put = store->put(tape);
    ASSERT_TRUE(put.ok) << put.error;
    ASSERT_EQ(store->size_of(put.id), tape.size());
    std::string back;
    char buf[4096];
    for (std::int64_t n; (n = store->read(put.id, back.size(), buf, sizeof buf)) > 0;)
        back.append(buf, static_cast<std::size_t>(n));
    EXPECT_EQ(back, tape);
    EXPECT_EQ(store->read(put.id, tape.size() + 5, buf, sizeof buf), 0);
    EXPECT_FALSE(store->size_of(essi::sha256_hex("never stored")));
    EXPECT_EQ(store->read(essi::sha256_hex("never stored"), 0, buf, sizeof buf), -1);
    ASSERT_EQ(store->remove(put.id, put.delete_token), ShareStore::Removal::removed);
    EXPECT_EQ(store->read(put.id, 0, buf, sizeof buf), -1);  // deleted while it was sent: the sending stops
}

TEST(ShareStoreLimits, ExpiredSharesAreGoneAndDeleted) {
    const fs::path d = temp_dir("ttl");
    auto store = open_store(d, StoreLimits{0, 1u << 20});  // every share expires at once
    const auto put = store->put("tape");
    ASSERT_TRUE(put.ok);
    EXPECT_FALSE(store->get(put.id));
    EXPECT_TRUE(store->put("tape").created);  // stored anew, with a new token
    fs::remove_all(d);
}

TEST(ShareStoreLimits, OldestGoFirstOverMaxBytes) {
    const fs::path d = temp_dir("evict");
    auto store = open_store(d, StoreLimits{3600, 10});
    const auto a = store->put("aaaaaa");
    const auto b = store->put("bbbbbb");
    ASSERT_TRUE(a.ok && b.ok);
    EXPECT_FALSE(store->get(a.id));
    EXPECT_EQ(*store->get(b.id), "bbbbbb");
    const auto huge = store->put("ccccccccccc");
    EXPECT_FALSE(huge.ok);
    EXPECT_TRUE(huge.too_large);
    EXPECT_TRUE(store->get(b.id));
    fs::remove_all(d);
}

TEST(ShareStoreLimits, OpensAStoreWithoutTokens) {
    const fs::path d = temp_dir("old");
    fs::create_directories(d);
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open((d / "shares.sqlite3").c_str(), &db), SQLITE_OK);
    const std::string id = essi::sha256_hex("old");
    const std::string sql =
        "CREATE TABLE shares (id TEXT PRIMARY KEY NOT NULL, size INTEGER NOT NULL, created_unix INTEGER "
        "NOT NULL, content BLOB NOT NULL); INSERT INTO shares VALUES ('" +
        id + "', 3, strftime('%s','now'), 'old');";
    ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
    auto store = open_store(d);
    ASSERT_TRUE(store);
    EXPECT_EQ(*store->get(id), "old");
    EXPECT_EQ(store->remove(id, "anything"), ShareStore::Removal::wrong_token);
    fs::remove_all(d);
}

TEST(ServeLimits, RateLimitPerClientPerMinute) {
    RateLimit rate(2);
    const auto t0 = RateLimit::Clock::now();
    EXPECT_EQ(rate.try_take("a", t0), 0u);
    EXPECT_EQ(rate.try_take("a", t0), 0u);
    EXPECT_EQ(rate.try_take("a", t0 + std::chrono::seconds(10)), 50u);
    EXPECT_EQ(rate.try_take("b", t0), 0u);  // another client
    EXPECT_EQ(rate.try_take("a", t0 + std::chrono::seconds(61)), 0u);
}

TEST(ServeLimits, ClientSlots) {
    ClientSlots slots(3, 2);
    EXPECT_TRUE(slots.enter("a"));
    EXPECT_TRUE(slots.enter("a"));
    EXPECT_FALSE(slots.enter("a"));
    EXPECT_TRUE(slots.enter("b"));
    EXPECT_FALSE(slots.enter("c"));  // 3 in all
    slots.leave("a");
    EXPECT_TRUE(slots.enter("c"));
}

TEST(ServeLimits, ClientKeyGroupsIpv6By64) {
    EXPECT_EQ(client_key("192.0.2.7"), "192.0.2.7");
    EXPECT_EQ(client_key("::ffff:192.0.2.7"), "192.0.2.7");
    EXPECT_EQ(client_key("2001:db8:1:2:aaaa:bbbb:cccc:dddd"), "2001:db8:1:2::/64");
    EXPECT_EQ(client_key("2001:db8:1:2::1"), client_key("2001:db8:1:2:ffff::9"));
    EXPECT_NE(client_key("2001:db8:1:2::1"), client_key("2001:db8:1:3::1"));
}
