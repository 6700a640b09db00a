// Supervisor's status: CPU and memory of the children (/proc), the rows, and their outputs:
// GRAPH_STATUS on LCM, <run>/status.json and the terminal table.

#include <filesystem>
#include <fstream>

#include "procs/launch/proc_stats.h"
#include "procs/launch/supervisor.h"
#include "procs/launch/supervisor_process.h"
#include "procs/runtime/process_loop.h"
#include "topay/graph_status_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::launch {
namespace {

double Seconds(Supervisor::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

void Supervisor::SampleResources(Clock::time_point now) {
  for (auto& p : processes_) {
    if (!p->alive()) {
      p->cpu_percent = 0.0;
      p->rss_kB = 0;
      continue;
    }
    if (const std::optional<ProcSample> sample = ReadProcSample(p->pid)) {
      const double dt = Seconds(now - p->last_cpu_at);
      if (dt > 0.05 && p->last_cpu_s > 0.0) p->cpu_percent = 100.0 * (sample->cpu_time_s - p->last_cpu_s) / dt;
      p->last_cpu_s = sample->cpu_time_s;
      p->last_cpu_at = now;
      p->rss_kB = sample->rss_kB;
    }
  }
}

std::vector<ProcessStatusRow> Supervisor::Rows(Clock::time_point now) const {
  std::vector<ProcessStatusRow> rows;
  for (const auto& p : processes_) {
    ProcessStatusRow row;
    row.name = p->spec.name;
    row.group = p->spec.group;
    row.state = static_cast<std::int8_t>(p->state);
    row.state_name = ToString(p->state);
    row.pid = p->pid;
    row.restarts = p->restarts;
    row.cpu_percent = p->cpu_percent;
    row.rss_kB = p->rss_kB;
    const bool beating = p->alive() && p->spec.heartbeat && p->health >= 0;
    row.heartbeat_age_s = beating ? Seconds(now - p->last_heartbeat) : -1.0;
    row.health = p->health;
    row.status = p->status;
    rows.push_back(row);
  }
  return rows;
}

void Supervisor::ReportStatus(Clock::time_point now, bool plain) {
  SampleResources(now);
  const std::vector<ProcessStatusRow> rows = Rows(now);
  const double uptime = Seconds(now - launched_);
  const graph_status_t msg = ToGraphStatus(graph_.name, options_.run_dir, procs::NowUtime(), rows);
  lcm_->publish(std::string(channels::GRAPH_STATUS), &msg);
  const std::string json_path = options_.run_dir + "/status.json";
  std::ofstream(json_path + ".tmp") << ToJson(graph_.name, options_.run_dir, uptime, rows);
  std::filesystem::rename(json_path + ".tmp", json_path);
  if (options_.tty || plain) console_.Table(FormatTable(graph_.name, uptime, rows));
}

}  // namespace topay::launch
