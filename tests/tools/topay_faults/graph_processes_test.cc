// DescendantProcesses finds this process's children and grandchildren by command name (and not
// zombies), GraphProcesses only those with graph command names; CommandNameOf maps graph names to
// command names.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <filesystem>
#include <map>
#include <string>
#include <thread>

#include "tests/procs/graph_test_support.h"
#include "tools/topay_faults/graph_processes.h"

namespace topay::tools {
namespace {

TEST(GraphProcesses, FindsChildrenAndGrandchildrenButNotZombies) {
  const pid_t shell = test::Spawn({"/bin/sh", "-c", "sleep 30 & wait"}, "/dev/null");
  std::map<std::string, pid_t> found;
  for (int k = 0; k < 200 && !found.count("sleep"); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    found = DescendantProcesses(getpid());
  }
  EXPECT_EQ(found["sh"], shell);
  ASSERT_TRUE(found.count("sleep"));  // the grandchild
  EXPECT_NE(found["sleep"], shell);
  EXPECT_FALSE(DescendantProcesses(found["sleep"]).count("sh"));  // not a descendant of the sleep
  kill(found["sleep"], SIGKILL);
  kill(shell, SIGKILL);
  for (int k = 0; k < 200 && DescendantProcesses(getpid()).count("sh"); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));  // a zombie until reaped: not listed
  }
  EXPECT_FALSE(DescendantProcesses(getpid()).count("sh"));
  waitpid(shell, nullptr, 0);
}

TEST(GraphProcesses, OnlyGraphProcessesCountAsTheGraphs) {
  const std::string dir = test::TestDir("graph_processes");
  const std::string tracker = dir + "/topay-tracker";
  std::filesystem::copy_file("/bin/sleep", tracker, std::filesystem::copy_options::overwrite_existing);
  const pid_t graph = test::Spawn({tracker, "30"}, "/dev/null");
  const pid_t other = test::Spawn({"/bin/sleep", "30"}, "/dev/null");
  std::map<std::string, pid_t> found;
  for (int k = 0; k < 200 && !(found.count("topay-tracker") && DescendantProcesses(getpid()).count("sleep")); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    found = GraphProcesses(getpid());
  }
  EXPECT_EQ(found["topay-tracker"], graph);
  EXPECT_EQ(found.size(), 1u);  // not the sleep
  EXPECT_EQ(DescendantProcesses(getpid())["sleep"], other);
  kill(graph, SIGKILL), kill(other, SIGKILL);
  waitpid(graph, nullptr, 0), waitpid(other, nullptr, 0);
}

TEST(GraphProcesses, CommandNames) {
  EXPECT_EQ(CommandNameOf("logger"), "lcm-logger");
  EXPECT_EQ(CommandNameOf("canbridge"), "topay-canbridge");
}

}  // namespace
}  // namespace topay::tools
