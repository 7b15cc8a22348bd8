# femto quick start:  `make render` renders the default scene, `make test` runs the tests.
# Both install missing Debian packages, configure and build first (render: only
# the CLI and the plugins; test: everything).
BUILD ?= build
SCENE ?= scenes/cornell-box/scene.xml
OUT ?= out/cornell-box.exr
JOBS ?= $(shell nproc)

.PHONY: all deps configure build build-render render python test sanitize sanitize-thread clean

all: build

deps:
	@tools/install-deps.sh

$(BUILD)/build.ninja: | deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/build.ninja

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# Only the CLI and the plugins: the tests are built by `make test`.
build-render: configure
	cmake --build $(BUILD) -j $(JOBS) --target femto_render

# The femto Python module in $(BUILD)/python (PYTHONPATH=$(BUILD)/python; docs/python.md).
python: configure
	cmake --build $(BUILD) -j $(JOBS) --target femto_python

render: build-render
	$(BUILD)/bin/femto render $(SCENE) -o $(OUT)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Unit tests under AddressSanitizer + UndefinedBehaviorSanitizer, and the
# render loop and photon-beam passes (the multi-threaded code) under
# ThreadSanitizer; separate build folders, not part of `make test`.
SANITIZE_UNIT = $(1)/bin/femto_unit_tests --gtest_brief=1
sanitize: deps
	cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFEMTO_SANITIZE=address
	cmake --build build-asan -j $(JOBS) --target femto_unit_tests femto_render
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  FEMTO_PLUGIN_PATH=build-asan/bin/plugins $(call SANITIZE_UNIT,build-asan)

# Every test that renders or builds with several threads and compares across
# thread counts (photon passes, beam maps, tiles, streaming), not the
# accuracy tests (minutes each under TSan), nor the streaming peak-memory
# test (TSan's shadow memory is what it would measure). Each pattern runs in a
# process of its own: the beams tests that link transient_beams statically
# and those that load its plugin must not meet in one process (two copies of
# the same code; TSan then names no frame of the plugin and its suppressions
# cannot match).
TSAN_TESTS ?= ThreadEdges.* RenderLoop.* TileSide.* TransientBeamsPhotons.*ThreadCount* TransientBeamsRender.*ThreadCount* TransientNlosPath.*ThreadCount* \
  TransientPathPulses.*ThreadCount*
# Plugins are dlopen'ed: GCC's built-in symbolizer leaves their frames
# unnamed, which the suppressions then cannot match; llvm-symbolizer names them.
TSAN_SYMBOLIZER = $(shell command -v llvm-symbolizer)
sanitize-thread: deps
	@command -v llvm-symbolizer >/dev/null || { echo "error: llvm-symbolizer is needed (apt-get install llvm)" >&2; exit 1; }
	cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFEMTO_SANITIZE=thread
	cmake --build build-tsan -j $(JOBS) --target femto_unit_tests femto_render
	@set -f; for tests in $(TSAN_TESTS); do \
	  echo "== $$tests"; \
	  TSAN_OPTIONS=external_symbolizer_path=$(TSAN_SYMBOLIZER):halt_on_error=1:second_deadlock_stack=1:suppressions=$(CURDIR)/tools/sanitize/tsan-tbb.supp \
	    FEMTO_PLUGIN_PATH=build-tsan/bin/plugins $(call SANITIZE_UNIT,build-tsan) --gtest_filter="$$tests" || exit 1; \
	done

clean:
	rm -rf $(BUILD) build-asan build-tsan out
