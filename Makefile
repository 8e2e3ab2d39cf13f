# Entry points. Each target installs missing Debian packages, configures and builds first.
BUILD ?= build
JOBS  ?= $(shell nproc)
SSRLAB = $(BUILD)/ssrlab
DEMO_OUT ?= out/demo

.PHONY: all deps configure build demo test bench clean test-asan

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

# AddressSanitizer + UBSan. Leak checking stays off: Mesa's llvmpipe driver leaks a few hundred
# bytes it allocated before being unloaded (the unit tests alone pass with it on).
test-asan: deps
	cmake --preset asan && cmake --build build-asan -j$(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1 \
	  ctest --output-on-failure -j$(JOBS) --timeout 1200

clean:
	rm -rf $(BUILD) build-debug build-asan out
