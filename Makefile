# C2Blend: the two commands of the README.
#   make demo   install Debian packages, build, blend the thesis' two cylinders, G2-fillet a
#               shaft on a plate with the FreeCAD workbench's code (out/demo.step)
#   make results regenerate docs/RESULTS.md (papers' solvers vs the closed form) with bench/compare
#   make figures regenerate docs/images/papers/ (the papers' figures, docs/FIGURES.md) with tools/plot_papers.py
#   make test   install Debian packages, build, run every test, then again under
#               AddressSanitizer + UndefinedBehaviorSanitizer, a subset under Valgrind,
#               the bounded fuzz runs, then the benchmarks
# Hardening targets (README.md, "Hardening"):
#   make fuzz      build the libFuzzer targets with clang in build-fuzz/ and run each for
#                  FUZZ_SECONDS (default 60); fails on any crash, leak or sanitizer report
#   make valgrind  build in build-vg/ and run tests/valgrind/run.sh under memcheck
BUILD ?= build
ASAN_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
VG_BUILD ?= build-vg
FUZZ_SECONDS ?= 60
JOBS ?= 2

.PHONY: all deps build demo test test-asan bench results figures clean

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
	$(MAKE) valgrind
	$(MAKE) fuzz
	$(MAKE) bench

test-asan: deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DC2B_SANITIZE=ON -DC2B_BUILD_BENCH=OFF
	cmake --build $(ASAN_BUILD) -j$(JOBS)
	cd $(ASAN_BUILD) && ctest -j$(JOBS) --output-on-failure -LE 'bench|bad|fuzz'
	# The bad inputs and fuzz seeds include expression syntax errors, on which libmatheval
	# leaks its parse nodes (tests/fuzz/lsan.supp); the suppression needs full malloc
	# stacks (the library has no frame pointers), too slow for the whole suite.
	cd $(ASAN_BUILD) && ASAN_OPTIONS=fast_unwind_on_malloc=0 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/fuzz/lsan.supp \
	  ctest -j$(JOBS) --output-on-failure -L 'bad|fuzz'

fuzz: deps
	cmake -S . -B $(FUZZ_BUILD) -DC2B_FUZZ=ON -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	      -DCMAKE_BUILD_TYPE=RelWithDebInfo -DC2B_BUILD_TESTS=OFF -DC2B_BUILD_BENCH=OFF
	cmake --build $(FUZZ_BUILD) -j$(JOBS) --target fuzz_spec fuzz_samples fuzz_nurbs fuzz_mesh
	FUZZ_SECONDS=$(FUZZ_SECONDS) sh tests/fuzz/run.sh $(FUZZ_BUILD)

valgrind: deps
	cmake -S . -B $(VG_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DC2B_BUILD_BENCH=OFF
	cmake --build $(VG_BUILD) -j$(JOBS) --target c2blend test_mode test_spec test_vseries \
	      test_nurbs test_curv test_check
	sh tests/valgrind/run.sh $(VG_BUILD)

bench: build
	cd $(BUILD) && ctest -L bench --output-on-failure -V | grep -E '^[0-9]+: [|]' | sed 's/^[0-9]*: //'

results: build
	$(BUILD)/bench/compare --markdown docs/RESULTS.md

figures: build
	/usr/bin/python3 tools/plot_papers.py --build $(BUILD) -o docs/images/papers

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(FUZZ_BUILD) $(VG_BUILD) out
