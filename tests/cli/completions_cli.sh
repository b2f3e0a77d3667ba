#!/usr/bin/env bash
# The shell completions (`essi completions bash|zsh|fish`, made from the CLI's own definition): bash's completion
# function and fish's `complete -C` offer the subcommands, an option's values and the options of a subcommand;
# zsh's script parses. Needs bash, zsh and fish (scripts/setup test installs them). Usage: completions_cli.sh ESSI
set -uo pipefail
essi="${1:?usage: completions_cli.sh ESSI}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
for shell in bash zsh fish; do
  "$essi" completions "$shell" > "$tmp/$shell" || fail "essi completions $shell"
done

# bash: COMPREPLY for a command line cut at its last word.
bash_offers() {  # bash_offers "WORDS..." -> the completions of the last word, one a line
  bash -c 'source "$1"; read -ra COMP_WORDS <<<"$2"; [[ $2 == *" " ]] && COMP_WORDS+=(""); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _essi; printf "%s\n" "${COMPREPLY[@]}"' _ "$tmp/bash" "$1"
}
expect() {  # expect NAME OFFERS WANTED...
  local name="$1" offers="$2"; shift 2
  for w in "$@"; do
    if ! grep -qx -- "$w" <<<"$offers"; then fail "$name: '$w' not offered (offered: $(tr '\n' ' ' <<<"$offers"))"; return; fi
  done
  pass "$name"
}
expect "bash: the subcommands" "$(bash_offers 'essi ')" check stats diff trace convert render profile serve
expect "bash: --format's values" "$(bash_offers 'essi check --format ')" text json junit sarif github codeclimate
expect "bash: the built-in profiles" "$(bash_offers 'essi stats --profile ')" iso6582 woyda hypertherm din66025 auto
expect "bash: check's options" "$(bash_offers 'essi check --max')" --max-diagnostics --max-per-code --max-size
expect "bash: profile's subcommands" "$(bash_offers 'essi profile ')" show list
expect "bash: convert --to" "$(bash_offers 'essi convert --to ')" essi eia gcode
if [ -n "$(bash_offers 'essi check --nothing-like-this')" ]; then fail "bash: an unknown option offers something"; else pass "bash: nothing for an unknown option"; fi

if command -v fish >/dev/null; then
  fish_offers() { fish -c 'source $argv[1]; complete -C $argv[2]' "$tmp/fish" "$1" | cut -f1; }
  expect "fish: the subcommands" "$(fish_offers 'essi ')" check stats diff trace convert render profile serve
  expect "fish: --format's values" "$(fish_offers 'essi check --format ')" text json junit sarif github codeclimate
  expect "fish: serve's options" "$(fish_offers 'essi serve --max')" --max-body --max-checks --max-diagnostics
  expect "fish: profile's subcommands" "$(fish_offers 'essi profile ')" show list
else
  fail "fish is not installed (Debian package fish; scripts/setup test installs it)"
fi
if command -v zsh >/dev/null; then
  if zsh -n "$tmp/zsh" && head -1 "$tmp/zsh" | grep -qx '#compdef essi'; then pass "zsh: the script parses"; else fail "zsh: the script does not parse"; fi
else
  fail "zsh is not installed (Debian package zsh; scripts/setup test installs it)"
fi
[ $failures -eq 0 ]
