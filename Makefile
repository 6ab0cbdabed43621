# The README's two commands: `make demo` and `make test`. Each installs what
# is missing (Debian packages), configures, builds, then runs. Quiet when all
# is already in place; the full build logs are in build/build.log and
# build-asan/build.log.
BUILD_DIR ?= build
ASAN_DIR ?= build-asan
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

# The sanitizer run: the test suite (and the CLI it calls) built with
# AddressSanitizer + UndefinedBehaviorSanitizer, Debug (assertions on) at -O1,
# with line tables only: -g1 keeps file:line in stack traces and compiles the
# heaviest file in 14 s instead of 18 s with -g. A sanitizer error exits with status 86,
# a code no test expects (the CLI's codes are 0-4). Gmsh's own leaks are
# suppressed inside the test binary (__lsan_default_suppressions in
# tests/io/gmsh/gmsh_write_test.cpp); fontconfig's caches (Cairo's text in the
# pictures, also in the CLI the tests run) and OpenCASCADE's (Gmsh's OCC kernel,
# the wing-body case) by tests/lsan.supp.
SANITIZER_ENV = ASAN_OPTIONS=exitcode=86:detect_leaks=1:check_initialization_order=1:strict_init_order=1 \
  UBSAN_OPTIONS=exitcode=86:print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=exitcode=86:print_suppressions=0:suppressions=$(CURDIR)/tests/lsan.supp

.PHONY: all deps build demo test build-sanitize test-sanitize test-openfoam clean

all: build

deps:
	@scripts/install-deps.sh

$(BUILD_DIR)/CMakeCache.txt: | deps
	@mkdir -p $(BUILD_DIR)
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > $(BUILD_DIR)/configure.log 2>&1 \
	  || { cat $(BUILD_DIR)/configure.log; exit 1; }

build: deps $(BUILD_DIR)/CMakeCache.txt
	@cmake --build $(BUILD_DIR) -j $(JOBS) > $(BUILD_DIR)/build.log 2>&1 \
	  || { grep -E -B2 -A8 'error|Error' $(BUILD_DIR)/build.log | head -80; echo "build failed: see $(BUILD_DIR)/build.log"; exit 1; }

$(ASAN_DIR)/CMakeCache.txt: | deps
	@mkdir -p $(ASAN_DIR)
	@cmake -S . -B $(ASAN_DIR) -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g1 -O1" -DDGWARP_SANITIZE=ON \
	  -DDGWARP_BUILD_BENCH=OFF > $(ASAN_DIR)/configure.log 2>&1 \
	  || { cat $(ASAN_DIR)/configure.log; exit 1; }

# Only the test binary and the CLI it runs (not the benchmarks).
build-sanitize: deps $(ASAN_DIR)/CMakeCache.txt
	@cmake --build $(ASAN_DIR) -j $(JOBS) --target dgwarp_tests > $(ASAN_DIR)/build.log 2>&1 \
	  || { grep -E -B2 -A8 'error|Error' $(ASAN_DIR)/build.log | head -80; echo "build failed: see $(ASAN_DIR)/build.log"; exit 1; }

demo: build
	@$(BUILD_DIR)/dgwarp demo

# The sanitizer suite alone.
test-sanitize: build-sanitize
	@echo "Sanitizer suite (ASan + UBSan, $(ASAN_DIR)/):"
	@cd $(ASAN_DIR) && $(SANITIZER_ENV) ctest --output-on-failure -j $(JOBS)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory test-sanitize

# dgwarp as OpenFOAM's motion solver: installs OpenFOAM (Debian's openfoam)
# and its headers, builds and installs libdgwarpFoam.so, runs its tests
# (docs/OPENFOAM.md). `make test` runs them too once the plugin is built.
test-openfoam: deps
	@BUILD_DIR=$(BUILD_DIR) JOBS=$(JOBS) scripts/build-openfoam-plugin.sh
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -L openfoam

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR)
