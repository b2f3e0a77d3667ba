#!/usr/bin/env bash
# The man page (docs/man/essi.1.in, made with the version into <build>/share/man/man1/essi.1): groff reads it
# without a warning, its NAME line is what `whatis` shows, it names every subcommand of `essi --help` and the
# version of `essi --version`. Usage: man_cli.sh ESSI MANPAGE
set -uo pipefail
essi="${1:?usage: man_cli.sh ESSI MANPAGE}"
page="${2:?usage: man_cli.sh ESSI MANPAGE}"
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
warnings="$(groff -man -ww -z "$page" 2>&1)"
if [ -z "$warnings" ]; then pass "groff: no warning"; else fail "groff: $warnings"; fi
if lexgrog "$page" | grep -q 'essi - check, measure'; then pass "lexgrog: the NAME line"; else fail "lexgrog: $(lexgrog "$page")"; fi
text="$(MANWIDTH=120 man -l "$page" 2>/dev/null | col -b)"
for sub in $("$essi" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && NF {print $1}'); do
  if grep -q "essi $sub" <<<"$text"; then pass "names essi $sub"; else fail "does not name essi $sub"; fi
done
version="$("$essi" --version | awk '{print $2}')"
if head -1 "$page" | grep -q "essikit $version"; then pass "version $version"; else fail "version: $(head -1 "$page") vs $version"; fi
[ $failures -eq 0 ]
