# Two commands on a fresh Debian 12 machine:
#   make demo   install what is missing, build, run the main job
#   make test   install what is missing, build (with assertions), run every test
.PHONY: all deps build build-test test test-fast demo graph bench bench-replan clean

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

# The fast suite: every test but the long ones (labelled long/<folder>: the 100-task runs and
# the benchmark harness's smoke runs). CI runs `make test`, all of them.
test-fast: build-test
	@cd $(TEST_BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -LE '^long'

# The main job until the process graph exists: one TopAY plan (front end, parallel trajectory
# optimization, independent validation) on a seeded Tables room and a medium-range task,
# writing the summary, the trajectory JSON and the plots. Exit code 3 (the plan failed, reason
# printed, JSON and top-down PNG still written) does not fail the demo; any other error does.
demo: build
	@mkdir -p $(DEMO_OUT)
	$(BUILD_DIR)/bin/topay-plan --scene tables --seed 2 --range medium \
	  --json $(DEMO_OUT)/trajectory.json --png $(DEMO_OUT)/path.png \
	  --time-png $(DEMO_OUT)/time_plots.png || [ $$? -eq 3 ]
	@echo "demo: wrote $(DEMO_OUT)/trajectory.json, path.png, time_plots.png"

# The simulation process graph (config/graphs/sim.yaml), isolated in a private network
# namespace; Ctrl-C stops it. Run folder: out/runs/<date-time>/ (docs/running.md).
graph: build
	$(BUILD_DIR)/bin/topay-launch config/graphs/sim.yaml $(GRAPH_ARGS)

# The replanning-latency benchmark of issue 18 (docs/benchmarks.md): sim + mapper + planner in a
# private network namespace, REPLAN_EVENTS boxes appearing on the path ahead of the driving
# robot; scan -> new trajectory, median and p95. Builds only what it runs, in the test build.
# `make test` runs the same program's 3-event smoke case (structure only, never the speed).
REPLAN_EVENTS ?= 20
REPLAN_SEED   ?= 18
bench-replan: deps
	@cmake -S . -B $(TEST_BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DTOPAY_BUILD_BENCHMARKS=OFF >/dev/null
	@cmake --build $(TEST_BUILD_DIR) -j $(JOBS) --target replan_latency_test topay-sim topay-mapper topay-planner
	TOPAY_REPLAN_EVENTS=$(REPLAN_EVENTS) TOPAY_REPLAN_SEED=$(REPLAN_SEED) $(TEST_BUILD_DIR)/bin/replan_latency_test

clean:
	rm -rf $(BUILD_DIR) $(TEST_BUILD_DIR)
