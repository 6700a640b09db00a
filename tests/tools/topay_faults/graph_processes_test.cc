// DescendantProcesses finds this process's children and grandchildren by command name (and not
// zombies); CommandNameOf maps graph names to command names.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

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

TEST(GraphProcesses, CommandNames) {
  EXPECT_EQ(CommandNameOf("logger"), "lcm-logger");
  EXPECT_EQ(CommandNameOf("canbridge"), "topay-canbridge");
}

}  // namespace
}  // namespace topay::tools
