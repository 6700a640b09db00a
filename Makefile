# Two commands on a fresh Debian 12 machine:
#   make demo   install what is missing, build, run the main job
#   make test   install what is missing, build (with assertions), run every test
.PHONY: all deps build build-test test demo bench clean

BUILD_DIR      ?= build
TEST_BUILD_DIR ?= build-test
JOBS           ?= $(shell nproc)
DEMO_OUT       ?= out/demo

all: build

deps:
	@./tools/install-deps.sh

# Release (-O2, no assertions): what benchmarks and the demo run.
build: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# RelWithDebInfo (-O2 -g, assertions on): what the tests run.
build-test: deps
	@cmake -S . -B $(TEST_BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DTOPAY_BUILD_BENCHMARKS=OFF >/dev/null
	@cmake --build $(TEST_BUILD_DIR) -j $(JOBS)

test: build-test
	@cd $(TEST_BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The main job. Until the planner and the process graph exist: generate a benchmark scene and
# a task, and draw them (see README).
demo: build
	@mkdir -p $(DEMO_OUT)
	$(BUILD_DIR)/bin/topay-scene --scene tables --seed 7 --range medium \
	  --json $(DEMO_OUT)/scene.json --task-json $(DEMO_OUT)/task.json --png $(DEMO_OUT)/scene.png
	@echo "demo: wrote $(DEMO_OUT)/scene.png, scene.json, task.json"

clean:
	rm -rf $(BUILD_DIR) $(TEST_BUILD_DIR)
