# essikit — entry points. Every target first runs scripts/setup, which installs what is missing
# (Debian packages, ImGui and Google Benchmark sources) and returns in a second when everything is there.
#
#   make run     build the CLI and check the example tapes
#   make test    build both runtimes and run the whole suite natively and under node (WASM)
#   make native  build/native/bin/essi (+ tests, bench)      make wasm   build/wasm/bin/*.js
#   make bench   run the benchmarks natively and under node  make fuzz   libFuzzer for 60 s (clang++-14)
#   make clean   remove build/
SHELL := /bin/bash
JOBS ?= 2
FUZZ_SECONDS ?= 60

# TOOLCHAIN.md: every emcc link at -O1+ needs Debian's acorn module on NODE_PATH.
export NODE_PATH := /usr/share/nodejs

.PHONY: all setup native wasm test run bench fuzz clean

all: native

setup:
	@scripts/setup

native: setup
	cmake --preset native
	cmake --build --preset native -j$(JOBS)

wasm: setup
	cmake --preset wasm
	cmake --build --preset wasm -j$(JOBS)

# Runs both ctest presets (the second even if the first fails), prints both summaries, and ends with one
# combined line in ctest's format; fails if either run failed.
test: setup native wasm
	@scripts/ctest-both

# Exit code 1 from `essi check` means "the tapes have errors" — a report, not a build failure;
# 2 (usage, unreadable file) and crashes fail the target.
run: setup native
	@test -x build/native/bin/essi || { echo "make run: build/native/bin/essi was not built (no native/*.cpp?)"; exit 2; }
	@build/native/bin/essi check examples/; rc=$$?; if [ $$rc -ge 2 ]; then exit $$rc; fi

bench: setup
	cmake --preset native
	cmake --build --preset native -j$(JOBS) --target essi_bench
	build/native/bin/essi_bench
	cmake --preset wasm
	@if [ -f third_party/benchmark/CMakeLists.txt ]; then \
	  cmake --build --preset wasm -j$(JOBS) --target essi_bench && \
	  echo "== WASM (node) ==" && \
	  cd build/wasm/bin && node --no-experimental-fetch essi_bench.js; \
	else echo "make bench: third_party/benchmark missing, no WASM bench"; fi

# libFuzzer + ASan + UBSan. New inputs go to build/fuzz/corpus (the saved corpus tests/fuzz/corpus is
# read only); crashes are written to build/fuzz/artifacts/. Promote interesting inputs by hand.
fuzz: setup
	cmake --preset fuzz
	cmake --build --preset fuzz -j$(JOBS)
	mkdir -p build/fuzz/corpus build/fuzz/artifacts
	build/fuzz/bin/essi_fuzz -max_total_time=$(FUZZ_SECONDS) -max_len=4096 -timeout=10 \
	  -artifact_prefix=build/fuzz/artifacts/ build/fuzz/corpus tests/fuzz/corpus

clean:
	rm -rf build
