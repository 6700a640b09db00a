// Writes the seed corpora of the LCM fuzz targets (tests/fuzz/corpus/<target>/) from a real
// graph log (e.g. tests/web/record_demo_log.sh's 30 s of the demo) and from the catalogue's
// sample messages (tests/lcm/sample_messages.h) for types the log lacks. Each subscriber
// target gets windows of the log on its channels in the record format of subscriber_fuzz.h
// (a tick wherever the receive time moved on by 5 ms or more); lcm_decode one message of every
// type; trajectory_message the log's trajectories with sample times. A scan (POINT_CLOUD, ~240 KB)
// is too large for a seed record and is thinned to every k-th point (at most kMaxCloudPoints).
// Regenerate with
// tools/fuzz/write_seeds.sh.
//
//   write_lcm_fuzz_seeds LOG CORPUS_ROOT
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "procs/msgs/type_registry.h"
#include "topay/point_cloud_t.hpp"
#include "tests/lcm/sample_messages.h"
#include "topay_msgs/channels.h"

namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;
namespace ch = topay::channels;

struct Event {
  std::int64_t utime = 0;
  std::string channel;
  Bytes data;
};

struct SubscriberTarget {
  std::string name;
  std::vector<std::string_view> channels;  // record channel index = position
};

constexpr std::size_t kMaxMessageBytes = 60000;  // fits the u16 length
constexpr std::size_t kMaxSeedBytes = 48 * 1024;
constexpr int kMaxRecords = 48;
constexpr int kWindows = 10;

void PutU16(Bytes* out, unsigned value) {
  out->push_back(static_cast<std::uint8_t>(value & 0xff));
  out->push_back(static_cast<std::uint8_t>((value >> 8) & 0xff));
}

void WriteFile(const fs::path& path, const Bytes& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
}

constexpr int kMaxCloudPoints = 500;  // 6 KB of points: several scans fit in a seed

// A scan too large for a record keeps every k-th point, k the smallest that leaves at most
// kMaxCloudPoints (re-encoded; the pose and time as they were).
void ThinPointCloud(Bytes* data) {
  topay::point_cloud_t cloud;
  if (cloud.decode(data->data(), 0, static_cast<int>(data->size())) < 0) return;
  const int points = cloud.num_coords / 3;
  const int stride = (points + kMaxCloudPoints - 1) / kMaxCloudPoints;
  if (stride <= 1) return;
  std::vector<float> kept;
  for (int i = 0; i < points; i += stride) kept.insert(kept.end(), {cloud.p_SP[3 * i], cloud.p_SP[3 * i + 1], cloud.p_SP[3 * i + 2]});
  cloud.p_SP = std::move(kept);
  cloud.num_coords = static_cast<std::int32_t>(cloud.p_SP.size());
  data->resize(static_cast<std::size_t>(cloud.getEncodedSize()));
  cloud.encode(data->data(), 0, static_cast<int>(data->size()));
}

std::vector<Event> ReadLog(const std::string& path) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error("cannot read the LCM log " + path);
  std::vector<Event> events;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    const auto* p = static_cast<const std::uint8_t*>(e->data);
    events.push_back({e->timestamp, e->channel, Bytes(p, p + e->datalen)});
    if (events.back().channel == ch::POINT_CLOUD) ThinPointCloud(&events.back().data);
  }
  return events;
}

// The target's records, in log order, as (first byte offset, bytes) runs to cut windows from.
std::vector<Bytes> TargetRecords(const SubscriberTarget& target, const std::vector<Event>& events) {
  std::vector<Bytes> records;
  std::map<std::string_view, int> seen;  // a channel listed twice alternates between its indices
  std::int64_t last_utime = -1;
  const int tick = static_cast<int>(target.channels.size());
  for (const Event& e : events) {
    std::vector<int> indices;
    for (int i = 0; i < tick; ++i) {
      if (target.channels[static_cast<std::size_t>(i)] == e.channel) indices.push_back(i);
    }
    if (indices.empty() || e.data.size() > kMaxMessageBytes) continue;
    if (last_utime >= 0 && e.utime - last_utime >= 5000) {
      Bytes t{static_cast<std::uint8_t>(tick)};
      PutU16(&t, static_cast<unsigned>(std::min<std::int64_t>((e.utime - last_utime) / 1000, 65535)));
      records.push_back(std::move(t));
    }
    last_utime = e.utime;
    const int index = indices[static_cast<std::size_t>(seen[e.channel]++) % indices.size()];
    Bytes r{static_cast<std::uint8_t>(index)};
    PutU16(&r, static_cast<unsigned>(e.data.size()));
    r.insert(r.end(), e.data.begin(), e.data.end());
    records.push_back(std::move(r));
  }
  return records;
}

int WriteSubscriberSeeds(const SubscriberTarget& target, const std::vector<Event>& events, const fs::path& root) {
  const std::vector<Bytes> records = TargetRecords(target, events);
  int written = 0;
  for (int w = 0; w < kWindows && !records.empty(); ++w) {
    Bytes seed;
    int n = 0;
    for (std::size_t i = records.size() * static_cast<std::size_t>(w) / kWindows;
         i < records.size() && n < kMaxRecords && seed.size() + records[i].size() <= kMaxSeedBytes; ++i, ++n) {
      seed.insert(seed.end(), records[i].begin(), records[i].end());
    }
    if (seed.empty()) continue;
    WriteFile(root / target.name / ("log-" + std::to_string(w)), seed);
    ++written;
  }
  return written;
}

