# The two commands of the README:
#   make demo   installs what is missing, builds, renders the default scene into out/
#   make test   installs what is missing, builds, runs the whole test suite (ctest)
# Other targets: make build | deps | bench | sanitize | clean

BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

# Debian 12 packages facet needs to build, test and run on the CPU (PoCL).
# libembree-dev and zlib1g-dev are for the bench only (it skips their parts without them).
PACKAGES := build-essential cmake pkg-config \
	pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo \
	libglm-dev libopenimageio-dev libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libfmt-dev \
	libgtest-dev clang \
	libembree-dev zlib1g-dev

SUDO := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)

.PHONY: all deps configure build demo test bench sanitize clean

all: build

deps:
	@missing=""; for p in $(PACKAGES); do \
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

demo: build
	$(BUILD)/facet render scenes/cornell_box.json --out out/cornell_box.exr

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The bench (bench/README.md): every speed and memory figure of facet, against Embree,
# in one run; writes out/bench/bench.json and out/bench/bench.md.
bench: build
	mkdir -p out/bench
	$(BUILD)/facet_bench --json out/bench/bench.json --markdown out/bench/bench.md

sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFACET_SANITIZE=ON
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD) build-asan out
