# The two commands of the README, for a fresh Debian 12 machine (as root):
#   make demo   install what is missing, build, run a short demo simulation
#   make test   install what is missing, build, run the whole test suite (ctest)
# Other targets: build, lint, bench, install, clean. BUILD=dir picks the build folder,
# NATIVE=1 tunes for this CPU (opt-in; the default build is portable).

BUILD ?= build
JOBS ?= $(shell nproc)
NATIVE ?= 0
CMAKE_FLAGS = -DCMAKE_BUILD_TYPE=Release $(if $(filter 1,$(NATIVE)),-DCOOLGAS_NATIVE=ON,-DCOOLGAS_NATIVE=OFF)

# Debian 12 packages. What building and running need (toolchain, libraries,
# gnuplot for the pipelines' figures, help2man for the manual pages, the
# Python package's build and its numpy/pandas), which
# `make demo` installs; what only the tests need (Python readers that
# check real clients open our files, pytest, the notebook's runner, a Slurm
# cluster to run pipelines/cluster/ on), which `make test` adds; and
# clang-tidy, which only `make lint` adds. All without recommended packages.
BUILD_PACKAGES := cmake make g++ pkg-config git \
  libhdf5-dev hdf5-tools libfftw3-dev libgsl-dev libeigen3-dev \
  libgtest-dev libcli11-dev libtoml11-dev \
  gnuplot-nox help2man man-db \
  python3 python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pandas
TEST_PACKAGES := python3-h5py python3-mdanalysis python3-ase python3-matplotlib python3-pytest python3-yaml python3-vtk9 \
  bash-completion \
  jupyter-nbconvert python3-ipykernel \
  slurmctld slurmd munge slurm-client
LINT_PACKAGES := clang-tidy-15

PREFIX ?= /usr/local

.PHONY: deps test-deps configure build demo test lint bench install clean

# $(call install_missing,PACKAGES): installs those not yet installed (as root).
define install_missing
	@missing=""; for p in $(1); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" -ne 0 ]; then echo "error: missing Debian packages:$$missing (run 'make' as root, or apt-get install them)"; exit 2; fi; \
	  echo "Installing missing Debian packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
endef

deps:
	$(call install_missing,$(BUILD_PACKAGES))

test-deps:
	$(call install_missing,$(TEST_PACKAGES))

# A build folder copied with the tree (a copied clone) was configured for
# the old folder, which cmake refuses: its cache is dropped and the build
# configured afresh here.
configure: deps
	@home=$$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' $(BUILD)/CMakeCache.txt 2>/dev/null); \
	if [ -n "$$home" ] && [ "$$home" != "$(CURDIR)" ]; then \
	  echo "note: $(BUILD)/ was configured for $$home; configuring it afresh for $(CURDIR)"; \
	  rm -rf $(BUILD)/CMakeCache.txt $(BUILD)/CMakeFiles; \
	fi
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# A skipped test says why on a line "SKIP: ..." of its output, which ctest
# does not show: the reasons are printed after its summary.
test: test-deps build
	cd $(BUILD) && { ctest --output-on-failure -j $(JOBS); status=$$?; \
	  awk '/^[0-9]+\/[0-9]+ Test: / { name = $$3 } /^SKIP: / { print "skipped: " name ": " substr($$0, 7) }' \
	    Testing/Temporary/LastTest.log; exit $$status; }

# clang-tidy with the checks of .clang-tidy on every source (tests/lint/clang_tidy.sh;
# its compile commands in $(BUILD)-lint). Not part of `make test`: the whole tree
# takes tens of CPU-minutes, so run it before committing C++.
lint: deps
	$(call install_missing,$(LINT_PACKAGES))
	sh tests/lint/clang_tidy.sh $(BUILD)-lint $(JOBS)

demo: build
	$(MAKE) -C pipelines/demo -j $(JOBS) BIN=$(abspath $(BUILD))/bin OUT=$(abspath out/demo)
	$(MAKE) -C pipelines/effects -j $(JOBS) BIN=$(abspath $(BUILD))/bin OUT=$(abspath out/effects)

# Speed figures for the README (one core each; see tests/bench/). The
# aggregation benchmarks (W3, ~1 CPU-min; W3b, far longer) are run by hand:
# build/bench/aggregation_bench (see tests/bench/README.md).
bench: build
	$(BUILD)/bench/engine_bench all 108000 50 3
	$(BUILD)/bench/engine_bench W5
	$(BUILD)/bench/engine_bench W7
	$(BUILD)/bench/rsa_bench 1000000 0.35 0.36 0.37
	$(BUILD)/bench/smoluchowski_bench 1
	$(BUILD)/bench/cluster_bench
	$(BUILD)/bench/structure_bench
	$(BUILD)/bench/shape_bench

# The programs into $(PREFIX)/bin, their manual pages, completion, and the
# documents and pipelines into $(PREFIX)/share (common/install/install.cmake).
install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD)
