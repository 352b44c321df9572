# C2Blend: the two commands of the README.
#   make demo   install Debian packages, build, blend the thesis' two cylinders
#   make results regenerate docs/RESULTS.md (papers' solvers vs the closed form) with bench/compare
#   make test   install Debian packages, build, run every test, then again under
#               AddressSanitizer + UndefinedBehaviorSanitizer, then the benchmarks
BUILD ?= build
ASAN_BUILD ?= build-asan
JOBS ?= 2

.PHONY: all deps build demo test test-asan bench results clean

all: build

deps:
	sh tools/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS)

demo: build
	sh tools/demo.sh $(BUILD)

test: build
	cd $(BUILD) && ctest -j$(JOBS) --output-on-failure -LE bench
	$(MAKE) test-asan
	$(MAKE) bench

test-asan: deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DC2B_SANITIZE=ON -DC2B_BUILD_BENCH=OFF
	cmake --build $(ASAN_BUILD) -j$(JOBS)
	cd $(ASAN_BUILD) && ctest -j$(JOBS) --output-on-failure -LE bench

bench: build
	cd $(BUILD) && ctest -L bench --output-on-failure -V | grep -E '^[0-9]+: [|]' | sed 's/^[0-9]*: //'

results: build
	$(BUILD)/bench/compare --markdown docs/RESULTS.md

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
