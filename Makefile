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

.PHONY: all bootstrap configure build demo test bench install deb clean

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

install: build
	@cmake --install $(BUILD) --prefix $(PREFIX)

# specula_<version>_<arch>.deb and libspecula-dev_<version>_<arch>.deb in $(BUILD)/ (docs/packaging.md).
deb: build
	@cd $(BUILD) && cpack -G DEB

clean:
	rm -rf $(BUILD)
