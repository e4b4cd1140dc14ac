# VROC: `make demo` and `make test` set everything up on a fresh Debian 12 machine (as root).
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
PACKAGES := cmake ninja-build g++ make pkg-config git ca-certificates \
  libeigen3-dev libbullet-dev libode-dev libmujoco-dev libdart-dev libccd-dev libassimp-dev libqhull-dev \
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev libfmt-dev libopenmpi-dev openmpi-bin \
  libosmesa6-dev libpng-dev libssl-dev gnuplot-nox ffmpeg chromium libjs-three libsndfile1-dev libspnav-dev libx11-dev ccache \
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build demo test test-long test-sanitize bench bench-dense bench-scale clean

all: build

# Installs only what is missing, so a second run costs nothing.
deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "vroc: installing Debian packages:$$missing"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

# Extra CMake options for a new build directory, e.g. CMAKE_FLAGS=-DVROC_WERROR=ON (what CI uses).
CMAKE_FLAGS ?=

configure: deps
	@[ -f $(BUILD_DIR)/build.ninja ] || cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# `make install PREFIX=/opt/vroc`: libraries, headers, `vroc`, plugins, scenes and the CMake package
# (find_package(vroc)); README.md, "Install and use as a library".
PREFIX ?= /usr/local
.PHONY: install
install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)

# Only what scripts/demo.sh runs: the `vroc` program and the built-in device plugins it loads (no
# tests, no benchmarks); `make test` builds the rest.
DEMO_TARGETS := vroc vroc_builtin_plugins
demo: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target $(DEMO_TARGETS)
	@scripts/demo.sh $(BUILD_DIR)

test: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS) -LE long

# The default suite built with AddressSanitizer and UndefinedBehaviorSanitizer, in its own build
# directory (nothing shared with $(BUILD_DIR) that could hide a finding); any finding fails.
# -O1 with line tables only (cheaper to build than -O2 -g; reports still name file:line).
# Benchmarks are not built (no test runs them), nor the Python module (an instrumented extension
# would need the sanitizer runtime preloaded into the interpreter; its C++ parts are the harness's
# and the backends', sanitized here through their own tests).
# Third-party leaks are suppressed in tests/sanitizers/lsan.supp, each with why. The two tests
# that start `mpirun` are left out: Open MPI leaks inside MPI_Init from MCA components it has
# already unloaded, which no suppression can name.
SANITIZE_DIR ?= build-sanitize
test-sanitize: deps
	@[ -f $(SANITIZE_DIR)/build.ninja ] || cmake -S . -B $(SANITIZE_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release \
	  "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O1 -g1 -DNDEBUG" \
	  -DVROC_SANITIZE=ON -DVROC_BUILD_BENCHMARKS=OFF -DVROC_PYTHON=OFF $(CMAKE_FLAGS)
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_init_order=1 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizers/lsan.supp:print_suppressions=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(SANITIZE_DIR) --output-on-failure -j $(JOBS) -LE long \
	    -E 'ParallelCli\.(MpiRanksGiveTheSameResultsAsOneProcess|AKilledRankEndsTheJobNamingTheMissingRunsAndResumeFinishesIt)$$'

# Coverage-guided fuzzing (libFuzzer, clang 16; docs/fuzzing.md): builds the targets of tests/fuzz/
# in their own directory and runs each for FUZZ_SECONDS on a copy of its corpus; fails on any crash,
# leak or timeout. Executions per target: $(FUZZ_DIR)/fuzz-summary.txt.
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_PACKAGES := clang-16 libfuzzer-16-dev libclang-rt-16-dev
.PHONY: fuzz
fuzz: deps
	@missing=""; for p in $(FUZZ_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "vroc: installing Debian packages:$$missing"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi
	@[ -f $(FUZZ_DIR)/build.ninja ] || CC=clang-16 CXX=clang++-16 cmake -S . -B $(FUZZ_DIR) -G Ninja \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVROC_FUZZ=ON -DVROC_BUILD_RENDERER=OFF -DVROC_BUILD_BENCHMARKS=OFF \
	  -DVROC_WITH_MPI=OFF -DVROC_PYTHON=OFF
	cmake --build $(FUZZ_DIR) --target fuzz_all -j $(JOBS)
	scripts/run_fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS)

test-long: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS) -L long

bench: build
	@scripts/bench.sh $(BUILD_DIR)

# Dense contact (issue 9): stress scenes on native and Bullet (1 and 4 sub-steps), then scaling.
bench-dense: build
	python3 scripts/dense_contact_bench.py --build $(BUILD_DIR) --duration 4 --repeats 3 --out runs/dense-contact \
	  --scenes plank stack20_ratio10 pyramid10 pyramid20 pyramid30 simbenchmark666 bin_spheres100 bin_boxes100 bin_hulls100 bin_spheres400
	python3 scripts/dense_contact_bench.py --build $(BUILD_DIR) --scaling --duration 2 --repeats 1 --out runs/dense-contact-scaling

# Scale-out (issue 11): one sweep over worker processes and MPI ranks; results checked identical.
bench-scale: build
	python3 scripts/scale_out_bench.py --build $(BUILD_DIR) --repeats 3 --out runs/scale-out

clean:
	rm -rf $(BUILD_DIR)
