// The process library's event loop (procs/runtime/process_loop.h) over memq://: heartbeats at
// start and per period, timers, clean stop on SIGTERM, the common flags, and no busy waiting.

#include "procs/runtime/process_loop.h"

#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <csignal>
#include <vector>

#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::procs {
namespace {

using Clock = ProcessLoop::Clock;

ProcessOptions MemqOptions(double heartbeat_period_s = 1.0) {
  ProcessOptions options;
  options.name = "test-process";
  options.lcm_url = "memq://";
  options.heartbeat_period_s = heartbeat_period_s;
  return options;
}

double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

TEST(ProcessLoop, PublishesHeartbeatsAtStartAndEveryPeriod) {
  ProcessLoop loop(MemqOptions(0.05));
  ASSERT_TRUE(loop.ok()) << loop.error();
  std::vector<heartbeat_t> beats;
  loop.Subscribe<heartbeat_t>(std::string(channels::HEARTBEAT), [&](const heartbeat_t& hb) { beats.push_back(hb); });
  loop.SetHealth(heartbeat_t::WARN, "degraded");
  EXPECT_EQ(loop.RunUntil(Clock::now() + std::chrono::milliseconds(230)), kExitOk);
  ASSERT_GE(beats.size(), 3u);  // at 0, 50, 100, 150, 200 ms (a loaded CI machine may lose one)
  EXPECT_LE(beats.size(), 6u);
  for (std::size_t i = 0; i < beats.size(); ++i) {
    EXPECT_EQ(beats[i].seq, static_cast<std::int64_t>(i));
    EXPECT_EQ(beats[i].process_name, "test-process");
    EXPECT_EQ(beats[i].pid, getpid());
    EXPECT_EQ(beats[i].health, heartbeat_t::WARN);
    EXPECT_EQ(beats[i].status, "degraded");
  }
}

TEST(ProcessLoop, RunsTimersAtTheirPeriod) {
  ProcessLoop loop(MemqOptions());
  int fast = 0, slow = 0;
  loop.AddTimer(0.01, [&] { ++fast; });
  loop.AddTimer(0.1, [&] { ++slow; });
  loop.RunUntil(Clock::now() + std::chrono::milliseconds(250));
  // 25 and 2 calls on time; a late timer skips to the next period instead of bursting.
  EXPECT_GE(fast, 10);
  EXPECT_LE(fast, 26);
  EXPECT_GE(slow, 1);
  EXPECT_LE(slow, 2);
}

TEST(ProcessLoop, ScheduledTimersRunAtTheDeadlinesTheyAskFor) {
  ProcessLoop loop(MemqOptions());
  const ProcessLoop::Clock::time_point start = ProcessLoop::Clock::now();
  int calls = 0;
  double earliest_ms = 1e9;
  // Deadlines on a fixed grid of 3 ms from the start, whatever the wake-up delays.
  loop.AddScheduledTimer([&] {
    const auto now = ProcessLoop::Clock::now();
    if (calls > 0) {
      const auto due = start + std::chrono::milliseconds(3 * calls);
      earliest_ms = std::min(earliest_ms, std::chrono::duration<double, std::milli>(now - due).count());
    }
    ++calls;
    return start + std::chrono::milliseconds(3 * calls);
  });
  loop.RunUntil(start + std::chrono::milliseconds(300));
  EXPECT_GE(calls, 90);   // 100 deadlines in 300 ms (a loaded machine may merge a few)
  EXPECT_LE(calls, 102);
  EXPECT_GE(earliest_ms, 0.0) << "called before its deadline";
}

TEST(ProcessLoop, HandlePendingHandlesWhatHasArrivedUpToTheLimitWithoutWaiting) {
  ProcessLoop loop(MemqOptions());
  std::vector<std::int64_t> seen;
  loop.Subscribe<heartbeat_t>("HB_TEST", [&](const heartbeat_t& hb) { seen.push_back(hb.seq); });
  for (int i = 0; i < 5; ++i) {
    heartbeat_t hb{};
    hb.seq = i;
    loop.lcm().publish("HB_TEST", &hb);
  }
  EXPECT_EQ(loop.HandlePending(3), 3);
  EXPECT_EQ(seen, std::vector<std::int64_t>({0, 1, 2}));
  const Clock::time_point before = Clock::now();
  EXPECT_EQ(loop.HandlePending(10), 2);
  EXPECT_EQ(loop.HandlePending(10), 0);  // nothing left: returns at once
  EXPECT_LT(Clock::now() - before, std::chrono::milliseconds(500));
  EXPECT_EQ(seen.size(), 5u);
}

TEST(ProcessLoop, SigtermEndsRunCleanly) {
  ProcessLoop loop(MemqOptions());
  int ticks = 0;
  loop.AddTimer(0.01, [&] {
    if (++ticks == 3) std::raise(SIGTERM);  // blocked: becomes readable on the signalfd
  });
  const Clock::time_point start = Clock::now();
  EXPECT_EQ(loop.RunUntil(start + std::chrono::seconds(5)), kExitOk);
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(1));
  EXPECT_LE(ticks, 4);
}

