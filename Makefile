# ctab — top-level entry points. `make run` and `make test` are the Quick start.
# Both install the Debian packages that are missing (apt-get, as root), configure and build.
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
# `make sanitize`: a second build with AddressSanitizer + UndefinedBehaviorSanitizer, running the fast tests.
# MPI (`mpirun -n R ctab generate`) where OpenMPI is installed; decided when the recipe runs, after `deps`.
WITH_MPI ?= $$(command -v mpicc >/dev/null 2>&1 && echo ON || echo OFF)
SANITIZE_DIR ?= build-asan
SANITIZE_FLAGS ?= -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
SANITIZE_ENV = ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/support/lsan.supp:print_suppressions=0
# `make fuzz-ci` / `make fuzz`: the libFuzzer targets of fuzz/ (clang, ASan + UBSan) in build-fuzz, each run for
# FUZZ_CI_SECONDS (CI) or FUZZ_SECONDS (a longer local run); docs/fuzzing.md.
FUZZ_DIR ?= build-fuzz
FUZZ_CI_SECONDS ?= 45
FUZZ_SECONDS ?= 600
FUZZ_TARGETS ?= blob hdf5_table profile gap_csv table_config

.PHONY: all deps configure build build-ctab run test sanitize fuzz-deps fuzz-build fuzz-ci fuzz bench clean

all: build

deps:
	@scripts/install_deps.sh

$(BUILD_DIR)/build.ninja: | deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCTAB_WITH_MPI=$(WITH_MPI)

configure: deps $(BUILD_DIR)/build.ninja

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job needs `ctab` and the libraries it links, not the ~300 test and benchmark targets (`make test`).
build-ctab: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target ctab

run: build-ctab
	$(BUILD_DIR)/bin/ctab generate -o $(BUILD_DIR)/default_table.h5
	$(BUILD_DIR)/bin/ctab inspect $(BUILD_DIR)/default_table.h5 | tail -n 12
	/usr/bin/python3 tables/scripts/plot_table.py $(BUILD_DIR)/default_table.h5 -o $(BUILD_DIR)/default_table.png

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# -O1 -g1 without NDEBUG: assertions on, line tables for the reports, a third less compile time than -O2 -g.
# No benchmarks and no header check (the Release build has them). The gtest executables run once at build time
# (test discovery), so the sanitizer options apply to the build too.
sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS=$(SANITIZE_FLAGS)" \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DCTAB_BUILD_BENCH=OFF -DCTAB_CHECK_HEADERS=OFF
	$(SANITIZE_ENV) cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS) -LE slow

# Clang and its sanitizer and libFuzzer runtimes are installed only here, not for `make test`.
fuzz-deps:
	@scripts/install_deps.sh --fuzz

# -O1 -g1 as the sanitizer build; only the libraries the targets link (no CLI, tests or benchmarks).
fuzz-build: fuzz-deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1" -DCTAB_FUZZ=ON \
	  -DCTAB_BUILD_TESTS=OFF -DCTAB_BUILD_BENCH=OFF -DCTAB_INSTALL=OFF
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target ctab_fuzz_targets

fuzz-ci: fuzz-build
	fuzz/run_fuzz.sh $(FUZZ_DIR) $(FUZZ_CI_SECONDS) $(FUZZ_TARGETS)

fuzz: fuzz-build
	fuzz/run_fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

bench: build
	$(BUILD_DIR)/bin/ctab bench solver
	$(BUILD_DIR)/bin/ctab bench wheelrail
	$(BUILD_DIR)/bin/ctab_solver_bench

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(FUZZ_DIR)
