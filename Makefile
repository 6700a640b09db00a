# Two commands on a fresh Debian 12 machine:
#   make demo   install what is missing, build, run the main job
#   make test   install what is missing, build (with assertions), run every test
.PHONY: all deps build build-test test test-fast test-demo demo missions demo-plan graph replay-view bench bench-replan bench-can fuzz faults test-faults test-asan test-tsan test-tsan-smoke tsan-configure clean

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
	@tools/check-disk-space.sh $(TEST_BUILD_DIR) 16
	@cmake -S . -B $(TEST_BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DTOPAY_BUILD_BENCHMARKS=OFF >/dev/null
	@cmake --build $(TEST_BUILD_DIR) -j $(JOBS)

test: build-test
	@cd $(TEST_BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The fast suite: every test but the long ones (labelled long/<folder>: the 100-task runs and
# the benchmark harness's smoke runs). CI runs `make test`, all of them.
test-fast: build-test
	@cd $(TEST_BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -LE '^long'

# The main job: the closed loop (docs/demo.md). The paper's pick-and-place task in a Tables room
# the robot has never seen (mapped only by its LiDAR as it goes), through the real processes
# (sim, director, mapper, planner, tracker, mission, logger) in a private network namespace,
# headless; a box appears on the route mid-run. Through CAN as on the robot (CAN=1, the default:
# tracker -> canbridge -> CAN bus -> motorsim -> plant, feedback -> estimator; config/graphs/
# demo.yaml); CAN=0 runs the same graph without CAN (config/graphs/demo_direct.yaml). Prints the mission's progress and, at the end,
# the summary (result, time, replans, ground-truth collisions, tracking error, planning and
# solve times) and where the log and plots are (out/demo/seed-<S>/). Exits non-zero if the
# mission failed or touched anything.
# The viewer (topay-viz, docs/viewer.md) serves the run at http://127.0.0.1:8765/ while it lasts
# (its address is printed); VIEW=0 leaves it out.
DEMO_SEED ?= 1
CAN       ?= 1
VIEW      ?= 1
DEMO_GRAPH = config/graphs/$(if $(filter 0,$(CAN)),demo_direct,demo).yaml
VIEW_FLAG  = $(if $(filter 0,$(VIEW)),--no-view,)
demo: build
	$(BUILD_DIR)/bin/topay-missions --seeds 1 --first-seed $(DEMO_SEED) --out $(DEMO_OUT) --graph $(DEMO_GRAPH) $(VIEW_FLAG)

# The closed-loop demo's end-to-end test (topay-missions on seed 1 through the whole graph; not
# in `make test`: docs/demo.md "Known problems").
test-demo: build-test
	@cd $(TEST_BUILD_DIR) && TOPAY_DEMO_TEST=1 ctest --output-on-failure -R MissionsDemo

# The same mission over SEEDS rooms, one graph after another, with a table of results
# (out/missions/results.md).
SEEDS      ?= 20
FIRST_SEED ?= 1
missions: build
	$(BUILD_DIR)/bin/topay-missions --seeds $(SEEDS) --first-seed $(FIRST_SEED) --out out/missions --graph $(DEMO_GRAPH) $(VIEW_FLAG)

# One TopAY plan (the main job before the closed loop): a seeded Tables room and a medium-range
# task; the summary, the trajectory JSON and the plots in out/plan/. Exit code 3 (the plan failed,
# reason printed, JSON and top-down PNG still written) does not fail it; any other error does.
demo-plan: build
	@mkdir -p out/plan
	$(BUILD_DIR)/bin/topay-plan --scene tables --seed 2 --range medium \
	  --json out/plan/trajectory.json --png out/plan/path.png \
	  --time-png out/plan/time_plots.png || [ $$? -eq 3 ]
	@echo "demo-plan: wrote out/plan/trajectory.json, path.png, time_plots.png"

# A recorded run in the viewer with play / pause / speed / a time slider (docs/viewer.md):
#   make replay-view LOG=out/demo/seed-1/graph.lcmlog      then open http://127.0.0.1:8765/
LOG ?= $(DEMO_OUT)/seed-$(DEMO_SEED)/graph.lcmlog
replay-view: build
	$(BUILD_DIR)/bin/topay-viz --log $(LOG)

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

# The CAN bridge's timing (docs/benchmarks.md "CAN bridge"): command -> CAN frame latency, cycle
# jitter with and without the real-time settings, bus load; 60 s each (CAN_BENCH_S).
CAN_BENCH_S ?= 60
bench-can: build
	tools/bench/can_bench.sh $(BUILD_DIR) $(CAN_BENCH_S)

# Reliability (docs/reliability.md). The fuzz campaign: every target of tests/fuzz/ built with
# clang as a libFuzzer binary with ASan + UBSan (build-fuzz/), then run for FUZZ_RUNS
# executions or FUZZ_SECONDS each (report: build-fuzz/fuzz/report.md). FUZZ_TARGETS picks some;
# FUZZ_JOBS targets run at a time, FUZZ_WORKERS libFuzzer processes on each (their runs add up).
# `make test` runs each target's seeds, regressions and 3,000 mutations (ctest -L fuzz).
FUZZ_BUILD_DIR ?= build-fuzz
FUZZ_RUNS      ?= 1000000
FUZZ_SECONDS   ?= 1800
FUZZ_TARGETS   ?=
FUZZ_JOBS      ?= 1
FUZZ_WORKERS   ?= 1
fuzz:
	@./tools/install-deps.sh --fuzz
	@cmake -S . -B $(FUZZ_BUILD_DIR) -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOPAY_FUZZ=ON -DTOPAY_SANITIZE=address,undefined \
	  -DTOPAY_BUILD_BENCHMARKS=OFF >/dev/null
	@cmake --build $(FUZZ_BUILD_DIR) -j $(JOBS) --target topay_fuzz_all
	FUZZ_JOBS=$(FUZZ_JOBS) FUZZ_WORKERS=$(FUZZ_WORKERS) tools/fuzz/run_fuzzers.sh $(FUZZ_BUILD_DIR) $(FUZZ_RUNS) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# The fault-injection suite (tools/topay_faults, docs/reliability.md): the closed-loop mission
# through CAN, again and again, with FAULT_RUNS episodes of every fault (kill -9 of each process,
# CAN, LCM, hostile goals and payloads) injected during it; the table in out/faults/results.md.
# Exits non-zero if any episode broke a rule (contact, no stop, late stop, crash, no recovery).
# FAULTS picks some (comma-separated; `build/bin/topay-faults --list`). About 2 h for 20 runs;
# an interrupted campaign (Ctrl-C keeps what it has) goes on with `make faults FAULTS_RESUME=1`.
FAULT_RUNS    ?= 20
FAULTS        ?=
FAULTS_RESUME ?=
faults: build
	$(BUILD_DIR)/bin/topay-faults --runs $(FAULT_RUNS) --out out/faults $(if $(FAULTS),--faults $(FAULTS),) \
	  $(if $(FAULTS_RESUME),--resume,)

# The fault-injection smoke (one mission: kill -9 of the tracker, a NaN goal, hostile payloads;
# about 25 s; not in `make test`: docs/reliability.md).
test-faults: build-test
	@cd $(TEST_BUILD_DIR) && TOPAY_FAULTS_TEST=1 ctest --output-on-failure -R FaultsSmoke

# The whole suite under sanitizers (own build folders; any report fails the test that hit it, and
# a report in a log a test's processes wrote fails the run: tools/sanitizers/check-child-reports.sh):
# ASan + UBSan (leaks included), and TSan. CTEST_ARGS narrows them, e.g. CTEST_ARGS='-L fuzz'.
ASAN_BUILD_DIR ?= build-asan
TSAN_BUILD_DIR ?= build-tsan
CTEST_ARGS     ?=
test-asan: deps
	@cmake -S . -B $(ASAN_BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOPAY_SANITIZE=address,undefined \
	  -DTOPAY_BUILD_BENCHMARKS=OFF >/dev/null
	@cmake --build $(ASAN_BUILD_DIR) -j $(JOBS)
	@rm -rf $(ASAN_BUILD_DIR)/test_out
	@cd $(ASAN_BUILD_DIR) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tools/sanitizers/lsan.supp \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS); \
	  status=$$?; $(CURDIR)/tools/sanitizers/check-child-reports.sh . && exit $$status
# TSan links a oneTBB built with -fsanitize=thread (Debian's is not instrumented, and TSan then
# takes every result read after task_group::wait for a race): tools/sanitizers/build-tsan-tbb.sh.
tsan-configure: deps
	@tools/sanitizers/build-tsan-tbb.sh $(TSAN_BUILD_DIR)/third_party/tbb-tsan
	@cmake -S . -B $(TSAN_BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOPAY_SANITIZE=thread \
	  -DTBB_DIR=$(CURDIR)/$(TSAN_BUILD_DIR)/third_party/tbb-tsan/lib/cmake/TBB -DTOPAY_BUILD_BENCHMARKS=OFF >/dev/null
test-tsan: tsan-configure
	@cmake --build $(TSAN_BUILD_DIR) -j $(JOBS)
	@rm -rf $(TSAN_BUILD_DIR)/test_out
	@cd $(TSAN_BUILD_DIR) && TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$(CURDIR)/tools/sanitizers/tsan.supp \
	  ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS); \
	  status=$$?; $(CURDIR)/tools/sanitizers/check-child-reports.sh . && exit $$status
# CI's sanitizer run (.ci/run, after make test): TSan over the tests of the code that runs
# threads (the planner's parallel arm searches, shortcuts and cost chunks on TBB, the planner
# process's worker, the simulator's scan worker, the director's placement, the viewer's server),
# each binary whole. The whole suite under TSan (make test-tsan) does not fit CI's budget.
TSAN_SMOKE_TESTS ?= parallel_acquisition_test path_shortcut_test trajectory_objective_test plan_worker_test \
  scan_worker_test background_placement_test director_node_test ws_server_slow_client_test ws_server_hostile_test
test-tsan-smoke: tsan-configure
	@cmake --build $(TSAN_BUILD_DIR) -j $(JOBS) --target $(TSAN_SMOKE_TESTS)
	@tools/sanitizers/run-tsan-tests.sh $(TSAN_BUILD_DIR) $(TSAN_SMOKE_TESTS)

clean:
	rm -rf $(BUILD_DIR) $(TEST_BUILD_DIR) $(FUZZ_BUILD_DIR) $(ASAN_BUILD_DIR) $(TSAN_BUILD_DIR)
