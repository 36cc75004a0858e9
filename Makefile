# VICC workspace. The two commands a user needs: `make demo` and `make test`.
# Debian's ROS 1 lives in /usr/bin; a pyenv python3 on PATH lacks catkin_pkg,
# so every recipe runs with /usr/bin first.
SHELL := /bin/bash
export PATH := /usr/bin:/bin:$(PATH)
JOBS ?= 2
BUILD_TYPE ?= Release
CATKIN := catkin_make -j$(JOBS) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCATKIN_ENABLE_TESTING=ON -DCATKIN_WHITELIST_PACKAGES=""

.PHONY: all deps build test demo bench clean

all: build

deps:
	@bash scripts/install_deps.sh

build: deps
	$(CATKIN)
	@# On a fresh clone catkin caches the test environment before any package has made
	@# devel/lib/python3/dist-packages, so the python rostests would run without PYTHONPATH
	@# (No module named 'vicc_msgs'): configure once more when the cache lacks it.
	@grep -q "PYTHONPATH='[^']*devel/lib/python3/dist-packages" build/catkin_generated/setup_cached.sh || $(CATKIN) --force-cmake

test: build
	@rm -rf build/test_results
	@set -o pipefail; source devel/setup.bash && $(CATKIN) run_tests 2>&1 | tee build/run_tests.log | grep -E "^\[ *(RUN|  OK|  FAILED|  PASSED)|FAILURE|Error|error:|rostest" || true
	@bash scripts/test_summary.sh build/test_results

demo: build
	@bash scripts/demo.sh

bench: build
	@bash bench/run_tracking_bench.sh
	@bash bench/run_fusion_bench.sh
	@bash bench/glyphs/run_glyph_bench.sh

clean:
	rm -rf build devel install
