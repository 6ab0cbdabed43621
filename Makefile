# The README's two commands: `make demo` and `make test`. Each installs what
# is missing (Debian packages), configures, builds, then runs. Quiet when all
# is already in place; the full build log is in build/build.log.
BUILD_DIR ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: all deps build demo test clean

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

demo: build
	@$(BUILD_DIR)/dgwarp demo

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR)
