# Entry points. Each target installs missing Debian packages, configures and builds first.
BUILD ?= build
JOBS  ?= $(shell nproc)
SSRLAB = $(BUILD)/ssrlab
DEMO_OUT ?= out/demo

# Scene-loader fuzzing (tests/fuzz, clang-14 + libFuzzer): FUZZ_SANITIZERS= (empty) or
# undefined builds a faster binary than the default ASan + UBSan one.
FUZZ_BUILD ?= build-fuzz
FUZZ_SANITIZERS ?= address,undefined
FUZZ_SECONDS ?= 25
FUZZ_RUNS ?= 10000000
FUZZ_WORKERS ?= 2

.PHONY: all deps configure build demo test bench clean test-asan fuzz-build fuzz-smoke fuzz

all: build

deps:
	@scripts/install-deps.sh

$(BUILD)/build.ninja: | deps
	cmake --preset default

configure: $(BUILD)/build.ninja

build: deps configure
	cmake --build $(BUILD) -j$(JOBS)

# The headless comparison on the default scene: every technique against the ray-traced reference,
# with the seeds' presets; prints the speed/error table (llvmpipe here: times are CPU, labelled).
demo: build
	@mkdir -p $(DEMO_OUT)
	$(SSRLAB) compare --scene gallery --size 640x360 --preset thesis-hq --preset thesis-lq \
	  --out $(DEMO_OUT)/compare.png --json $(DEMO_OUT)/results.json
	$(SSRLAB) render --scene gallery --technique linear --size 1280x720 --out $(DEMO_OUT)/gallery-linear.png
	@echo "demo: grid $(abspath $(DEMO_OUT))/compare.png, results $(abspath $(DEMO_OUT))/results.json"

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) --timeout 600
	$(MAKE) --no-print-directory fuzz-smoke

# AddressSanitizer + UBSan. Leak checking stays off: Mesa's llvmpipe driver leaks a few hundred
# bytes it allocated before being unloaded (the unit tests alone pass with it on).
test-asan: deps
	cmake --preset asan && cmake --build build-asan -j$(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1 \
	  ctest --output-on-failure -j$(JOBS) --timeout 1200

# libFuzzer targets of the OBJ/MTL and JSON scene loaders (docs/ROBUSTNESS.md, "Fuzzing").
# fuzz-smoke: each target FUZZ_SECONDS (CI, after ctest); fuzz: each target FUZZ_RUNS executions
# in FUZZ_WORKERS processes. Either fails on any finding (reproducer in $(FUZZ_BUILD)/artifacts).
fuzz-build: deps
	cmake --preset fuzz -B $(FUZZ_BUILD) -DSSRLAB_FUZZ_SANITIZERS=$(FUZZ_SANITIZERS)
	cmake --build $(FUZZ_BUILD) -j$(JOBS)

fuzz-smoke: fuzz-build
	FUZZ_BUILD=$(FUZZ_BUILD) scripts/fuzz.sh smoke $(FUZZ_SECONDS)

fuzz: fuzz-build
	FUZZ_BUILD=$(FUZZ_BUILD) scripts/fuzz.sh long $(FUZZ_RUNS) $(FUZZ_WORKERS)

clean:
	rm -rf $(BUILD) build-debug build-asan build-fuzz out
