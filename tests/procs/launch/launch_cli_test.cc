// topay-launch's command line: --dry-run prints the resolved plan and starts nothing; a bad
// graph file or a command that does not exist is exit code 1 naming file and field before
// anything starts; a usage error is exit code 2. (Nothing here opens LCM.)

#include <gtest/gtest.h>

#include "graph_test_support.h"

namespace topay::test {
namespace {

int RunLaunch(const std::vector<std::string>& args, const std::string& out_path) {
  std::vector<std::string> argv = {BinDir() + "/topay-launch"};
  argv.insert(argv.end(), args.begin(), args.end());
  const int status = WaitFor(Spawn(argv, out_path), 10.0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(LaunchCli, DryRunPrintsTheResolvedPlan) {
  const std::string dir = TestDir("launch_cli_dry_run");
  EXPECT_EQ(RunLaunch({std::string(TOPAY_SOURCE_DIR) + "/config/graphs/sim.yaml", "--dry-run", "--run-dir", dir + "/run"},
                      dir + "/out.txt"),
            0);
  const std::string out = ReadText(dir + "/out.txt");
  EXPECT_NE(out.find("private network namespace (isolated)"), std::string::npos) << out;
  EXPECT_NE(out.find("1. logger"), std::string::npos) << out;
  EXPECT_NE(out.find("2. sim"), std::string::npos) << out;
  EXPECT_NE(out.find(BinDir() + "/topay-sim --config"), std::string::npos) << out;
  EXPECT_NE(out.find("lcm-logger --quiet --append " + dir + "/run/graph.lcmlog"), std::string::npos) << out;
  EXPECT_EQ(out.find("drive-pattern"), std::string::npos) << "autostart: false";
  EXPECT_FALSE(std::filesystem::exists(dir + "/run")) << "a dry run creates nothing";
  EXPECT_EQ(RunLaunch({std::string(TOPAY_SOURCE_DIR) + "/config/graphs/sim.yaml", "--dry-run", "--no-isolated"},
                      dir + "/out2.txt"),
            0);
  EXPECT_NE(ReadText(dir + "/out2.txt").find("not isolated"), std::string::npos);
}

TEST(LaunchCli, BadGraphFilesAreExitCodeOneNamingFileAndField) {
  const std::string dir = TestDir("launch_cli_bad");
  const std::map<std::string, std::string> cases = {
      {"unknown_key", "processes:\n  - {name: a, command: /bin/true, restrat: never}\n"},
      {"missing_command", "processes:\n  - {name: a}\n"},
      {"cycle", "processes:\n  - {name: a, command: /bin/true, depends_on: [b]}\n  - {name: b, command: /bin/true, depends_on: [a]}\n"},
      {"unknown_dependency", "processes:\n  - {name: a, command: /bin/true, depends_on: [zz]}\n"},
      {"no_such_command", "processes:\n  - {name: a, command: /no/such/binary}\n"},
  };
  const std::map<std::string, std::string> expected = {
      {"unknown_key", "processes[0] (a).restrat: unknown key 'restrat'"},
      {"missing_command", "processes[0] (a).command: missing"},
      {"cycle", "processes: dependency cycle among a, b"},
      {"unknown_dependency", "processes[0] (a).depends_on: unknown process 'zz'"},
      {"no_such_command", "process a.command: '/no/such/binary' not found or not executable"},
  };
  for (const auto& [name, text] : cases) {
    const std::string path = dir + "/" + name + ".yaml";
    WriteText(path, text);
    EXPECT_EQ(RunLaunch({path, "--run-dir", dir + "/run"}, dir + "/" + name + ".txt"), 1) << name;
    const std::string out = ReadText(dir + "/" + name + ".txt");
    EXPECT_NE(out.find(path), std::string::npos) << name << ": " << out;
    EXPECT_NE(out.find(expected.at(name)), std::string::npos) << name << ": " << out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/run"));
}

TEST(LaunchCli, UsageErrorsAreExitCodeTwo) {
  const std::string dir = TestDir("launch_cli_usage");
  EXPECT_EQ(RunLaunch({}, dir + "/none.txt"), 2);
  EXPECT_EQ(RunLaunch({"g.yaml", "--isolated", "--no-isolated"}, dir + "/both.txt"), 2);
  EXPECT_EQ(RunLaunch({"--help"}, dir + "/help.txt"), 0);
  EXPECT_NE(ReadText(dir + "/help.txt").find("--replay"), std::string::npos);
}

}  // namespace
}  // namespace topay::test
