#include "fault_campaign.h"

#include <unistd.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "fault_injector.h"
#include "fault_queue.h"
#include "graph_monitor.h"
#include "procs/launch/graph_spec.h"
#include "sim/scenes/scene_json.h"
#include "tools/topay_missions/child_command.h"

namespace topay::tools {
namespace {

namespace fs = std::filesystem;

constexpr double kPollPeriodS = 0.001;  // the loop's period (the goal flood is 1 kHz)
constexpr double kLargestObstacleSideM = 3.0;  // boxes with a longer side are walls: no goal in them

// The UDP port of an "udpm://group:port?..." URL (LCM's default 7667 if none is given).
int LcmPort(const std::string& url) {
  const std::size_t colon = url.rfind(':');
  if (colon == std::string::npos || colon < url.find("//")) return 7667;
  const std::size_t end = url.find('?', colon);
  return std::stoi(url.substr(colon + 1, end == std::string::npos ? std::string::npos : end - colon - 1));
}

// The room of the mission: its extent (random goals) and the centres of its obstacles.
void ReadRoom(const std::string& path, FaultInjectorOptions* options) {
  const Scene scene = ReadSceneJson(path);
  options->room_min_m = scene.bounds_W_m.min();
  options->room_max_m = scene.bounds_W_m.max();
  options->box_centers_m.clear();
  for (const OrientedBox& box : scene.boxes) {
    if (box.size_m.x() < kLargestObstacleSideM && box.size_m.y() < kLargestObstacleSideM) {
      options->box_centers_m.push_back(box.center_W_m);
    }
  }
}

bool WriteScenario(const FaultCampaignOptions& options, CampaignMission* mission) {
  ChildCommandOptions child;
  child.output_path = mission->run_dir + "/scenario.out";
  const ChildCommandResult r = RunChildCommand(
      {options.bin_dir + "/topay-scenario", "--seed", std::to_string(mission->seed), "--out", mission->run_dir}, child);
  if (r.exit_code == 0) return true;
  mission->note = r.error.empty() ? fmt::format("topay-scenario exited with code {} (see {})", r.exit_code,
                                                child.output_path)
                                  : r.error;
  return false;
}

void PrintEpisode(const EpisodeResult& e, std::ostream& progress) {
  progress << fmt::format("  {:<24} {}{}\n", e.fault,
                          e.injected ? (e.recovered ? fmt::format("recovered in {:.1f} s", e.recover_s)
                                                    : std::string("NOT recovered"))
                                     : "not injected: " + e.notes,
                          e.injected ? " | " + e.reaction + (e.contacts > 0 ? fmt::format(" | {} CONTACTS", e.contacts) : "")
                                     : "")
           << std::flush;
}

// The faults of one mission, one episode after another, while the graph runs.
class MissionEpisodes {
 public:
  MissionEpisodes(const FaultCampaignOptions& options, FaultQueue* queue, GraphMonitor* monitor,
                  std::uint64_t room_seed, FaultInjectorOptions injector_options, CampaignResult* result,
                  std::ostream& progress)
      : options_(options), queue_(queue), monitor_(monitor), injector_(injector_options, monitor),
        seed_(room_seed), result_(result), progress_(progress) {}

  void Poll() {
    const GraphView view = monitor_->View();
    if (!episode_) {
      const FaultSpec* next = queue_->Next(episodes_, options_.episodes_per_mission);
      if (next == nullptr) return;
      episode_ = std::make_unique<FaultEpisode>(*next, seed_, &injector_, getpid(), options_.episode);
    }
    if (episode_->Tick(view)) Book();
  }

  void GraphEnded(int exit_code) {
    if (!episode_) return;
    episode_->GraphEnded(monitor_->View(), exit_code);
    Book();
  }

 private:
  void Book() {
    const EpisodeResult& r = episode_->Result();
    if (r.injected) ++episodes_;
    if (queue_->Record(r)) {
      result_->episodes.push_back(r);
      PrintEpisode(r, progress_);
    }
    episode_.reset();
  }

  const FaultCampaignOptions& options_;
  FaultQueue* queue_;
  GraphMonitor* monitor_;
  FaultInjector injector_;
  std::uint64_t seed_;
  CampaignResult* result_;
  std::ostream& progress_;
  std::unique_ptr<FaultEpisode> episode_;
  int episodes_ = 0;
};

}  // namespace

CampaignResult RunFaultCampaign(const FaultCampaignOptions& options, std::ostream& progress,
                                const std::function<bool()>& stop_requested) {
  const launch::GraphSpec graph = launch::LoadGraph(options.graph_file);
  GraphMonitor monitor(graph.lcm_url);
  FaultQueue queue(options.faults, options.runs);
  CampaignResult result;
  result.episodes = options.earlier;
  for (const EpisodeResult& e : options.earlier) queue.Count(e);
  const int max_missions = options.max_missions > 0
                               ? options.max_missions
                               : 2 * static_cast<int>(options.faults.size()) * options.runs;
  for (int k = 0; k < max_missions && !queue.Done() && !result.interrupted; ++k) {
    CampaignMission mission;
    mission.index = options.first_mission + k;
    mission.seed = options.seeds[static_cast<std::size_t>(mission.index - 1) % options.seeds.size()];
    mission.run_dir = fs::absolute(fs::path(options.out_dir) / fmt::format("mission-{}", mission.index)).string();
    fs::remove_all(mission.run_dir);
    fs::create_directories(mission.run_dir);
    progress << fmt::format("== mission {} (room seed {}, {})\n", mission.index, mission.seed, mission.run_dir)
             << std::flush;
    if (!WriteScenario(options, &mission)) {
      progress << "  " << mission.note << "\n";
      result.missions.push_back(mission);
      continue;
    }
    FaultInjectorOptions injector;
    injector.lcm_url = graph.lcm_url;
    injector.lcm_port = LcmPort(graph.lcm_url);
    injector.work_dir = mission.run_dir;
    injector.graph_ancestor = getpid();
    injector.seed = mission.seed * 1000 + static_cast<std::uint64_t>(mission.index - 1);
    ReadRoom(mission.run_dir + "/room.json", &injector);
    monitor.Reset();
    MissionEpisodes episodes(options, &queue, &monitor, mission.seed, injector, &result, progress);
    ChildCommandOptions child;
    child.output_path = mission.run_dir + "/launcher.out";
    child.timeout_s = options.mission_timeout_s;
    child.poll_period_s = kPollPeriodS;
    child.on_poll = [&] { episodes.Poll(); };
    child.stop_requested = [&] {
      result.interrupted = result.interrupted || stop_requested();
      return result.interrupted || queue.Done();
    };
    const ChildCommandResult r =
        RunChildCommand({options.bin_dir + "/topay-launch", options.graph_file, "--run-dir", mission.run_dir,
                         "--plain", "--no-isolated", "--without", "viewer"},
                        child);
    mission.launcher_exit_code = r.exit_code;
    mission.note = r.error;
    episodes.GraphEnded(r.exit_code);
    result.missions.push_back(mission);
  }
  return result;
}

}  // namespace topay::tools
