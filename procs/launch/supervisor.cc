#include "procs/launch/supervisor.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "procs/launch/child_process.h"
#include "procs/launch/proc_stats.h"
#include "procs/launch/supervisor_process.h"
#include "procs/launch/status_report.h"
#include "procs/runtime/process_loop.h"
#include "topay/graph_status_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"
#include "topay_msgs/checked_decode.h"

namespace topay::launch {

using Clock = Supervisor::Clock;

namespace {

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
Clock::duration FromSeconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

std::string DescribeExit(int status) {
  if (WIFEXITED(status)) return "exited with code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return std::string("killed by ") + strsignal(WTERMSIG(status));
  return "ended";
}

}  // namespace

const char* ToString(ProcState state) {
  switch (state) {
    case ProcState::kWaiting: return "WAITING";
    case ProcState::kStarting: return "STARTING";
    case ProcState::kRunning: return "RUNNING";
    case ProcState::kBackoff: return "BACKOFF";
    case ProcState::kExited: return "EXITED";
    case ProcState::kStopping: return "STOPPING";
  }
  return "?";
}

Supervisor::Supervisor(GraphSpec graph, SupervisorOptions options)
    : graph_(std::move(graph)),
      options_(std::move(options)),
      signals_({SIGINT, SIGTERM, SIGHUP, SIGCHLD}),
      console_(stdout, options_.tty, options_.run_dir + "/launch.log") {
  lcm_ = std::make_unique<lcm::LCM>(graph_.lcm_url);
  if (!lcm_->good()) {
    throw std::runtime_error("cannot open LCM (" + (graph_.lcm_url.empty() ? "default URL" : graph_.lcm_url) +
                             "): no multicast route? use --isolated or add one");
  }
  lcm_->subscribe(std::string(channels::HEARTBEAT), &Supervisor::OnHeartbeat, this);
  try {  // abstract: nothing left on disk, and the children share the launcher's network namespace
    watchdog_ = std::make_unique<procs::WatchdogSocket>("@topay-launch-" + std::to_string(getpid()));
  } catch (const std::exception& e) {
    Log(std::string("watchdog socket: ") + e.what() + "; supervising by the bus heartbeat only");
  }
  for (const ProcessSpec& spec : graph_.processes) {
    auto p = std::make_unique<Process>();
    p->spec = spec;
    p->index = static_cast<int>(processes_.size());
    p->log.open(options_.run_dir + "/" + spec.name + ".log", std::ios::app);
    processes_.push_back(std::move(p));
  }
  if (options_.replay) {
    std::set<std::string> excluded = {std::string(channels::HEARTBEAT),
                                      std::string(channels::GRAPH_STATUS), "LCM_SELF_TEST"};
    for (const ProcessSpec& spec : graph_.processes) excluded.insert(spec.publishes.begin(), spec.publishes.end());
    player_ = std::make_unique<LogPlayer>(*options_.replay, excluded);
    std::string list;
    for (const std::string& c : excluded) list += " " + c;
    Log("replay of " + options_.replay->log_path + " leaves out the graph's own channels:" + list);
  }
}

Supervisor::~Supervisor() {
  // Nothing may outlive the launcher: kill whatever is left of every group.
  for (const auto& p : processes_) {
    if (p->alive()) kill(-p->pid, SIGKILL);
  }
  for (const auto& s : streams_) close(s->fd);
}

void Supervisor::OnHeartbeat(const lcm::ReceiveBuffer* rbuf, const std::string&) {
  const std::optional<heartbeat_t> hb = CheckedDecode<heartbeat_t>(rbuf->data, rbuf->data_size, nullptr);
  if (!hb) return;
  for (auto& p : processes_) {
    if (p->spec.name != hb->process_name || p->pid != hb->pid || !p->alive()) continue;
    const Clock::time_point now = Clock::now();
    p->last_heartbeat = now;
    p->health = hb->health;
    p->status = hb->status;
    if (p->state == ProcState::kStarting) {
      MarkReady(*p);
      Log(p->spec.name + ": first heartbeat " + std::to_string(std::lround(Seconds(now - p->started) * 1000)) +
          " ms after start (pid " + std::to_string(p->pid) + ")");
    }
  }
}

void Supervisor::OnWatchdog(pid_t pid, std::string_view text) {
  if (text != procs::kWatchdogMessage) return;
  for (auto& p : processes_) {
    if (p->pid == pid && p->alive() && p->state == ProcState::kRunning) p->last_heartbeat = Clock::now();
  }
}

bool Supervisor::AllReady() const {
  return std::all_of(processes_.begin(), processes_.end(),
                     [](const auto& p) { return p->state == ProcState::kRunning; });
}

bool Supervisor::AllDone() const {
  return std::all_of(processes_.begin(), processes_.end(),
                     [](const auto& p) { return p->state == ProcState::kExited && !p->alive(); });
}

void Supervisor::StartReady(Clock::time_point now) {
  for (auto& p : processes_) {
    if (p->state == ProcState::kBackoff && now >= p->restart_at) {
      Start(*p, now);
      continue;
    }
    if (p->state != ProcState::kWaiting) continue;
    const bool deps_ready = std::all_of(p->spec.depends_on.begin(), p->spec.depends_on.end(), [&](const std::string& d) {
      return std::any_of(processes_.begin(), processes_.end(),
                         [&](const auto& q) { return q->spec.name == d && q->ever_ready; });
    });
    if (deps_ready) Start(*p, now);
  }
}

void Supervisor::Start(Process& p, Clock::time_point now) {
  std::map<std::string, std::string> env = {{"TOPAY_PROCESS_NAME", p.spec.name},
                                            {"TOPAY_RUN_DIR", options_.run_dir}};
  if (!graph_.lcm_url.empty()) env["LCM_DEFAULT_URL"] = graph_.lcm_url;
  if (p.spec.realtime.mlockall) env["TOPAY_MLOCKALL"] = "1";
  if (watchdog_) env[procs::kNotifySocketEnv] = watchdog_->name();
  const SpawnedChild child = SpawnChild(p.spec, env, signals_.previous_mask());
  guardian_.Add(child.pid);
  p.pid = child.pid;
  p.started = now;
  p.last_heartbeat = now;
  p.killed_silent = false;
  p.term_sent = false;
  p.health = -1;
  p.status.clear();
  p.last_cpu_s = 0.0;
  p.last_cpu_at = now;
  p.state = ProcState::kStarting;
  streams_.push_back(std::make_unique<Stream>(Stream{child.output_fd, &p, ""}));
  p.log << "=== started pid " << p.pid << " (start " << p.restarts + 1 << ") ===" << std::endl;
  Log(p.spec.name + ": started pid " + std::to_string(p.pid));
}

void Supervisor::MarkReady(Process& p) {
  p.state = ProcState::kRunning;
  p.ever_ready = true;
  // The child applied its settings before exec; it is running now, so they can be checked.
  for (const std::string& warning : CheckRealtime(p.spec, p.pid)) Log(p.spec.name + ": warning: " + warning);
}

void Supervisor::Reap(Clock::time_point now) {
  int status = 0;
  pid_t pid;
  while ((pid = waitpid(-1, &status, WNOHANG)) > 0) {
    for (auto& p : processes_) {
      if (p->pid == pid) OnExit(*p, status, now);
    }
  }
}

void Supervisor::OnExit(Process& p, int status, Clock::time_point now) {
  kill(-p.pid, SIGKILL);  // anything the process left behind in its group
  guardian_.Remove(p.pid);
  p.pid = 0;
  const bool failed = p.killed_silent || !WIFEXITED(status) || WEXITSTATUS(status) != 0;
  const std::string what = p.killed_silent ? "killed after its heartbeat stopped" : DescribeExit(status);
  p.log << "=== " << what << " ===" << std::endl;
  if (stopping_) {
    p.state = ProcState::kExited;
    Log(p.spec.name + ": " + what);
    return;
  }
  if (Seconds(now - p.started) >= options_.stable_after_s) p.consecutive_failures = 0;
  const bool restart = p.spec.restart == RestartPolicy::kAlways ||
                       (p.spec.restart == RestartPolicy::kOnFailure && failed);
  const bool allowed = p.spec.max_restarts < 0 || p.restarts < p.spec.max_restarts;
  if (!restart || !allowed) {
    p.state = ProcState::kExited;
    Log(p.spec.name + ": " + what + (restart ? ", restart limit reached" : "") + ", not restarted");
    if (p.spec.ends_graph) {
      exit_code_ = p.killed_silent ? 128 + SIGKILL : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      BeginStop(p.spec.name + " ended the graph (exit code " + std::to_string(exit_code_) + ")", now);
    }
    return;
  }
  const double delay = std::min(p.spec.restart_delay_s * std::pow(2.0, p.consecutive_failures),
                                p.spec.restart_delay_max_s);
  ++p.consecutive_failures;
  ++p.restarts;
  p.state = ProcState::kBackoff;
  p.restart_at = now + FromSeconds(delay);
  char text[64];
  std::snprintf(text, sizeof(text), ", restart %d in %.2f s", p.restarts, delay);
  Log(p.spec.name + ": " + what + text);
}

void Supervisor::Supervise(Clock::time_point now) {
  for (auto& p : processes_) {
    if (p->alive() && !p->spec.heartbeat && p->state == ProcState::kStarting &&
        now - p->started >= FromSeconds(p->spec.ready_delay_s)) {
      MarkReady(*p);
    }
    if (!p->alive() || p->killed_silent || !p->spec.heartbeat) continue;
    double limit = 0.0;
    if (p->state == ProcState::kStarting) limit = p->spec.startup_timeout_s;
    else if (p->state == ProcState::kRunning) limit = graph_.heartbeat_period_s + p->spec.heartbeat_timeout_s;
    else continue;
    const double silent = Seconds(now - p->last_heartbeat);
    if (silent <= limit) continue;
    char text[160];
    std::snprintf(text, sizeof(text), ": no heartbeat for %.2f s (limit %.2f s; bus and watchdog), killing pid %d", silent, limit, p->pid);
    Log(p->spec.name + text);
    p->killed_silent = true;
    kill(-p->pid, SIGKILL);
    kill(p->pid, SIGCONT);  // a stopped process dies of SIGKILL anyway; harmless
  }
}

void Supervisor::ReadOutput(Stream& stream, bool hang_up) {
  char buffer[4096];
  ssize_t n;
  while ((n = read(stream.fd, buffer, sizeof(buffer))) > 0) stream.partial.append(buffer, n);
  std::size_t newline;
  while ((newline = stream.partial.find('\n')) != std::string::npos) {
    const std::string line = stream.partial.substr(0, newline);
    stream.partial.erase(0, newline + 1);
    console_.ChildLine(stream.process->spec.name, stream.process->index, line);
    stream.process->log << line << '\n';
  }
  stream.process->log.flush();  // whole lines reach <run>/<name>.log at once (tail -f, topay-missions)
  if (n == 0 || (hang_up && n < 0 && errno != EAGAIN)) {
    if (!stream.partial.empty()) {
      console_.ChildLine(stream.process->spec.name, stream.process->index, stream.partial);
      stream.process->log << stream.partial << '\n';
    }
    stream.process->log.flush();
    close(stream.fd);
    stream.fd = -1;
  }
}

void Supervisor::BeginStop(const std::string& reason, Clock::time_point now) {
  if (stopping_) return;
  stopping_ = true;
  stop_deadline_ = now + FromSeconds(graph_.grace_period_s);
  char grace[32];
  std::snprintf(grace, sizeof(grace), "%.1f", graph_.grace_period_s);
  Log("stopping the graph (" + reason + "): reverse dependency order, grace period " + grace + " s");
  for (auto& p : processes_) {
    if (!p->alive()) p->state = ProcState::kExited;
  }
}

void Supervisor::StopStep(Clock::time_point now) {
  if (now >= stop_deadline_ && !killed_all_) {
    killed_all_ = true;
    for (auto& p : processes_) {
      if (!p->alive()) continue;
      Log(p->spec.name + ": still running after the grace period, SIGKILL");
      kill(-p->pid, SIGKILL);
    }
    return;
  }
  // Reverse dependency order: SIGTERM to every process none of whose dependents is still alive
  // (dependents stop before what they depend on; unrelated processes stop together).
  for (auto& p : processes_) {
    if (!p->alive() || p->term_sent) continue;
    const bool dependents_alive = std::any_of(processes_.begin(), processes_.end(), [&](const auto& q) {
      return q->alive() && std::find(q->spec.depends_on.begin(), q->spec.depends_on.end(), p->spec.name) !=
                               q->spec.depends_on.end();
    });
    if (dependents_alive) continue;
    p->term_sent = true;
    p->state = ProcState::kStopping;
    kill(-p->pid, SIGTERM);
    kill(p->pid, SIGCONT);
  }
}

Clock::time_point Supervisor::NextWake(Clock::time_point now) const {
  Clock::time_point wake = std::min(next_status_, now + std::chrono::seconds(1));
  if (!options_.tty) wake = std::min(wake, next_plain_status_);
  if (stopping_) wake = std::min(wake, stop_deadline_);
  if (player_) wake = std::min(wake, player_->NextDue());
  if (replay_done_at_) wake = std::min(wake, *replay_done_at_);
  for (const auto& p : processes_) {
    if (p->state == ProcState::kBackoff) wake = std::min(wake, p->restart_at);
    if (p->state == ProcState::kStarting && !p->spec.heartbeat) {
      wake = std::min(wake, p->started + FromSeconds(p->spec.ready_delay_s));
    }
    if (p->alive() && p->spec.heartbeat && !p->killed_silent) {
      const double limit = p->state == ProcState::kStarting
                               ? p->spec.startup_timeout_s
                               : graph_.heartbeat_period_s + p->spec.heartbeat_timeout_s;
      wake = std::min(wake, p->last_heartbeat + FromSeconds(limit) + std::chrono::milliseconds(1));
    }
  }
  return wake;
}

void Supervisor::PollOnce(Clock::time_point now) {
  std::vector<pollfd> fds = {{signals_.fd(), POLLIN, 0}, {lcm_->getFileno(), POLLIN, 0}};
  for (const auto& s : streams_) fds.push_back({s->fd, POLLIN, 0});
  if (watchdog_) fds.push_back({watchdog_->fd(), POLLIN, 0});  // last: the streams' indices stay i + 2
  const auto wait = std::chrono::ceil<std::chrono::milliseconds>(NextWake(now) - Clock::now()).count();
  if (poll(fds.data(), fds.size(), static_cast<int>(std::clamp<long long>(wait, 0, 1000))) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    return;
  }
  if (fds[0].revents & POLLIN) {
    while (const std::optional<int> signal = signals_.Read()) {
      if (*signal == SIGCHLD) continue;  // reaped below, every iteration
      if (stopping_ && !killed_all_) {
        Log(std::string("second ") + strsignal(*signal) + ": SIGKILL now");
        stop_deadline_ = Clock::now();
      }
      BeginStop(strsignal(*signal), Clock::now());
    }
  }
  if (fds[1].revents & POLLIN) lcm_->handleTimeout(0);
  for (std::size_t i = 0; i < streams_.size(); ++i) {
    if (fds[i + 2].revents != 0) ReadOutput(*streams_[i], (fds[i + 2].revents & (POLLHUP | POLLERR)) != 0);
  }
  if (watchdog_ && (fds.back().revents & POLLIN)) {
    watchdog_->ReadAll([this](pid_t pid, std::string_view text) { OnWatchdog(pid, text); });
  }
  std::erase_if(streams_, [](const auto& s) { return s->fd < 0; });
}

void Supervisor::Tick(Clock::time_point now) {
  StartReady(now);
  Supervise(now);
  if (options_.duration_s && now - launched_ >= FromSeconds(*options_.duration_s)) BeginStop("duration reached", now);
  if (AllDone()) BeginStop("every process has exited", now);
  if (!player_ || stopping_) return;
  if (!player_->started() && AllReady()) {
    Log("every process is ready: replay starts");
    player_->Start(now);
  }
  if (player_->Pump(now, lcm_.get()) && !replay_done_at_) {
    Log("replay done: " + std::to_string(player_->published()) + " messages played, " +
        std::to_string(player_->skipped()) + " left out");
    replay_done_at_ = now + FromSeconds(options_.replay->linger_s);
  }
  if (replay_done_at_ && now >= *replay_done_at_) BeginStop("replay finished", now);
}

int Supervisor::Run() {
  launched_ = Clock::now();
  next_status_ = launched_;
  next_plain_status_ = launched_ + FromSeconds(options_.plain_status_period_s);
  Log("graph " + graph_.name + " (" + graph_.file + "), run folder " + options_.run_dir);
  try {
    while (true) {
      const Clock::time_point now = Clock::now();
      Reap(now);
      if (stopping_) {
        if (std::none_of(processes_.begin(), processes_.end(), [](const auto& p) { return p->alive(); })) break;
        StopStep(now);
      } else {
        Tick(now);
      }
      if (options_.tty && table_dirty_) console_.Table(FormatTable(graph_.name, Seconds(now - launched_), Rows(now)));
      table_dirty_ = false;
      if (now >= next_status_) {
        const bool plain = !options_.tty && now >= next_plain_status_;
        if (plain) next_plain_status_ = now + FromSeconds(options_.plain_status_period_s);
        ReportStatus(now, plain);
        next_status_ = now + FromSeconds(options_.status_period_s);
      }
      PollOnce(now);
    }
  } catch (const std::exception& e) {
    Log(std::string("error: ") + e.what());
    exit_code_ = 1;
  }
  for (const auto& s : streams_) ReadOutput(*s, true);
  streams_.clear();
  ReportStatus(Clock::now(), true);
  console_.ClearTable();
  Log("graph stopped");
  return exit_code_;
}

}  // namespace topay::launch
