#pragma once
// Support for tests that run real processes over real LCM: a private network namespace for the
// test process (else the test is SKIPPED, never passed silently), topay-launch as a child,
// a HEARTBEAT watcher, and checks that processes are gone (the test process is a child
// subreaper, so orphans come back to it and are reaped rather than left as zombies).

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "procs/launch/proc_stats.h"
#include "procs/runtime/net_namespace.h"
#include "topay/heartbeat_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay_msgs/channels.h"
#include "topay_msgs/checked_decode.h"

namespace topay::test {

using Clock = std::chrono::steady_clock;

inline std::string BinDir() { return std::string(TOPAY_BINARY_DIR) + "/bin"; }

inline double SecondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// Enters a private network namespace (loopback multicast) once per test process. Call it first
/// in a test: `if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;`. Also makes the process a
/// child subreaper.
inline bool EnterTestNamespace(std::string* why) {
  static bool entered = false;
  static std::string error;
  static bool tried = false;
  if (!tried) {
    tried = true;
    entered = procs::EnterPrivateNetworkNamespace(&error);
    prctl(PR_SET_CHILD_SUBREAPER, 1);
  }
  *why = "cannot create a private network namespace: " + error;
  return entered;
}

/// A fresh folder under the build tree for one test's files: test_out/procs/<Suite.Test>/<name>
/// (per test, as ctest runs the tests of a file in parallel).
inline std::string TestDir(const std::string& name) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = info != nullptr ? std::string(info->test_suite_name()) + "." + info->name() : "none";
  const std::filesystem::path dir = std::filesystem::path(TOPAY_BINARY_DIR) / "test_out" / "procs" / test / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline void WriteText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

inline std::string ReadText(const std::string& path) {
  std::ifstream file(path);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

/// Starts `program args...` with stdout and stderr into `output_path`; returns its pid. The child
/// is killed when the test process ends, however it ends (PR_SET_PDEATHSIG).
inline pid_t Spawn(const std::vector<std::string>& argv, const std::string& output_path) {
  const pid_t test_pid = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != test_pid) _exit(127);  // the test process ended before the line above
    const int fd = ::open(output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

/// Waits for `pid` up to timeout_s; returns its wait status, or -1 on timeout.
inline int WaitFor(pid_t pid, double timeout_s) {
  const Clock::time_point start = Clock::now();
  while (SecondsSince(start) < timeout_s) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return -1;
}

/// Stops each process still alive: SIGINT, then SIGKILL if it has not exited within 5 s.
inline void StopProcesses(const std::vector<pid_t>& pids) {
  for (pid_t pid : pids) {
    if (pid > 0 && launch::ProcessAlive(pid)) {
      kill(pid, SIGINT);
      if (WaitFor(pid, 5.0) == -1) kill(pid, SIGKILL), WaitFor(pid, 3.0);
    }
  }
}

/// Stops its processes (StopProcesses) when it goes out of scope: a test that fails an ASSERT
/// between starting and stopping them leaves nothing running into the next test.
class ProcessGuard {
 public:
  ProcessGuard() = default;
  ProcessGuard(ProcessGuard&& other) noexcept : pids_(std::move(other.pids_)) { other.pids_.clear(); }
  ProcessGuard(const ProcessGuard&) = delete;
  ProcessGuard& operator=(const ProcessGuard&) = delete;
  ProcessGuard& operator=(ProcessGuard&&) = delete;
  ~ProcessGuard() { StopProcesses(pids_); }
  void Add(pid_t pid) { pids_.push_back(pid); }

 private:
  std::vector<pid_t> pids_;
};

/// Reaps every exited child of this (subreaper) process, orphans included. Call it only after
/// waiting for the children whose status matters (it would take theirs too).
inline void ReapOrphans() {
  while (waitpid(-1, nullptr, WNOHANG) > 0) {
  }
}

/// True once none of `pids` is alive (zombies count as gone: they have ended, only their exit
/// status waits to be collected), polling up to timeout_s.
inline bool AllGoneWithin(const std::vector<int>& pids, double timeout_s, double* took_s) {
  const Clock::time_point start = Clock::now();
  while (true) {
    bool any = false;
    for (const int pid : pids) any = any || launch::ProcessAlive(pid);
    *took_s = SecondsSince(start);
    if (!any) return true;
    if (*took_s > timeout_s) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

/// Listens to HEARTBEAT (and optionally any other channel, counted) in this namespace.
class HeartbeatWatcher {
 public:
  struct Last {
    int pid = 0;
    std::int64_t seq = 0;
    std::string status;
    Clock::time_point at;
    int count = 0;
  };

  explicit HeartbeatWatcher(const std::string& url = "") : lcm_(url) {
    lcm_.subscribe(std::string(channels::HEARTBEAT), &HeartbeatWatcher::OnHeartbeat, this);
  }
  bool good() { return lcm_.good(); }
  lcm::LCM& lcm() { return lcm_; }

  /// Handles messages for `seconds`.
  /// Handles every message already queued, without waiting.
  void Drain() {
    while (lcm_.handleTimeout(0) > 0) {
    }
  }
  void Spin(double seconds) {
    const Clock::time_point start = Clock::now();
    while (SecondsSince(start) < seconds) lcm_.handleTimeout(10);
  }
  /// Handles messages until pred() or timeout; returns pred().
  template <class Pred>
  bool SpinUntil(Pred pred, double timeout_s) {
    const Clock::time_point start = Clock::now();
    while (!pred() && SecondsSince(start) < timeout_s) lcm_.handleTimeout(5);
    return pred();
  }

  std::map<std::string, Last> last;

 private:
  void OnHeartbeat(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    const auto hb = CheckedDecode<heartbeat_t>(rbuf->data, rbuf->data_size, nullptr);
    if (!hb) return;
    Last& entry = last[hb->process_name];
    entry.pid = hb->pid;
    entry.seq = hb->seq;
    entry.status = hb->status;
    entry.at = Clock::now();
    ++entry.count;
  }

  lcm::LCM lcm_;
};

}  // namespace topay::test

#include <nlohmann/json.hpp>

namespace topay::test {

/// A graph file for the tests: `processes` is the YAML list body (indented by 2).
inline std::string GraphYaml(const std::string& name, const std::string& processes, double grace_s = 2.0) {
  return "name: " + name + "\ngrace_period_s: " + std::to_string(grace_s) + "\nprocesses:\n" + processes;
}

/// A kinematic-sim process entry named `name` (publishes ROBOT_STATE; state_rate_hz from the
/// config at `config`, or the default 10 Hz).
inline std::string ModelProcess(const std::string& name, const std::string& config = "",
                                const std::string& extra = "") {
  std::string entry = "  - name: " + name + "\n    command: ${BIN_DIR}/topay-kinematic-sim\n";
  if (!config.empty()) entry += "    args: [--config, " + config + "]\n";
  return entry + "    publishes: [ROBOT_STATE]\n" + extra;
}

/// topay-launch on `graph_path` with `flags`, output into <run_dir>/launcher.out.
inline pid_t StartLauncher(const std::string& graph_path, const std::string& run_dir,
                           const std::vector<std::string>& flags) {
  std::filesystem::create_directories(run_dir);
  std::vector<std::string> argv = {BinDir() + "/topay-launch", graph_path, "--plain", "--run-dir", run_dir};
  argv.insert(argv.end(), flags.begin(), flags.end());
  return Spawn(argv, run_dir + "/launcher.out");
}

/// The pids the launcher reports in <run_dir>/status.json (0 for processes not running).
inline std::map<std::string, int> StatusPids(const std::string& run_dir) {
  std::map<std::string, int> pids;
  try {
    const nlohmann::json json = nlohmann::json::parse(ReadText(run_dir + "/status.json"));
    for (const auto& p : json.at("processes")) pids[p.at("name")] = p.at("pid");
  } catch (const std::exception&) {
  }
  return pids;
}

/// Publishes a SIM_EVENT that makes a box (id, full size, m) stand on the floor at p_W (x, y)
/// now, named `name` in the simulator's log.
inline void AppearBoxNow(lcm::LCM* lcm, std::int32_t id, double x_m, double y_m, const double (&size_m)[3],
                         const std::string& name) {
  sim_event_t e{};
  e.name = name;
  e.action = sim_event_t::APPEAR;
  e.box_id = id;
  e.has_box = true;
  e.center_m[0] = x_m;
  e.center_m[1] = y_m;
  e.center_m[2] = 0.5 * size_m[2];
  for (int a = 0; a < 3; ++a) e.size_m[a] = size_m[a];
  e.trigger = sim_event_t::NOW;
  lcm->publish(std::string(channels::SIM_EVENT), &e);
}

}  // namespace topay::test
