#!/usr/bin/env bash
# The pre-commit hook essi-check (.pre-commit-hooks.yaml), run by pre-commit itself (Debian package pre-commit;
# scripts/setup test installs it) with `pre-commit try-repo` against this repository, in a project of its own
# holding example tapes: a good tape passes, a bad one fails the hook with its diagnostic, a file that is no tape
# is not given to it. Usage: pre_commit_cli.sh ESSI
set -uo pipefail
essi="$(realpath "${1:?usage: pre_commit_cli.sh ESSI}")"
root="$(cd "$(dirname "$0")/../.." && pwd)"
command -v pre-commit >/dev/null || { echo "FAIL - pre-commit is not installed (Debian package pre-commit; scripts/setup test installs it)"; exit 1; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export PRE_COMMIT_HOME="$tmp/cache" PATH="$(dirname "$essi"):$PATH" GIT_CONFIG_GLOBAL="$tmp/gitconfig"
git config --global user.email ci@example.invalid; git config --global user.name ci
git config --global --add safe.directory '*'
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
project="$tmp/project"
mkdir -p "$project" && cd "$project" && git init -q .
cp "$root/examples/absolute_offset.esi" good.esi
cp "$root/examples/bad_arc_off_circle.esi" bad.esi
cp "$root/examples/woyda_eia.eia" good.eia
echo "not a tape" > notes.txt
git add . && git commit -qm tapes
out="$(pre-commit try-repo "$root" essi-check --files good.esi good.eia notes.txt 2>&1)"; rc=$?
if [ $rc -eq 0 ] && grep -q "essi check (ESSI / EIA cutting tapes).*Passed" <<<"$out"; then pass "good tapes pass"; else fail "good tapes: rc $rc: $out"; fi
out="$(pre-commit try-repo "$root" essi-check --files good.esi bad.esi 2>&1)"; rc=$?
if [ $rc -ne 0 ] && grep -q "Failed" <<<"$out" && grep -q "bad.esi:.*error E301" <<<"$out"; then pass "a bad tape fails with its diagnostic"
else fail "bad tape: rc $rc: $out"; fi
out="$(pre-commit try-repo "$root" essi-check --files notes.txt 2>&1)"; rc=$?
if [ $rc -eq 0 ] && grep -q "no files to check" <<<"$out"; then pass "a file that is no tape is not checked"; else fail "notes.txt: rc $rc: $out"; fi
[ $failures -eq 0 ]
