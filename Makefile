# Fluence: the two commands of the README.
#   make render   install missing Debian packages, build the fluence program (not the tests), render the
#                 Cornell box sample, and say how long all of it took
#   make test     install missing Debian packages, build, run the whole test suite (then the scene,
#                 delegate and CLI tests again under AddressSanitizer and UBSan: scripts/sanitizer_tests.sh)
BUILD_DIR ?= build
# ccache (used when installed, CMakeLists.txt) keyed on paths relative to the checkout, so a fresh
# clone elsewhere reuses what an earlier build compiled (scripts/sanitizer_tests.sh does the same).
export CCACHE_BASEDIR ?= $(CURDIR)
export CCACHE_NOHASHDIR ?= true
JOBS ?= $(shell nproc)
# Warnings as errors (CMake option FLUENCE_WERROR): on for `make test` (and so in CI), off for
# `make build` and `make render`, where a newer compiler's new warning must not stop a user.
WERROR ?= OFF
test: WERROR = ON
SPP ?= 256
FLUENCE := $(BUILD_DIR)/apps/fluence
# When make started, for `make render`'s total time (packages, configure, build and render).
MAKE_START := $(shell date +%s)

.PHONY: all deps configure build render test clean format format-check

all: build

deps:
	@bash scripts/install_dependencies.sh

configure: deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLUENCE_WERROR=$(WERROR)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# Only what rendering needs: the fluence program, not the 1,100 tests (`make test` builds those).
render: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target fluence
	@mkdir -p out
	$(FLUENCE) render usd_samples/cornell_box.usda -o out/cornell_box.exr --preview out/cornell_box.png --spp $(SPP)
	@echo "Wrote $(CURDIR)/out/cornell_box.exr (linear Rec.709, beauty + AOVs) and $(CURDIR)/out/cornell_box.png (sRGB preview)"
	@echo "make render took $$(( $$(date +%s) - $(MAKE_START) )) s (packages, configure, build of fluence, render)"

# After the suite and the fuzz smoke run, the sanitizer pass: the scene, delegate and apps (CLI)
# tests again, built with clang++-16 -fsanitize=address,undefined into $(BUILD_DIR)/asan, any
# sanitizer report a failure (scripts/sanitizer_tests.sh). `make test-sanitized` runs it alone.
# Of the apps suite it runs what reads scenes, the two corpus sweeps included (CorpusCli and
# RealCorpusCli: every public layer through `fluence info` and `render` under the sanitizers, 566 s
# wall on 2 cores), and leaves out, to keep .ci/run under 45 minutes on 2 cores, the tests whose time
# goes into rendering rather than reading scenes (stability scenes, tiles, checkpoints, farm,
# interrupts, products, Cryptomatte, light paths, path classes, frame ranges, the denoiser on every
# sample scene); `make test-sanitized SANITIZE_APPS_EXCLUDE=` runs them all.
SANITIZE_APPS_EXCLUDE ?= ^(BenchStability|StabilityScenes|CheckpointCli|TilesCli|Farm|Signals/InterruptCli|RenderProductsCli|CryptomatteCli|LightPathCli|PathClassCli|FramesCli|DenoiseSamplesCli)
SANITIZER_TESTS = SANITIZE_BUILD_DIR=$(BUILD_DIR)/asan JOBS=$(JOBS) WERROR=$(WERROR) \
	SANITIZE_ARGS='$(if $(SANITIZE_APPS_EXCLUDE),-E $(SANITIZE_APPS_EXCLUDE))' bash scripts/sanitizer_tests.sh
test: format-check build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)
	FUZZ_BUILD_DIR=$(BUILD_DIR)/fuzz bash scripts/fuzz_smoke.sh 60
	$(SANITIZER_TESTS)

.PHONY: test-sanitized
test-sanitized: deps
	$(SANITIZER_TESTS)

# The tree follows .clang-format (clang-format 14). `make format` rewrites every tracked .cpp and .h
# in place; `make format-check` (run first by `make test`) names the files that differ and fails.
CLANG_FORMAT ?= clang-format-14
format: deps
	git ls-files '*.cpp' '*.h' | xargs $(CLANG_FORMAT) -i
format-check: deps
	@git ls-files '*.cpp' '*.h' | xargs $(CLANG_FORMAT) --dry-run -Werror \
		|| { echo "format-check: the files above differ from .clang-format; run make format" >&2; exit 1; }

# Fuzzing the USDA reader for longer (fuzz/README.md): make fuzz FUZZ_SECONDS=3600. The working
# corpus is kept in $(BUILD_DIR)/fuzz/corpus between runs.
.PHONY: fuzz bench
fuzz: FUZZ_SECONDS ?= 3600
fuzz: deps
	FUZZ_BUILD_DIR=$(BUILD_DIR)/fuzz FUZZ_CORPUS=$(BUILD_DIR)/fuzz/corpus bash scripts/fuzz_smoke.sh $(FUZZ_SECONDS)

# The benchmarks (bench/*.cpp: Embree throughput, media overhead, crate loading, USDA parsing, instancing, subdivision, lights, rect textures,
# majorant grid, volume tracking); figures go to bench/results/.
bench: deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD_DIR) -j $(JOBS) --target usda_parse_bench instancing_bench subdivision_bench many_lights_bench \
		rect_texture_bench majorant_grid_bench volume_tracking_bench embree_throughput_bench media_overhead_bench crate_load_bench
	$(BUILD_DIR)/bench/embree_throughput_bench
	$(BUILD_DIR)/bench/media_overhead_bench
	$(BUILD_DIR)/bench/crate_load_bench
	$(BUILD_DIR)/bench/usda_parse_bench
	$(BUILD_DIR)/bench/instancing_bench
	$(BUILD_DIR)/bench/subdivision_bench
	$(BUILD_DIR)/bench/many_lights_bench
	$(BUILD_DIR)/bench/rect_texture_bench
	$(BUILD_DIR)/bench/majorant_grid_bench
	$(BUILD_DIR)/bench/volume_tracking_bench

# Speed against accuracy (bench/run.py): every benchmark scene and method, error against time; Fluence against Cycles
# where blender is installed; the stability suite. Writes bench/results/DATE-*, docs/RESULTS.md, docs/STABILITY.md.
# make figures FIGURES_ARGS=--quick (or --suite cycles, --suite stability, --scenes cornell_box,smoke).
.PHONY: figures
figures:
	@bash scripts/install_dependencies.sh bench
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD_DIR) -j $(JOBS) --target fluence
	/usr/bin/python3 bench/run.py --fluence $(FLUENCE) $(FIGURES_ARGS)

clean:
	rm -rf $(BUILD_DIR) out
