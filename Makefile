# Two commands matter: `make demo` (set up, build, render the demo) and `make test`.
# `make install PREFIX=...` installs (cmake --install); `make deb` makes the Debian packages.
BUILD ?= build
PREFIX ?= /usr/local
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?= -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
# CI (CI=true) builds with warnings as errors.
ifeq ($(CI),true)
CMAKE_FLAGS += -DSPECULA_WERROR=ON
endif

# The sanitizer build (docs/testing.md#sanitizers): clang with AddressSanitizer, LeakSanitizer and
# UndefinedBehaviorSanitizer, and the libFuzzer fuzzers, in its own directory.
SANITIZE_BUILD ?= build-sanitize
SANITIZE_CMAKE_FLAGS ?= -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
                        -DSPECULA_SANITIZE=ON -DSPECULA_FUZZERS=ON
FUZZ_SECONDS ?= 15

.PHONY: all bootstrap configure build demo test bench install deb clean build-sanitize test-sanitize fuzz-short soak

all: build

bootstrap:
	@bash scripts/bootstrap.sh

$(BUILD)/build.ninja: CMakeLists.txt | bootstrap
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null

configure: bootstrap $(BUILD)/build.ninja

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@mkdir -p out
	$(BUILD)/specula render -o out/demo.png
	@echo "wrote out/demo.png"

test: build
	@bash scripts/test.sh $(BUILD)

$(SANITIZE_BUILD)/build.ninja: CMakeLists.txt | bootstrap
	@cmake -S . -B $(SANITIZE_BUILD) $(SANITIZE_CMAKE_FLAGS) >/dev/null

build-sanitize: bootstrap $(SANITIZE_BUILD)/build.ninja
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS)

# The whole suite under the sanitizers (scripts/test-sanitize.sh).
test-sanitize: build-sanitize
	@bash scripts/test-sanitize.sh $(SANITIZE_BUILD)

# Each fuzzer for FUZZ_SECONDS (scripts/fuzz.sh): they still build and still find nothing.
fuzz-short: build-sanitize
	@bash scripts/fuzz.sh $(SANITIZE_BUILD) $(FUZZ_SECONDS)

# 100,000 frames, memory and GL objects recorded (scripts/soak.sh; docs/testing.md#soak).
soak: build
	@bash scripts/soak.sh $(BUILD)

bench: build
	@mkdir -p out
	$(BUILD)/specula bench -o out/bench.json
	$(BUILD)/specula_microbench

install: build
	@cmake --install $(BUILD) --prefix $(PREFIX)

# specula_<version>_<arch>.deb and libspecula-dev_<version>_<arch>.deb in $(BUILD)/ (docs/packaging.md).
deb: build
	@cd $(BUILD) && cpack -G DEB

clean:
	rm -rf $(BUILD)
