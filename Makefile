# femto quick start:  `make render` renders the default scene, `make test` runs the tests.
# Both install missing Debian packages, configure and build first (render: only
# the CLI and the plugins; test: everything).
BUILD ?= build
SCENE ?= scenes/cornell-box/scene.xml
OUT ?= out/cornell-box.exr
JOBS ?= $(shell nproc)

.PHONY: all deps configure build build-render render python test clean

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

clean:
	rm -rf $(BUILD) out
