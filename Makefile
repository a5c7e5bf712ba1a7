# sigchain top-level Makefile: the README's two commands are `make demo` and `make test`.
BUILD   ?= build
PREFIX  ?= /usr/local
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps configure build test man install demo fuzz bench performance chart validate \
	accuracy counts clean

all: build

deps:
	@scripts/install-deps

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

configure: $(BUILD)/CMakeCache.txt

build: deps configure
	cmake --build $(BUILD) -j $(JOBS)

# Every unit, CLI (Bats) and man-page check under CTest; ends with CTest's summary line.
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

man: deps configure
	cmake --build $(BUILD) --target man

# Installs what is built and builds only what is installed: the tools and their man
# pages (CMake's target `tools`: no test, no benchmark), then CMake's install rules
# (tools, pages, sigchain-config, scene.mk, the reference data). It runs no package
# manager: the Debian packages must be there already (`make deps`, i.e.
# scripts/install-deps), as a package build or an unprivileged user expects.
install: configure
	cmake --build $(BUILD) -j $(JOBS) --target tools
	cmake --install $(BUILD) --prefix $(PREFIX)

# The main job: the Olinda scene against the real Landsat-7 image, then the sample
# files of White (1996) and the training scene (scripts/demo), ending with a summary.
# Builds only the tools and man pages it needs (the tests with `make test`).
# DEMO_IMAGES=docs/images also refreshes the README's pictures of its renders.
demo: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null
	cmake --build $(BUILD) -j $(JOBS) --target tools
	@scripts/demo $(BUILD)

fuzz: deps
	@scripts/fuzz

bench: build
	@for b in $(BUILD)/bench/bench_*; do [ -x "$$b" ] && "$$b"; done

# docs/performance.md, every figure from a run of the benchmarks it quotes
# (scripts/performance fills bench/performance.md.in; about 3 minutes on 2 cores).
# LOWTRAN7_F=FILE (a LOWTRAN 7 Fortran source of the user's) adds LOWTRAN 7 side by side.
PERF_TARGETS = tools bench_parsers bench_view_angle bench_sensor_compare bench_rt bench_mtf \
	bench_trace bench_build_radiance
performance: configure
	cmake --build $(BUILD) -j $(JOBS) --target $(PERF_TARGETS)
	@scripts/performance $(BUILD)

# Speed versus accuracy of trace's sampling strategies on the demo scenes: chart,
# table and error map into BUILD/chart/, and each stage's cost against the number of
# spectral bands (bands.png, bench/bands_cost.sh) (CHART_OUT=docs/chart refreshes the
# committed copy; a few minutes; not part of `make test`).
chart: build
	@scripts/chart $(BUILD)

# The validations on real images (White (1996), section 4.5): each validation scene's
# Makefile, then docs/validation.md, its pictures and the README's results table,
# all from that run (scripts/validation; a few minutes on 2 cores).
validate: deps configure
	cmake --build $(BUILD) -j $(JOBS) --target tools
	@JOBS=$(JOBS) scripts/validation $(BUILD)

# docs/accuracy.md: every accuracy figure of the atmosphere, thermal and trace checks
# against their references, from one run of the tests that check them (scripts/accuracy;
# about 6 s once built; tests/cli/accuracy_doc.bats fails when the page is stale).
accuracy: build
	@scripts/accuracy $(BUILD)

# The README's paragraph on what `make test` runs, counted (scripts/test_counts; runs
# the robustness campaign once for its catalogue, about a minute and a half).
counts: build
	@scripts/test_counts $(BUILD)

clean:
	rm -rf $(BUILD)
