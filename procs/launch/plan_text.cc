#include "procs/launch/plan_text.h"

#include <sstream>

namespace topay::launch {
namespace {

std::string Join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

void DescribeRealtime(const RealtimeSettings& rt, std::ostringstream& out) {
  if (!rt.nice && !rt.fifo_priority && rt.cpus.empty() && !rt.mlockall) return;
  out << "    realtime:";
  if (rt.nice) out << " nice " << *rt.nice;
  if (rt.fifo_priority) out << ", SCHED_FIFO " << *rt.fifo_priority;
  if (!rt.cpus.empty()) {
    out << ", cpus";
    for (const int cpu : rt.cpus) out << " " << cpu;
  }
  if (rt.mlockall) out << ", mlockall";
  out << "\n";
}

}  // namespace

std::string DescribePlan(const GraphSpec& graph, bool isolated, const std::string& run_dir) {
  std::ostringstream out;
  out << "graph " << graph.name << " (" << graph.file << ")\n"
      << "  network: " << (isolated ? "private network namespace (isolated)" : "the machine's own (not isolated)")
      << "\n  LCM URL: " << (graph.lcm_url.empty() ? "(inherited LCM_DEFAULT_URL or LCM's default)" : graph.lcm_url)
      << "\n  run folder: " << run_dir << "\n  stop: SIGTERM in reverse order, SIGKILL after "
      << graph.grace_period_s << " s\n  start order:\n";
  int i = 1;
  for (const ProcessSpec& p : graph.processes) {
    out << "  " << i++ << ". " << p.name << (p.group.empty() ? "" : " [" + p.group + "]") << "\n"
        << "    command: " << p.command << (p.args.empty() ? "" : " " + Join(p.args, " ")) << "\n";
    if (!p.working_dir.empty()) out << "    working_dir: " << p.working_dir << "\n";
    for (const auto& [key, value] : p.env) out << "    env: " << key << "=" << value << "\n";
    if (!p.depends_on.empty()) out << "    after: " << Join(p.depends_on, ", ") << " (first heartbeat)\n";
    out << "    restart: " << ToString(p.restart);
    if (p.restart != RestartPolicy::kNever) {
      out << ", backoff " << p.restart_delay_s << " s doubling to " << p.restart_delay_max_s << " s"
          << (p.max_restarts < 0 ? ", unlimited" : ", at most " + std::to_string(p.max_restarts));
    }
    out << "\n    heartbeat: ";
    if (p.heartbeat) {
      out << "silent after " << graph.heartbeat_period_s + p.heartbeat_timeout_s << " s without one (period "
          << graph.heartbeat_period_s << " s + timeout " << p.heartbeat_timeout_s << " s), first within "
          << p.startup_timeout_s << " s\n";
    }
    else out << "not monitored (ready " << p.ready_delay_s << " s after its start)\n";
    if (!p.publishes.empty()) out << "    publishes: " << Join(p.publishes, ", ") << "\n";
    DescribeRealtime(p.realtime, out);
    out << "    log: " << run_dir << "/" << p.name << ".log\n";
  }
  return out.str();
}

}  // namespace topay::launch
