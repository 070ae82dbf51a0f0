# Two commands matter: `make demo` (set up, build, render the demo) and `make test`.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?= -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
# CI (CI=true) builds with warnings as errors.
ifeq ($(CI),true)
CMAKE_FLAGS += -DSPECULA_WERROR=ON
endif

.PHONY: all bootstrap configure build demo test bench clean

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

bench: build
	@mkdir -p out
	$(BUILD)/specula bench -o out/bench.json
	$(BUILD)/specula_microbench

clean:
	rm -rf $(BUILD)
