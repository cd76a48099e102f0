# The two commands of the README:
#   make demo   installs what rendering needs (DEMO_PACKAGES) if missing, builds facet alone
#               (no tests, no bench) in build-demo, renders the default scene into out/
#   make test   installs what is missing (PACKAGES: the test toolchain too), builds, runs the
#               whole test suite (ctest), then each fuzz harness for FUZZ_SECONDS (30 s) on
#               the stored corpus
#   make bench  installs what is missing (PACKAGES, with Embree), builds, runs the bench
# Other targets: make build | deps | install [PREFIX=/usr/local] | package | fresh-check | bench | bench-mitsuba | bench-cycles | sanitize | fuzz | format | clean (docs/robustness.md)

BUILD ?= build
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 30
SANITIZE_ASAN_OPTIONS ?= detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CLANG_FORMAT ?= $(shell command -v clang-format-14 || echo clang-format)
CMAKE_FLAGS ?=

# Debian 12 packages facet needs to build, test and run on the CPU (PoCL).
# libtinygltf-dev (glTF), libassimp-dev (PLY, STL, FBX, Collada, 3DS, ...) and zlib1g-dev (gzip'd meshes) read users' assets;
# assimp-testmodels holds the malformed glTF files of SceneGltf.AssimpTestModels and the STL, FBX,
# Collada and 3DS models of AssimpReader.* and tests/cli_test.sh (skipped without it);
# libembree-dev is for the bench only (it skips its part without it);
# fiu-utils (libfiu) injects write failures in tests/faults/disk_full.sh (skipped without it);
# oclgrind for the Oclgrind tier (ctest -L oclgrind, skipped without it).
# Open MPI for `mpirun -n N facet render` (optional: CMake builds without it when absent).
PACKAGES := build-essential cmake pkg-config \
	pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo \
	libglm-dev libopenimageio-dev libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libfmt-dev \
	libgtest-dev clang libclang-rt-14-dev clang-format \
	libtinygltf-dev libdraco-dev libassimp-dev zlib1g-dev assimp-testmodels \
	libembree-dev \
	fiu-utils oclgrind \
	libopenmpi-dev openmpi-bin

# What `make demo` needs to build and run facet, nothing of the test or bench toolchain: every
# package CMakeLists.txt's REQUIRED find_package and pkg_check_modules look for, and PoCL to run.
# `make fresh-check` proves the list on a freshly bootstrapped Debian 12 (tests/fresh/).
DEMO_PACKAGES := build-essential cmake pkg-config \
	pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo \
	libglm-dev libopenimageio-dev libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libfmt-dev \
	libtinygltf-dev libdraco-dev libassimp-dev zlib1g-dev
DEMO_BUILD ?= build-demo

SUDO := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)

.PHONY: all deps deps-demo install-packages configure build build-demo demo install package test fresh-check bench bench-mitsuba bench-cycles sanitize fuzz-build fuzz format clean

all: build

deps:
	@$(MAKE) --no-print-directory install-packages WANT="$(PACKAGES)"

deps-demo:
	@$(MAKE) --no-print-directory install-packages WANT="$(DEMO_PACKAGES)"

install-packages:
	@missing=""; for p in $(WANT); do \
		dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
		echo "Installing:$$missing"; \
		$(SUDO) apt-get update -q && \
		DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q --no-install-recommends $$missing; \
	fi

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build-demo
	$(DEMO_BUILD)/facet render scenes/cornell_box.json --out out/cornell_box.exr

# facet alone (no tests, no bench) in $(DEMO_BUILD), with only DEMO_PACKAGES installed.
build-demo: deps-demo
	cmake -S . -B $(DEMO_BUILD) -DCMAKE_BUILD_TYPE=Release -DFACET_BUILD_TESTS=OFF -DFACET_BUILD_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(DEMO_BUILD) -j $(JOBS) --target facet

# Installs facet (its kernels are embedded), the example scenes and the docs under PREFIX.
PREFIX ?= /usr/local
install: build-demo
	$(SUDO) cmake --install $(DEMO_BUILD) --prefix $(PREFIX)

# A Debian package of that build: $(DEMO_BUILD)/facet_<version>_<arch>.deb, its dependencies
# declared (`sudo apt install ./$(DEMO_BUILD)/facet_*.deb` installs them).
# CPack reads the libraries off the binary with dpkg-shlibdeps (dpkg-dev) and file.
PACKAGE_TOOLS := dpkg-dev file
package: build-demo
	@$(MAKE) --no-print-directory install-packages WANT="$(PACKAGE_TOOLS)"
	cd $(DEMO_BUILD) && cpack -G DEB

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	$(MAKE) fuzz

