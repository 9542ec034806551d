# The README's two commands, and a few more. Each target bootstraps (installs missing Debian packages
# when run as root, or says how), configures with a CMake preset, and builds what it needs.
PRESET ?= release
BUILD  := build/$(PRESET)
JOBS   ?= $(shell nproc)
CTEST_ARGS ?=
# ccache keys on paths relative to the checkout, so a fresh clone (CI) reuses earlier compiles.
export CCACHE_BASEDIR := $(CURDIR)
export CCACHE_NOHASHDIR := 1

.PHONY: all bootstrap configure build demo check test bench fuzz format clean

all: build

bootstrap:
	@scripts/bootstrap.sh

configure: bootstrap
	@test -f $(BUILD)/build.ninja || cmake --preset $(PRESET)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The main job on a built-in default. It needs the antkit command alone, so it builds that target
# and what it links (not the tests, proofs, fuzz or benchmark programs): the demo starts minutes
# sooner on a fresh machine.
demo: configure
	cmake --build $(BUILD) -j $(JOBS) --target antkit
	@scripts/demo.sh $(BUILD)/cli/antkit

# The tier for every edit: unit and property tests and the fast proofs, without what is labelled
# slow, the Cortex-M image (mcu) or the determinism matrix. `make test` is the whole suite.
check: build
	@scripts/bootstrap.sh --node-packages
	@echo "rapidcheck seed: $$(grep -m1 '^ANTKIT_RC_SEED' $(BUILD)/CMakeCache.txt | cut -d= -f2)"
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -LE 'slow|mcu|determinism' $(CTEST_ARGS)

# The whole test suite (unit, property, proof, fuzz-regression, slow).
test: build
	@scripts/bootstrap.sh --node-packages
	@echo "rapidcheck seed: $$(grep -m1 '^ANTKIT_RC_SEED' $(BUILD)/CMakeCache.txt | cut -d= -f2)"
	@status=0; ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) $(CTEST_ARGS) \
	  -O $(BUILD)/ctest.log || status=$$?; \
	skipped=$$(grep -cE '^[[:space:]]+[0-9]+ - .*[(]Skipped[)]$$' $(BUILD)/ctest.log || true); \
	echo "skipped: $$skipped test(s) (each says why in its output; listed above)"; \
	exit $$status

bench: configure
	cmake --build $(BUILD) -j $(JOBS) --target antkit_bench
	$(BUILD)/bench/antkit_bench

fuzz: bootstrap
	@test -f build/fuzz/build.ninja || cmake --preset fuzz
	cmake --build build/fuzz -j $(JOBS)

format:
	git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

clean:
	rm -rf build
