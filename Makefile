# ctab — top-level entry points. `make run` and `make test` are the Quick start.
# Both install the Debian packages that are missing (apt-get, as root), configure and build.
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)

.PHONY: all deps configure build run test bench clean

all: build

deps:
	@scripts/install_deps.sh

$(BUILD_DIR)/build.ninja: | deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)

configure: deps $(BUILD_DIR)/build.ninja

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

run: build
	$(BUILD_DIR)/bin/ctab generate -o $(BUILD_DIR)/default_table.h5
	$(BUILD_DIR)/bin/ctab inspect $(BUILD_DIR)/default_table.h5 | tail -n 12
	/usr/bin/python3 tables/scripts/plot_table.py $(BUILD_DIR)/default_table.h5 -o $(BUILD_DIR)/default_table.png

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	$(BUILD_DIR)/bin/ctab bench solver
	$(BUILD_DIR)/bin/ctab bench wheelrail
	$(BUILD_DIR)/bin/ctab_solver_bench

clean:
	rm -rf $(BUILD_DIR)
