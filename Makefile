# essikit — entry points. Every target first runs scripts/setup with what it needs (native, wasm, test, fuzz), which
# installs what is missing of that (Debian packages, ImGui and Google Benchmark sources, npm packages) and returns in a
# second when everything is there.
#
#   make run     build both runtimes (CLI + browser viewer) and start `essi serve` on http://127.0.0.1:8080/
#   make test    build both runtimes and run the whole suite natively and under node (WASM) + browser e2e, and the
#                unit suite once more built with ASan + UBSan (build/sanitize)
#   make native  build/native/bin/essi (+ tests, bench)      make wasm   build/wasm/bin/*.js, build/wasm/web/
#   make bench   the core benchmarks natively and under node, then the viewer's browser benchmark
#   make fuzz    each libFuzzer target (read_interp, read_eia, profile, share_link, serve_request) for 60 s (clang++-14, UBSan;
#                FUZZ_SECONDS, FUZZ_RUNS, FUZZ_TARGETS, FUZZ_PRESET=fuzz for ASan + UBSan)
#   make dist    dist/: the static essi's tarball, the Debian package and the npm package (docs/install.md)
#   make clean   remove build/ and dist/
SHELL := /bin/bash
JOBS ?= 2
FUZZ_SECONDS ?= 60

# docs/toolchain.md: every emcc link at -O1+ needs Debian's acorn module on NODE_PATH.
export NODE_PATH := /usr/share/nodejs

.PHONY: all setup setup-test native wasm sanitize test run bench fuzz dist clean

setup-test:
	@scripts/setup test

all: native

# Each target installs what it needs first (scripts/setup NEED): `make native` no Emscripten, Chromium or LinuxCNC.
setup:
	@scripts/setup all

native:
	@scripts/setup native
	cmake --preset native
	cmake --build --preset native -j$(JOBS)

wasm:
	@scripts/setup wasm
	cmake --preset wasm
	cmake --build --preset wasm -j$(JOBS)

# The unit suite and the fuzz corpus replay with AddressSanitizer + UndefinedBehaviorSanitizer.
sanitize:
	@scripts/setup native
	cmake --preset sanitize
	cmake --build --preset sanitize -j$(JOBS)

# Runs the three ctest presets (each even if one before failed), prints their summaries, and ends with one
# combined line in ctest's format; fails if any run failed.
test: setup-test native wasm sanitize dist
	@scripts/ctest-both

# Builds the CLI and the viewer, then serves the viewer (build/wasm/web) and examples/ until Ctrl+C.
# HOST and PORT change the address (make run PORT=8081).
HOST ?= 127.0.0.1
PORT ?= 8080
run: native wasm
	@test -x build/native/bin/essi || { echo "make run: build/native/bin/essi was not built"; exit 2; }
	@test -f build/wasm/web/essi_viewer.wasm || { echo "make run: the viewer was not built (build/wasm/web)"; exit 2; }
	@echo "make run: open http://$(HOST):$(PORT)/ in a browser and drop a tape on the page (Ctrl+C stops)"
	exec build/native/bin/essi serve --host $(HOST) --port $(PORT)

bench: setup-test
	cmake --preset native
	cmake --build --preset native -j$(JOBS) --target essi_bench
	build/native/bin/essi_bench
	cmake --build --preset native -j$(JOBS) --target essi essi_gen_batch essi_gen_nest
	scripts/bench_batch
	@echo "== peak memory of essi check, every rule (bound: 4 bytes per input byte + 64 MB) =="
	scripts/bench_memory
	scripts/bench_serve_limits
	@echo "== essi check with every rule of the cut plan, 100 MB nest (goal: 150 MB/s) =="
	PROFILE=tests/bench/every_rule.profile.json GOAL_MBPS=150 scripts/bench_compare 100
	@echo "== essi check with machine time, cost and consumables against without, 100 MB nest (goal: within 10 %) =="
	scripts/bench_machine_time 100
	@echo "== essi check --parts against without, one thread, 100 MB nest (goal: within 1.10x) =="
	scripts/bench_parts 100
	@echo "== essi check against the build before the kerf path and the cut plan (d60aff7), 100 MB nest and batch =="
	scripts/bench_baseline 100
	cmake --preset wasm
	@if [ -f third_party/benchmark/CMakeLists.txt ]; then \
	  cmake --build --preset wasm -j$(JOBS) --target essi_bench && \
	  echo "== WASM (node) ==" && \
	  (cd build/wasm/bin && node --no-experimental-fetch essi_bench.js) && \
	  echo "== the core in WASM (node) against native, per CPU second (goal: 0.5x or more) ==" && \
	  scripts/bench_wasm; \
	else echo "make bench: third_party/benchmark missing, no WASM bench"; fi
	cmake --build --preset native -j$(JOBS) --target essi_gen_nest
	cmake --build --preset wasm -j$(JOBS) --target essi_viewer
	node tests/e2e/bench.mjs

