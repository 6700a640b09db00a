// Graph files (procs/launch/graph_spec.h): a full file loads with every key; each kind of bad
// file is an error naming the file, the line and the field.

#include "procs/launch/graph_spec.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "graph_test_support.h"

namespace topay::launch {
namespace {

using test::TestDir;
using test::WriteText;

// Loads `text` as a graph file; returns the GraphError's message ("" if it loaded).
std::string LoadError(const std::string& text, std::string* path_out = nullptr) {
  // One folder per test: ctest runs the tests of this file in parallel.
  static int call = 0;
  const std::string path = TestDir(std::string("graph_spec_") +
                                   testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                                   std::to_string(call++)) +
                           "/graph.yaml";
  WriteText(path, text);
  if (path_out != nullptr) *path_out = path;
  try {
    LoadGraph(path);
  } catch (const GraphError& e) {
    return e.what();
  }
  return "";
}

TEST(GraphSpec, LoadsEveryKeyAndOrdersByDependencies) {
  const std::string path = TestDir("graph_spec_full") + "/g.yaml";
  WriteText(path, R"(name: demo
isolated: true
lcm_url: udpm://239.255.76.67:7667?ttl=0
grace_period_s: 2.5
heartbeat_period_s: 0.5
run_root: /tmp/runs
processes:
  - name: planner
    command: ${BIN_DIR}/topay-planner
    args: [--config, a.yaml]
    env: {A: "1"}
    working_dir: /tmp
    depends_on: [model]
    restart: always
    restart_delay_s: 0.2
    restart_delay_max_s: 3
    max_restarts: 4
    heartbeat_timeout_s: 1.5
    startup_timeout_s: 9
    group: planning
    publishes: [TRAJECTORY]
    ends_graph: true
    realtime: {nice: -5, fifo_priority: 40, cpus: [0, 1], mlockall: true}
  - name: model
    command: model-bin
    heartbeat: false
    ready_delay_s: 0.1
    restart: never
)");
  const GraphSpec g = LoadGraph(path);
  EXPECT_EQ(g.name, "demo");
  EXPECT_TRUE(g.isolated);
  EXPECT_EQ(g.lcm_url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(g.grace_period_s, 2.5);
  EXPECT_EQ(g.heartbeat_period_s, 0.5);
  EXPECT_EQ(g.run_root, "/tmp/runs");
  ASSERT_EQ(g.processes.size(), 2u);
  EXPECT_EQ(g.processes[0].name, "model");  // the dependency first
  EXPECT_EQ(g.processes[0].restart, RestartPolicy::kNever);
  EXPECT_FALSE(g.processes[0].heartbeat);
  EXPECT_EQ(g.processes[0].ready_delay_s, 0.1);
  const ProcessSpec& p = g.processes[1];
  EXPECT_EQ(p.command, "${BIN_DIR}/topay-planner");
  EXPECT_EQ(p.args, (std::vector<std::string>{"--config", "a.yaml"}));
  EXPECT_EQ(p.env.at("A"), "1");
  EXPECT_EQ(p.working_dir, "/tmp");
  EXPECT_EQ(p.restart, RestartPolicy::kAlways);
  EXPECT_EQ(p.restart_delay_s, 0.2);
  EXPECT_EQ(p.restart_delay_max_s, 3.0);
  EXPECT_EQ(p.max_restarts, 4);
  EXPECT_EQ(p.heartbeat_timeout_s, 1.5);
  EXPECT_EQ(p.startup_timeout_s, 9.0);
  EXPECT_EQ(p.group, "planning");
  EXPECT_EQ(p.publishes, std::vector<std::string>{"TRAJECTORY"});
  EXPECT_TRUE(p.ends_graph);
  EXPECT_FALSE(g.processes[0].ends_graph);
  EXPECT_EQ(p.realtime.nice, -5);
  EXPECT_EQ(p.realtime.fifo_priority, 40);
  EXPECT_EQ(p.realtime.cpus, (std::vector<int>{0, 1}));
  EXPECT_TRUE(p.realtime.mlockall);
}

TEST(GraphSpec, DefaultsNameToTheFileStem) {
  std::string path;
  EXPECT_EQ(LoadError("processes:\n  - {name: a, command: x}\n", &path), "");
  const GraphSpec g = LoadGraph(path);
  EXPECT_EQ(g.name, "graph");
  EXPECT_FALSE(g.isolated);
  EXPECT_EQ(g.processes[0].restart, RestartPolicy::kOnFailure);
  EXPECT_EQ(g.processes[0].heartbeat_timeout_s, 3.0);
}

TEST(GraphSpec, UnknownKeyIsNamedWithFileAndLine) {
  std::string path;
  const std::string error = LoadError("processes:\n  - name: a\n    command: x\n    comand: y\n", &path);
  EXPECT_NE(error.find(path + ":4:"), std::string::npos) << error;
  EXPECT_NE(error.find("processes[0] (a)"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown key 'comand'"), std::string::npos) << error;
  EXPECT_NE(LoadError("nme: x\nprocesses:\n  - {name: a, command: x}\n").find("unknown key 'nme'"), std::string::npos);
  EXPECT_NE(LoadError("processes:\n  - name: a\n    command: x\n    realtime: {nic: 1}\n").find("(a).realtime.nic: unknown key 'nic'"),
            std::string::npos);
}

TEST(GraphSpec, MissingCommandIsNamed) {
  std::string path;
  const std::string error = LoadError("processes:\n  - name: a\n    args: [x]\n", &path);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("processes[0] (a).command: missing"), std::string::npos) << error;
}

TEST(GraphSpec, DependencyCycleIsNamed) {
  std::string path;
  const std::string error = LoadError(R"(processes:
  - {name: a, command: x, depends_on: [c]}
  - {name: b, command: x}
  - {name: c, command: x, depends_on: [a]}
)", &path);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("dependency cycle among a, c"), std::string::npos) << error;
}

TEST(GraphSpec, UnknownDependencyIsNamed) {
  std::string path;
  const std::string error = LoadError("processes:\n  - {name: a, command: x, depends_on: [mappr]}\n", &path);
  EXPECT_NE(error.find(path + ":2:"), std::string::npos) << error;
  EXPECT_NE(error.find("processes[0] (a).depends_on: unknown process 'mappr'"), std::string::npos) << error;
}

TEST(GraphSpec, OtherBadValuesAreNamed) {
  EXPECT_NE(LoadError("processes:\n  - {name: a, command: x, restart: sometimes}\n").find("restart: must be"),
            std::string::npos);
  EXPECT_NE(LoadError("processes:\n  - {name: a, command: x}\n  - {name: a, command: y}\n").find("duplicate"),
            std::string::npos);
  EXPECT_NE(LoadError("processes:\n  - {name: a, command: x, realtime: {fifo_priority: 100}}\n").find("fifo_priority"),
            std::string::npos);
  EXPECT_NE(LoadError("processes:\n  - {name: a, command: x, heartbeat_timeout_s: abc}\n").find("heartbeat_timeout_s: wrong type"),
            std::string::npos);
  EXPECT_NE(LoadError("name: x\n").find("processes: a non-empty list is required"), std::string::npos);
  EXPECT_NE(LoadError("processes: [\n").find("YAML"), std::string::npos);
  EXPECT_NE(LoadError("processes:\n  - {command: x}\n").find("name: missing"), std::string::npos);
}

TEST(GraphSpec, KeyThatIsNotANameIsAGraphError) {
  // A list, a map or null as a key (`[k]: 1`) used to escape LoadGraph as yaml-cpp's bad
  // conversion instead of a GraphError (found by the graph_yaml fuzz target,
  // tests/fuzz/regressions/graph_yaml/key_not_a_name).
  std::string path;
  const std::string error = LoadError("processes:\n  - {name: a, command: x, [k]: 1}\n", &path);
  EXPECT_NE(error.find(path + ":2: processes[0] (a): a key must be a name"), std::string::npos) << error;
  EXPECT_NE(LoadError("{a: 1}: 2\nprocesses:\n  - {name: a, command: x}\n").find(":1: a key must be a name"),
            std::string::npos);
  EXPECT_NE(LoadError("processes:\n  - name: a\n    command: x\n    realtime: {~: 1}\n").find("(a).realtime: a key"),
            std::string::npos);
}

TEST(GraphSpec, ParsesTextAsLoadGraphReadsFiles) {
  const std::string path = std::string(TOPAY_SOURCE_DIR) + "/config/graphs/demo.yaml";
  const GraphSpec loaded = LoadGraph(path);
  std::ifstream file(path);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const GraphSpec parsed = ParseGraph(text, path);
  EXPECT_EQ(parsed.file, path);
  EXPECT_EQ(parsed.name, loaded.name);
  ASSERT_EQ(parsed.processes.size(), loaded.processes.size());
  for (std::size_t i = 0; i < parsed.processes.size(); ++i) {
    EXPECT_EQ(parsed.processes[i].name, loaded.processes[i].name);
    EXPECT_EQ(parsed.processes[i].args, loaded.processes[i].args);
  }
  try {
    ParseGraph("processes: [\n", "mem/graph.yaml");
    FAIL() << "no error for malformed YAML";
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("mem/graph.yaml:"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ParseGraph("processes:\n  - {name: a, command: x}\n", "some/dir/g2.yaml").name, "g2");
}

TEST(GraphSpec, ExpandsVariablesAndNamesUnknownOnes) {
  std::string path;
  ASSERT_EQ(LoadError("processes:\n  - {name: a, command: '${BIN_DIR}/a', args: ['${RUN_DIR}/x.log'], env: {K: '${BIN_DIR}'}}\n", &path), "");
  GraphSpec g = LoadGraph(path);
  GraphVariables vars{{{"BIN_DIR", "/b"}, {"RUN_DIR", "/r"}}};
  ExpandVariables(vars, &g);
  EXPECT_EQ(g.processes[0].command, "/b/a");
  EXPECT_EQ(g.processes[0].args[0], "/r/x.log");
  EXPECT_EQ(g.processes[0].env.at("K"), "/b");
  GraphSpec bad = LoadGraph(path);
  bad.processes[0].args[0] = "${NOPE}";
  try {
    ExpandVariables(vars, &bad);
    FAIL() << "no error for ${NOPE}";
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("process a.args: unknown variable ${NOPE}"), std::string::npos) << e.what();
  }
}

TEST(GraphSpec, SelectsGroupsWithTheirDependencies) {
  std::string path;
  ASSERT_EQ(LoadError(R"(processes:
  - {name: a, command: x}
  - {name: b, command: x, depends_on: [a], group: g}
  - {name: c, command: x, group: h}
)", &path), "");
  GraphSpec g = LoadGraph(path);
  SelectGroups({"g"}, &g);
  ASSERT_EQ(g.processes.size(), 2u);
  EXPECT_EQ(g.processes[0].name, "a");
  EXPECT_EQ(g.processes[1].name, "b");
}

TEST(GraphSpec, AutostartFalseOnlyWithItsGroup) {
  std::string path;
  ASSERT_EQ(LoadError(R"(processes:
  - {name: a, command: x, group: g}
  - {name: b, command: x, depends_on: [a], group: h, autostart: false}
)", &path), "");
  GraphSpec all = LoadGraph(path);
  SelectGroups({}, &all);
  ASSERT_EQ(all.processes.size(), 1u);
  EXPECT_EQ(all.processes[0].name, "a");
  GraphSpec h = LoadGraph(path);
  SelectGroups({"h"}, &h);
  EXPECT_EQ(h.processes.size(), 2u);
}

TEST(GraphSpec, WithoutDropsAGroupUnlessAKeptProcessNeedsIt) {
  std::string path;
  ASSERT_EQ(LoadError(R"(processes:
  - {name: a, command: x, group: g}
  - {name: viz, command: x, depends_on: [a], group: viewer}
  - {name: c, command: x, depends_on: [a], group: h}
)", &path), "");
  GraphSpec g = LoadGraph(path);
  ExcludeGroups({"viewer"}, &g);
  ASSERT_EQ(g.processes.size(), 2u);
  EXPECT_EQ(g.processes[1].name, "c");
  GraphSpec needed = LoadGraph(path);
  try {
    ExcludeGroups({"g"}, &needed);
    FAIL() << "dropped a process another one depends on";
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("viz depends on a"), std::string::npos) << e.what();
  }
}

TEST(GraphSpec, ShippedGraphsLoad) {
  const GraphSpec sim = LoadGraph(std::string(TOPAY_SOURCE_DIR) + "/config/graphs/sim.yaml");
  EXPECT_TRUE(sim.isolated);
  EXPECT_EQ(sim.processes.front().name, "logger");
  const GraphSpec robot = LoadGraph(std::string(TOPAY_SOURCE_DIR) + "/config/graphs/robot.yaml");
  EXPECT_FALSE(robot.isolated);
  EXPECT_FALSE(robot.processes.empty());
}

}  // namespace
}  // namespace topay::launch
