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

demo: build
	@mkdir -p $(DEMO_OUT)
	$(SSRLAB) render --scene gallery --technique none   --out $(DEMO_OUT)/gallery-none.png
	$(SSRLAB) render --scene gallery --technique linear --out $(DEMO_OUT)/gallery-linear.png
	$(SSRLAB) render --scene gallery --technique linear --view reflection --out $(DEMO_OUT)/gallery-linear-reflection.png
	@echo "demo: images written to $(abspath $(DEMO_OUT))/"

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) --timeout 600

test-asan: deps
	cmake --preset asan && cmake --build build-asan -j$(JOBS)
	cd build-asan && ctest --output-on-failure -j$(JOBS) --timeout 1200

clean:
	rm -rf $(BUILD) build-debug build-asan out
