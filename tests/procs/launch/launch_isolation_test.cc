// Two graphs started with --isolated side by side, from the same namespace: each runs in its
// own private network namespace, so neither graph's log holds a message of the other, and the
// namespace they were started from sees none of their traffic.

#include <gtest/gtest.h>

#include <set>

#include "graph_test_support.h"

namespace topay::test {
namespace {

// Names of the processes whose heartbeats the log holds.
std::set<std::string> HeartbeatNames(const std::string& log_path) {
  std::set<std::string> names;
  lcm::LogFile log(log_path, "r");
  EXPECT_TRUE(log.good()) << log_path;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    if (event->channel != channels::HEARTBEAT) continue;
    if (const auto hb = CheckedDecode<heartbeat_t>(event->data, event->datalen, nullptr)) names.insert(hb->process_name);
  }
  return names;
}

TEST(LaunchIsolation, TwoIsolatedGraphsDoNotSeeEachOther) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("isolation");
  pid_t launchers[2];
  const char* names[2] = {"alpha", "beta"};
  for (int g = 0; g < 2; ++g) {
    const std::string graph = dir + "/" + names[g] + ".yaml";
    WriteText(graph, GraphYaml(names[g], ModelProcess(std::string(names[g]) + "-model") +
                                             "  - name: " + names[g] + "-logger\n    command: lcm-logger\n"
                                             "    args: [-f, '${RUN_DIR}/graph.lcmlog']\n    heartbeat: false\n"));
    launchers[g] = StartLauncher(graph, dir + "/" + names[g], {"--isolated", "--duration", "3"});
  }
  HeartbeatWatcher watcher;  // in the namespace the launchers were started from
  ASSERT_TRUE(watcher.good());
  watcher.Spin(2.0);
  EXPECT_TRUE(watcher.last.empty()) << "heartbeats leaked out of the isolated graphs";
  for (int g = 0; g < 2; ++g) {
    const int status = WaitFor(launchers[g], 10.0);
    const std::string out = ReadText(dir + "/" + names[g] + "/launcher.out");
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
    EXPECT_NE(out.find("isolated: private network namespace"), std::string::npos) << out;
  }
  EXPECT_EQ(HeartbeatNames(dir + "/alpha/graph.lcmlog"), std::set<std::string>{"alpha-model"});
  EXPECT_EQ(HeartbeatNames(dir + "/beta/graph.lcmlog"), std::set<std::string>{"beta-model"});
}

}  // namespace
}  // namespace topay::test