TEST(ProcessLoop, SigintEndsRunCleanly) {
  ProcessLoop loop(MemqOptions());
  loop.AddTimer(0.01, [] { std::raise(SIGINT); });
  const Clock::time_point start = Clock::now();
  EXPECT_EQ(loop.RunUntil(start + std::chrono::seconds(5)), kExitOk);
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(1));
}

TEST(ProcessLoop, SleepsWhenIdle) {
  ProcessLoop loop(MemqOptions());
  const double cpu_before = CpuSeconds();
  loop.RunUntil(Clock::now() + std::chrono::milliseconds(500));
  // A busy loop would burn ~0.5 s of CPU; an idle one a few milliseconds.
  EXPECT_LT(CpuSeconds() - cpu_before, 0.05);
}

TEST(ProcessLoop, ReportsAnLcmUrlThatCannotOpen) {
  ProcessOptions options = MemqOptions();
  options.lcm_url = "nosuchprovider://";
  ProcessLoop loop(options);
  EXPECT_FALSE(loop.ok());
  EXPECT_NE(loop.error().find("nosuchprovider://"), std::string::npos);
  EXPECT_EQ(loop.Run(), kExitConfigError);
}

int Parse(std::vector<std::string> args, ProcessOptions* options) {
  CLI::App app{"test"};
  AddCommonFlags(&app, "default-name", options);
  std::vector<char*> argv;
  args.insert(args.begin(), "prog");
  for (std::string& a : args) argv.push_back(a.data());
  return ParseFlags(&app, static_cast<int>(argv.size()), argv.data()).value_or(-1);
}

TEST(CommonFlags, SetUrlConfigAndName) {
  ProcessOptions options;
  EXPECT_EQ(Parse({"--lcm-url", "memq://", "--config", "x.yaml", "--name", "n"}, &options), -1);
  EXPECT_EQ(options.lcm_url, "memq://");
  EXPECT_EQ(options.config_path, "x.yaml");
  EXPECT_EQ(options.name, "n");
}

TEST(CommonFlags, ExitCodesForHelpAndUsageErrors) {
  ProcessOptions options;
  testing::internal::CaptureStdout();
  EXPECT_EQ(Parse({"--help"}, &options), kExitOk);
  testing::internal::GetCapturedStdout();
  testing::internal::CaptureStderr();
  EXPECT_EQ(Parse({"--no-such-flag"}, &options), kExitUsageError);
  testing::internal::GetCapturedStderr();
}

TEST(CommonFlags, NameDefaultsToTheLauncherEnvironment) {
  ProcessOptions options;
  unsetenv("TOPAY_PROCESS_NAME");
  EXPECT_EQ(Parse({}, &options), -1);
  EXPECT_EQ(options.name, "default-name");
  setenv("TOPAY_PROCESS_NAME", "from-graph", 1);
  EXPECT_EQ(Parse({}, &options), -1);
  EXPECT_EQ(options.name, "from-graph");
  unsetenv("TOPAY_PROCESS_NAME");
}

}  // namespace
}  // namespace topay::procs