# libFuzzer, each target (tests/fuzz/fuzz_NAME.cpp) for FUZZ_SECONDS (or FUZZ_RUNS executions). FUZZ_PRESET=fuzz-fast
# (the default: UBSan only, -O2, the volume runs of docs/fuzzing.md) or fuzz (ASan + UBSan). New inputs go to
# build/fuzz/corpus/NAME (the saved corpus tests/fuzz/corpus/NAME is read only); crashes are written to
# build/fuzz/artifacts/; each target's last status line goes to build/fuzz/NAME.log. The ESSI target reads long
# inputs (whole generated tapes are in its corpus) with a dictionary of ESSI tokens; the EIA target has its own
# (read_eia.dict). An earlier run's log is kept as NAME.K.log (the runs continue on the same corpus; the table adds
# up their executions). FUZZ_FLAGS go to every target (default -entropic=0: libFuzzer's entropic schedule took a fifth
# of a read_interp execution). Promote interesting inputs by hand. scripts/fuzz_table prints docs/fuzzing.md's table.
FUZZ_TARGETS ?= read_interp read_eia profile share_link serve_request
FUZZ_PRESET ?= fuzz-fast
FUZZ_RUNS ?= -1
FUZZ_FLAGS ?= -entropic=0
fuzz:
	@scripts/setup fuzz
	cmake --preset $(FUZZ_PRESET)
	cmake --build --preset $(FUZZ_PRESET) -j$(JOBS) --target $(addprefix essi_fuzz_,$(FUZZ_TARGETS))
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p build/fuzz/corpus/$$t build/fuzz/artifacts; \
	  dict=""; [ -f tests/fuzz/$$t.dict ] && dict="-dict=tests/fuzz/$$t.dict"; \
	  if [ -s build/fuzz/$$t.log ]; then k=2; while [ -e build/fuzz/$$t.$$k.log ]; do k=$$((k+1)); done; \
	    mv build/fuzz/$$t.log build/fuzz/$$t.$$k.log; fi; \
	  echo "== essi_fuzz_$$t ($(FUZZ_PRESET), $(FUZZ_SECONDS) s, runs $(FUZZ_RUNS), max_len 4096, $(FUZZ_FLAGS))"; \
	  build/$(FUZZ_PRESET)/bin/essi_fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -runs=$(FUZZ_RUNS) -max_len=4096 \
	    -timeout=10 -print_final_stats=1 $(FUZZ_FLAGS) $$dict -artifact_prefix=build/fuzz/artifacts/$$t- \
	    build/fuzz/corpus/$$t tests/fuzz/corpus/$$t 2>&1 | tee build/fuzz/$$t.log | grep -E "^#[0-9]+.*(pulse|DONE)|^stat::|ERROR|SUMMARY" ; \
	  [ $${PIPESTATUS[0]} -eq 0 ] || exit 1; \
	done

# The packages, from the viewer's WASM build (compiled into both essi binaries): docs/install.md.
#   dist/essi-VERSION-linux-x86_64.tar.gz   the static essi (preset dist-static), man page, completions, examples
#   dist/essikit_VERSION_amd64.deb          essi built against Debian's shared libraries (preset dist-deb), CPack
#   dist/essikit-VERSION.tgz                the npm package (the wasm preset's target essi_npm, scripts/pack_npm)
dist:
	@scripts/setup dist
	cmake --preset wasm
	cmake --build --preset wasm -j$(JOBS) --target essi_viewer essi_npm
	scripts/pack_npm build/wasm dist
	cmake --preset dist-static
	cmake --build --preset dist-static -j$(JOBS) --target dist_tarball
	cmake --preset dist-deb
	cmake --build --preset dist-deb -j$(JOBS)
	rm -f dist/essikit_*_amd64.deb
	cd build/dist-deb && cpack -G DEB
	rm -rf dist/_CPack_Packages
	@ls -l dist/

clean:
	rm -rf build dist
