#pragma once
// topay-launch's supervisor: starts the graph's processes in dependency order, watches their
// heartbeats and exits, restarts them by policy with exponential backoff, routes their output,
// reports the status (terminal table, GRAPH_STATUS, <run>/status.json) and stops them in
// reverse order on SIGINT/SIGTERM (grace period, then SIGKILL). Single-threaded: one poll()
// over a signalfd, the LCM fd and the children's output pipes.

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "procs/launch/console.h"
#include "procs/launch/graph_spec.h"
#include "procs/launch/group_guardian.h"
#include "procs/launch/log_player.h"
#include "procs/launch/status_report.h"
#include "procs/runtime/signal_fd.h"
#include "procs/runtime/watchdog_notify.h"

namespace topay::launch {

struct SupervisorOptions {
  std::string run_dir;                 ///< existing folder for the logs and status.json
  double status_period_s = 1.0;        ///< GRAPH_STATUS, status.json and the live table
  double plain_status_period_s = 10.0; ///< table as plain lines when not on a terminal
  bool tty = false;                    ///< colours and a live table
  double stable_after_s = 10.0;        ///< a run this long resets the backoff
  std::optional<double> duration_s;    ///< stop the graph after this long (tests, benchmarks)
  std::optional<ReplayOptions> replay; ///< play a log once every process is ready
};

enum class ProcState { kWaiting, kStarting, kRunning, kBackoff, kExited, kStopping };
const char* ToString(ProcState state);

class Supervisor {
 public:
  using Clock = std::chrono::steady_clock;

  /// Takes the (expanded) graph. Opens LCM on graph.lcm_url (throws std::runtime_error if it
  /// cannot) and blocks SIGINT/SIGTERM/SIGHUP/SIGCHLD into a signalfd: construct it before
  /// any thread starts. Opens the replay log if any (throws std::runtime_error).
  Supervisor(GraphSpec graph, SupervisorOptions options);
  ~Supervisor();

  /// Runs the graph until a signal, the duration, the end of the replay, the exit of an
  /// `ends_graph` process or every process has exited for good. Returns 0, the exit code of the
  /// `ends_graph` process that ended it, or 1 after an internal error (fork or poll failed; the
  /// graph is stopped).
  int Run();

 private:
  struct Process;
  struct Stream;

  void Tick(Clock::time_point now);  // one iteration while running (not stopping)
  void StartReady(Clock::time_point now);
  void Start(Process& p, Clock::time_point now);
  void MarkReady(Process& p);  // first heartbeat (or ready delay): dependents may start
  void Reap(Clock::time_point now);
  void OnExit(Process& p, int status, Clock::time_point now);
  void Supervise(Clock::time_point now);
  void OnHeartbeat(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  /// A datagram on the watchdog socket: "WATCHDOG=1" from a running child keeps it alive as a
  /// heartbeat does (its health and status come only with the bus heartbeat).
  void OnWatchdog(pid_t pid, std::string_view text);
  void ReadOutput(Stream& stream, bool hang_up);
  // supervisor_status.cc: CPU and memory from /proc, the status rows, their three outputs.
  void SampleResources(Clock::time_point now);
  std::vector<ProcessStatusRow> Rows(Clock::time_point now) const;
  void ReportStatus(Clock::time_point now, bool plain);
  void BeginStop(const std::string& reason, Clock::time_point now);
  void StopStep(Clock::time_point now);
  bool AllReady() const;
  bool AllDone() const;
  Clock::time_point NextWake(Clock::time_point now) const;
  void PollOnce(Clock::time_point now);
  void Log(const std::string& text) {
    console_.Event(text);
    table_dirty_ = true;  // on a terminal the table is redrawn with the new state
  }

  GraphSpec graph_;
  SupervisorOptions options_;
  procs::SignalFd signals_;
  GroupGuardian guardian_;  // forked before LCM and any child
  Console console_;
  std::unique_ptr<lcm::LCM> lcm_;
  std::unique_ptr<procs::WatchdogSocket> watchdog_;  // the children's NOTIFY_SOCKET (null: bus heartbeats only)
  std::vector<std::unique_ptr<Process>> processes_;
  std::vector<std::unique_ptr<Stream>> streams_;
  std::unique_ptr<LogPlayer> player_;
  Clock::time_point launched_;
  Clock::time_point next_status_;
  Clock::time_point next_plain_status_;
  std::optional<Clock::time_point> replay_done_at_;
  bool stopping_ = false;
  Clock::time_point stop_deadline_;
  bool killed_all_ = false;
  bool table_dirty_ = false;
  int exit_code_ = 0;
};

}  // namespace topay::launch
