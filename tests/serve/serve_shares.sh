#!/usr/bin/env bash
# The share store of `essi serve` under hostile use (docs/security.md): delete tokens, expiry (--share-ttl), the
# upload rate limit (--share-rate), the size bound (--max-store), and no acknowledged share lost after kill -9.
# Usage: serve_shares.sh PATH/TO/essi
essi="${1:?usage: serve_shares.sh ESSI}"
source "$(dirname "$0")/lib.sh"
make_web_root
oct=(-H 'Content-Type: application/octet-stream')
share() { curl -sS -H 'Expect:' "${oct[@]}" --data-binary "$1" "$url/api/share"; }
json_field() { python3 -c 'import json,sys; print(json.load(sys.stdin).get(sys.argv[1], ""))' "$1"; }

# --- delete tokens -----------------------------------------------------------------------------------------------
start_server a --data "$tmp/data"
reply="$(share '+100+0
63
')"
id="$(json_field id <<<"$reply")"; token="$(json_field delete_token <<<"$reply")"
[[ "$token" =~ ^[0-9a-f]{64}$ ]] && pass "POST returns a delete_token" || fail "no delete_token: $reply"
again="$(share '+100+0
63
')"
[ -z "$(json_field delete_token <<<"$again")" ] && pass "a second upload of the same bytes gets no token" || fail "second upload got a token: $again"
expect "DELETE without token: 403" 403 '"error":"wrong or missing delete token' -- -X DELETE "$url/api/share/$id"
expect "DELETE with a wrong token: 403" 403 '"error"' -- -X DELETE -H "X-Delete-Token: $(printf x | sha256sum | cut -c1-64)" "$url/api/share/$id"
expect "still there" 200 '63' -- "$url/api/share/$id"
expect "DELETE with the token: 204" 204 '' -- -X DELETE -H "X-Delete-Token: $token" "$url/api/share/$id"
expect "gone: 404" 404 '"error":"no shared tape' -- "$url/api/share/$id"
expect "DELETE again: 404" 404 '"error"' -- -X DELETE -H "X-Delete-Token: $token" "$url/api/share/$id"
reply="$(share 'second tape')"; id2="$(json_field id <<<"$reply")"; token2="$(json_field delete_token <<<"$reply")"
expect "DELETE with ?token=: 204" 204 '' -- -X DELETE "$url/api/share/$id2?token=$token2"
expect "DELETE bad id: 400" 400 '"error":"bad share id' -- -X DELETE "$url/api/share/xyz"

# --- kill -9: every acknowledged share is still there --------------------------------------------------------------
acked=()
for i in $(seq 1 20); do
  r="$(printf 'tape %d\n63\n' "$i" | curl -sS -H 'Expect:' "${oct[@]}" --data-binary @- -w ' %{http_code}' "$url/api/share")"
  [ "${r##* }" = 201 ] && acked+=("$(json_field id <<<"${r% *}")")
done
kill -9 "$server_pid"; wait "$server_pid" 2>/dev/null; server_pid=""
start_server b --data "$tmp/data"
lost=0
for a in "${acked[@]}"; do [ "$(curl -sS -o /dev/null -w '%{http_code}' "$url/api/share/$a")" = 200 ] || lost=$((lost + 1)); done
[ "${#acked[@]}" = 20 ] && [ $lost = 0 ] && pass "kill -9: ${#acked[@]} acknowledged shares, none lost" || fail "kill -9: ${#acked[@]} acknowledged, $lost lost"
stop_server

# --- expiry ------------------------------------------------------------------------------------------------------
# (8 s: a loaded CI machine may take seconds between the upload and the first read; expires_unix is the upload's
# second + the TTL, whatever the machine's speed: between the seconds read before and after the upload)
start_server ttl --data "$tmp/data-ttl" --share-ttl 8s
before=$(date +%s)
reply="$(share 'short lived')"; id="$(json_field id <<<"$reply")"
after=$(date +%s)
expires="$(json_field expires_unix <<<"$reply")"
[ "$expires" -ge $((before + 8)) ] && [ "$expires" -le $((after + 8)) ] && pass "expires_unix is the upload's time + ttl" \
  || fail "expires_unix $expires not within [$((before + 8)), $((after + 8))]"
expect "fresh share: 200" 200 'short lived' -- "$url/api/share/$id"
wait_s=$((expires + 1 - $(date +%s))); [ "$wait_s" -gt 0 ] && sleep "$wait_s"
expect "expired share: 404" 404 '"error":"no shared tape' -- "$url/api/share/$id"
rows="$(python3 -c 'import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute("select count(*) from shares").fetchone()[0])' "$tmp/data-ttl/shares.sqlite3")"
[ "$rows" = 0 ] && pass "expired share deleted from the store" || fail "$rows rows left after expiry"
stop_server

# --- upload rate per client ------------------------------------------------------------------------------------------
start_server rate --data "$tmp/data-rate" --share-rate 3
for i in 1 2 3; do share "rate $i" > /dev/null; done
expect "4th upload in a minute: 429" 429 '"error":"too many shares' -- "${oct[@]}" --data-binary 'rate 4' "$url/api/share"
ra="$(header_value Retry-After)"
[[ "$ra" =~ ^[0-9]+$ ]] && [ "$ra" -ge 1 ] && [ "$ra" -le 60 ] && pass "Retry-After: $ra" || fail "Retry-After '$ra'"
expect "checks are not rate limited" 200 '"files"' -- "${oct[@]}" --data-binary 'x' "$url/api/check"
stop_server

# --- size bound: the oldest go first -------------------------------------------------------------------------------
start_server store --data "$tmp/data-store" --max-store 1KB
ids=()
for i in 1 2 3; do
  head -c 400 /dev/zero | tr '\0' "$i" > "$tmp/t$i"
  ids+=("$(share @"$tmp/t$i" | json_field id)")
  sleep 1.1  # distinct created_unix seconds
done
expect "oldest evicted over --max-store" 404 '"error"' -- "$url/api/share/${ids[0]}"
expect "second kept" 200 '^2' -- "$url/api/share/${ids[1]}"
expect "newest kept" 200 '^3' -- "$url/api/share/${ids[2]}"
head -c 2000 /dev/zero | tr '\0' 'x' > "$tmp/huge"
expect "a tape larger than the store: 507" 507 '"error":"the tape is larger than the whole store' -- "${oct[@]}" --data-binary @"$tmp/huge" "$url/api/share"
expect "... and nothing was evicted for it" 200 '^3' -- "$url/api/share/${ids[2]}"
finish
