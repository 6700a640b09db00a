#include "procs/sim/plant_checkpoint.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "sim/scenes/json_fields.h"

namespace topay::simproc {
namespace {

constexpr std::size_t kMaxCheckpointBytes = 1 << 16;

PlantCheckpoint Fields(const JsonFieldReader& reader, const nlohmann::json& j) {
  reader.RequireObject(j, "");
  reader.RequireKnownKeys(j, "", {"utime", "x_m", "y_m", "yaw_rad", "q_rad", "gripper"});
  PlantCheckpoint c;
  c.utime = static_cast<std::int64_t>(reader.Unsigned(reader.Member(j, "", "utime"), "utime"));
  c.x_m = reader.Number(reader.Member(j, "", "x_m"), "x_m");
  c.y_m = reader.Number(reader.Member(j, "", "y_m"), "y_m");
  c.yaw_rad = reader.Number(reader.Member(j, "", "yaw_rad"), "yaw_rad");
  const Eigen::VectorXd q = reader.NumberArray(reader.Member(j, "", "q_rad"), "q_rad", -1);
  c.q_rad.assign(q.data(), q.data() + q.size());
  c.gripper = reader.Number(reader.Member(j, "", "gripper"), "gripper");
  if (c.gripper < 0.0 || c.gripper > 1.0) reader.Fail("gripper", "must be in [0, 1]");
  return c;
}

}  // namespace

PlantCheckpoint CheckpointOf(const sim::PlantState& truth, std::int64_t utime) {
  PlantCheckpoint c;
  c.utime = utime;
  c.x_m = truth.state.x_m;
  c.y_m = truth.state.y_m;
  c.yaw_rad = truth.state.yaw_rad;
  c.q_rad.assign(truth.state.q_rad.data(), truth.state.q_rad.data() + truth.state.q_rad.size());
  c.gripper = truth.gripper;
  return c;
}

std::string FormatPlantCheckpoint(const PlantCheckpoint& c) {
  nlohmann::json j;
  j["utime"] = c.utime;
  j["x_m"] = c.x_m;
  j["y_m"] = c.y_m;
  j["yaw_rad"] = c.yaw_rad;
  j["q_rad"] = c.q_rad;
  j["gripper"] = c.gripper;
  return j.dump() + "\n";
}

PlantCheckpoint ParsePlantCheckpoint(const std::string& text, const std::string& source) {
  const JsonFieldReader reader(source);
  return Fields(reader, reader.ParseText(text));
}

std::string WritePlantCheckpoint(const std::string& path, const PlantCheckpoint& checkpoint) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << FormatPlantCheckpoint(checkpoint);
    out.flush();
    if (!out) return "cannot write " + temporary + ": " + std::strerror(errno);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    return "cannot rename " + temporary + " to " + path + ": " + std::strerror(errno);
  }
  return "";
}

std::optional<PlantCheckpoint> ReadPlantCheckpoint(const std::string& path) {
  std::error_code ignored;
  if (!std::filesystem::exists(path, ignored)) return std::nullopt;
  const JsonFieldReader reader(path);
  return Fields(reader, reader.ParseFile(kMaxCheckpointBytes, "plant checkpoint"));
}

void ResumeFrom(const PlantCheckpoint& checkpoint, sim::PlantOptions* plant) {
  plant->initial.x_m = checkpoint.x_m;
  plant->initial.y_m = checkpoint.y_m;
  plant->initial.yaw_rad = checkpoint.yaw_rad;
  plant->initial.q_rad = checkpoint.q_rad;
  plant->initial.gripper = checkpoint.gripper;
}

}  // namespace topay::simproc