// One message of every type: the log's first of each channel, and every catalogue sample.
int WriteDecodeSeeds(const std::vector<Event>& events, const fs::path& root) {
  int written = 0;
  auto write = [&](int type_index, const Bytes& data, const std::string& name) {
    Bytes seed{static_cast<std::uint8_t>(type_index)};
    seed.insert(seed.end(), data.begin(), data.end());
    WriteFile(root / "lcm_decode" / name, seed);
    ++written;
  };
  // The type order of lcm_decode_fuzz.cc's AllTypes (alphabetical, as lcmtypes/).
  const std::vector<std::string> type_names = {
      "base_pose_t", "base_velocity_t", "control_command_t", "drive_command_t", "drive_status_t", "goal_t",
      "graph_status_t", "gripper_command_t", "heartbeat_t", "joint_state_t", "map_update_t", "mission_status_t",
      "motorsim_fault_t", "planner_paths_t", "planner_status_t", "point_cloud_t", "poly_trajectory_t",
      "robot_state_t", "sim_contact_t", "sim_event_t", "sim_status_t", "tracker_status_t", "whole_body_state_t"};
  auto index_of = [&](const std::string& type) {
    for (std::size_t i = 0; i < type_names.size(); ++i) {
      if (type_names[i] == type) return static_cast<int>(i);
    }
    return -1;
  };
  std::map<std::string, bool> done;
  for (const Event& e : events) {
    if (done[e.channel] || e.data.size() > kMaxSeedBytes) continue;
    const auto info = topay::msgs::IdentifyMessage(e.data.data(), e.data.size());
    if (!info) continue;
    done[e.channel] = true;
    write(index_of(info->name), e.data, "log-" + e.channel);
  }
  topay::test::Catalogue::ForEach([&](auto* type) {
    using Msg = std::remove_pointer_t<decltype(type)>;
    const Msg msg = topay::test::MessageSample<Msg>::Make();
    Bytes data(static_cast<std::size_t>(msg.getEncodedSize()));
    msg.encode(data.data(), 0, static_cast<int>(data.size()));
    write(index_of(Msg::getTypeName()), data, std::string("sample-") + Msg::getTypeName());
  });
  return written;
}

int WriteTrajectorySeeds(const std::vector<Event>& events, const fs::path& root) {
  int written = 0;
  for (const Event& e : events) {
    if (e.channel != ch::TRAJECTORY || e.data.size() > kMaxMessageBytes || written >= 8) continue;
    Bytes seed{0};
    PutU16(&seed, static_cast<unsigned>(e.data.size()));
    seed.insert(seed.end(), e.data.begin(), e.data.end());
    for (unsigned k = 0; k <= 16; ++k) PutU16(&seed, 65535 * k / 16);
    WriteFile(root / "trajectory_message" / ("log-" + std::to_string(written++)), seed);
  }
  return written;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: write_lcm_fuzz_seeds LOG CORPUS_ROOT\n";
    return 2;
  }
  try {
    const std::vector<Event> events = ReadLog(argv[1]);
    const fs::path root = argv[2];
    std::vector<std::string_view> all(ch::kAll.begin(), ch::kAll.end());
    const std::vector<SubscriberTarget> targets = {
        {"estimator_inputs", {ch::BASE_POSE, ch::BASE_VELOCITY, ch::JOINT_STATE, ch::GRIPPER_STATE}},
        {"tracker_inputs",
         {ch::TRAJECTORY, ch::ROBOT_STATE, ch::GRIPPER_COMMAND, ch::DRIVE_STATUS, ch::HEARTBEAT, ch::POINT_CLOUD}},
        {"mission_inputs", {ch::ROBOT_STATE, ch::PLANNER_STATUS, ch::TRACKER_STATUS}},
        {"director_inputs", {ch::MISSION_STATUS, ch::TRAJECTORY, ch::ROBOT_STATE}},
        {"planner_intake", {ch::GOAL, ch::ROBOT_STATE, ch::MAP_UPDATE, ch::TRACKER_STATUS}},
        {"viz_inputs", all},
        {"map_update", {ch::MAP_UPDATE}},
        {"sim_inputs", {ch::CONTROL_COMMAND, ch::ACTUATOR_COMMAND, ch::GRIPPER_COMMAND, ch::TRAJECTORY, ch::SIM_EVENT,
                        ch::CONTROL_COMMAND}},
        {"mapper_inputs", {ch::POINT_CLOUD, ch::ROBOT_STATE}},
        {"motorsim_inputs", {ch::SIM_PLANT_STATE, ch::MOTORSIM_FAULT}},
    };
    for (const SubscriberTarget& target : targets) {
      std::cout << target.name << ": " << WriteSubscriberSeeds(target, events, root) << " seed(s)\n";
    }
    std::cout << "lcm_decode: " << WriteDecodeSeeds(events, root) << " seed(s)\n";
    std::cout << "trajectory_message: " << WriteTrajectorySeeds(events, root) << " seed(s)\n";
  } catch (const std::exception& e) {
    std::cerr << "write_lcm_fuzz_seeds: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
