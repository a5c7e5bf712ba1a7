# sigchain top-level Makefile: the README's two commands are `make demo` and `make test`.
BUILD   ?= build
PREFIX  ?= /usr/local
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps configure build test man install demo fuzz bench clean

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

install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

# The main job. Until the demo scene lands (issue 7) it runs the seed's sample
# files through the tools that exist.
demo: build
	@scripts/demo $(BUILD)

fuzz: deps
	@scripts/fuzz

bench: build
	@for b in $(BUILD)/bench/bench_*; do [ -x "$$b" ] && "$$b"; done

clean:
	rm -rf $(BUILD)