# `make demo` on a freshly bootstrapped Debian 12 (minbase + git, make, ca-certificates, sudo),
# from a clone of HEAD, as a user with sudo; needs root. The base is bootstrapped once and kept
# (tests/fresh/fresh_machine.sh says where). Then the .deb of `make package` is installed with
# apt on a second fresh system and renders there. CI runs it after the suite.
fresh-check:
	$(SUDO) env FRESH_DEB=1 bash tests/fresh/fresh_machine.sh

# The loaders' libFuzzer harnesses (tests/fuzz), built with clang in their own folder.
fuzz-build: deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFACET_FUZZ=ON
	cmake --build $(FUZZ_BUILD) -j $(JOBS)

fuzz: fuzz-build
	tests/fuzz/run_fuzzers.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

# The bench (bench/README.md): every speed and memory figure of facet, against Embree,
# in one run; writes out/bench/bench.json and out/bench/bench.md.
# Then the parallel efficiency of two devices and two MPI ranks against one process
# (bench/parallel_efficiency.py, out/bench/parallel_efficiency.md), and the Mitsuba 3 baseline (bench/README.md): equal-time RMSE on the demo scenes against
# Mitsuba 3, skipped when its Python package is absent. MITSUBA_BENCH_FLAGS=--quick: a short run.
# Then the Blender Cycles baseline (bench/README.md): equal-time RMSE against Cycles through
# PyPI's bpy (CYCLES_PYTHON: a Python 3.11 that has it, e.g. a venv's), skipped without it;
# CYCLES_BENCH_FLAGS passed on (--quick, --denoise, --scenes ...).
PYTHON ?= python3
MITSUBA_BENCH_FLAGS ?=
CYCLES_PYTHON ?= $(PYTHON)
CYCLES_BENCH_FLAGS ?=
bench: build
	mkdir -p out/bench
	$(BUILD)/facet_bench --json out/bench/bench.json --markdown out/bench/bench.md
	$(PYTHON) bench/parallel_efficiency.py --facet $(BUILD)/facet
	$(MAKE) --no-print-directory bench-mitsuba
	$(MAKE) --no-print-directory bench-cycles

bench-mitsuba:
	@if $(PYTHON) -c 'import mitsuba, numpy' 2>/dev/null; then \
		mkdir -p out/bench && $(PYTHON) bench/mitsuba/equal_time.py --facet $(BUILD)/facet $(MITSUBA_BENCH_FLAGS); \
	else \
		echo "Mitsuba 3 not installed: pip install mitsuba==3.9.1 numpy, and libllvm19 from Debian" \
		     "(apt-get install libllvm19; DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so):" \
		     "skipping the Mitsuba 3 baseline"; \
	fi

bench-cycles:
	@if $(CYCLES_PYTHON) -c 'import bpy, numpy' 2>/dev/null; then \
		mkdir -p out/bench && $(CYCLES_PYTHON) bench/cycles/equal_time.py --facet $(BUILD)/facet $(CYCLES_BENCH_FLAGS); \
	else \
		echo "Blender Cycles not installed: pip install bpy==5.0.0 numpy (Python 3.11, e.g. in a venv," \
		     "then CYCLES_PYTHON=that venv's python): skipping the Blender Cycles baseline"; \
	fi

# AddressSanitizer + UBSan build of everything; runs the unit, render and cli tiers (docs/robustness.md).
# Leaks inside the OpenCL driver stack (PoCL, LLVM) are suppressed, facet's are not.
sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFACET_SANITIZE=ON -DFACET_BUILD_BENCH=OFF
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS=$(SANITIZE_ASAN_OPTIONS) UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
		LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizer/lsan.supp:print_suppressions=0 \
		ctest --output-on-failure -j $(JOBS) -L "unit|render|cli"

# Rewrites every tracked C++ and OpenCL C source as .clang-format says (clang-format 14);
# ctest's Sources.ClangFormat (tests/format_check.sh) checks it without rewriting.
format:
	git ls-files '*.cpp' '*.hpp' '*.h' '*.cl' | xargs $(CLANG_FORMAT) -i

clean:
	rm -rf $(BUILD) $(DEMO_BUILD) build-asan $(FUZZ_BUILD) out
