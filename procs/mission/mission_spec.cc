#include "procs/mission/mission_spec.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::mission {
namespace {

constexpr double kUnitQuaternionTolerance = 1e-3;

void RequireFinite(const std::vector<double>& values, const YamlSection& s, const char* key) {
  for (double v : values) {
    if (!std::isfinite(v)) throw ConfigError(s.source(), s.FieldPath(key), "expected finite numbers");
  }
}

double ReadNonNegative(YamlSection* s, const char* key, double value) {
  s->Read(key, &value);
  if (!std::isfinite(value) || value < 0.0) {
    throw ConfigError(s->source(), s->FieldPath(key), fmt::format("must be finite and >= 0, got {}", value));
  }
  return value;
}

std::optional<double> ReadOptionalPositive(YamlSection* s, const char* key) {
  double value = std::nan("");
  s->Read(key, &value);
  if (std::isnan(value)) return std::nullopt;
  if (!std::isfinite(value) || value <= 0.0) {
    throw ConfigError(s->source(), s->FieldPath(key), fmt::format("must be finite and > 0, got {}", value));
  }
  return value;
}

std::vector<double> ReadVector(YamlSection* s, const char* key, std::size_t size, bool required) {
  std::vector<double> values;
  s->Read(key, &values);
  if (values.empty() && !required) return values;
  if (values.empty()) throw ConfigError(s->source(), s->FieldPath(key), "missing (required)");
  if (values.size() != size) {
    throw ConfigError(s->source(), s->FieldPath(key),
                      fmt::format("expected {} numbers, got {}", size, values.size()));
  }
  RequireFinite(values, *s, key);
  return values;
}

Eigen::Matrix3d ReadOrientation(YamlSection* s) {
  const std::vector<double> rpy = ReadVector(s, "rpy_rad", 3, false);
  const std::vector<double> q = ReadVector(s, "quat_wxyz", 4, false);
  if (rpy.empty() == q.empty()) {
    throw ConfigError(s->source(), s->FieldPath("rpy_rad"),
                      rpy.empty() ? "missing: give rpy_rad [roll, pitch, yaw] or quat_wxyz [w, x, y, z]"
                                  : "give either rpy_rad or quat_wxyz, not both");
  }
  if (!rpy.empty()) {
    return (Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
  }
  Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
  const double norm = quat.norm();
  if (std::abs(1.0 - norm) > kUnitQuaternionTolerance) {
    throw ConfigError(s->source(), s->FieldPath("quat_wxyz"),
                      fmt::format("not a unit quaternion (norm {:.6f})", norm));
  }
  return quat.normalized().toRotationMatrix();
}

std::optional<WholeBodyState> ReadHint(YamlSection s) {
  if (!s.present()) {
    s.Finish();
    return std::nullopt;
  }
  WholeBodyState hint;
  const char* keys[] = {"x_m", "y_m", "yaw_rad"};
  double* values[] = {&hint.x_m, &hint.y_m, &hint.yaw_rad};
  for (int k = 0; k < 3; ++k) {
    *values[k] = std::nan("");
    s.Read(keys[k], values[k]);
    if (std::isnan(*values[k])) throw ConfigError(s.source(), s.FieldPath(keys[k]), "missing (required)");
    if (!std::isfinite(*values[k])) throw ConfigError(s.source(), s.FieldPath(keys[k]), "must be finite");
  }
  std::vector<double> q;
  s.Read("q_rad", &q);
  if (q.empty()) throw ConfigError(s.source(), s.FieldPath("q_rad"), "missing (required)");
  RequireFinite(q, s, "q_rad");
  hint.q_rad = Eigen::Map<const Eigen::VectorXd>(q.data(), static_cast<Eigen::Index>(q.size()));
  s.Finish();
  return hint;
}

std::optional<ArrivalTolerance> ReadTolerance(YamlSection s) {
  if (!s.present()) {
    s.Finish();
    return std::nullopt;
  }
  ArrivalTolerance t;
  t.position_m = ReadNonNegative(&s, "position_m", t.position_m);
  t.orientation_rad = ReadNonNegative(&s, "orientation_rad", t.orientation_rad);
  s.Finish();
  return t;
}

void ReadGoto(YamlSection* s, MissionStep* step) {
  const std::vector<double> p = ReadVector(s, "position_m", 3, true);
  step->X_WE.linear() = ReadOrientation(s);
  step->X_WE.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  step->hint = ReadHint(s->Section("hint"));
}

void ReadGripper(YamlSection* s, MissionStep* step) {
  std::string action;
  s->Read("action", &action);
  double position = std::nan("");
  s->Read("position", &position);
  if (action.empty() == std::isnan(position)) {
    throw ConfigError(s->source(), s->FieldPath("action"),
                      action.empty() ? "missing: give action (open | close) or position (0..1)"
                                     : "give either action or position, not both");
  }
  if (action == "open") {
    step->gripper_position = 0.0;
  } else if (action == "close") {
    step->gripper_position = 1.0;
  } else if (!action.empty()) {
    throw ConfigError(s->source(), s->FieldPath("action"), "expected open or close, got '" + action + "'");
  } else if (!(position >= 0.0 && position <= 1.0)) {
    throw ConfigError(s->source(), s->FieldPath("position"), fmt::format("must be in 0..1, got {}", position));
  } else {
    step->gripper_position = position;
  }
  double settle_s = std::nan("");
  s->Read("settle_s", &settle_s);
  if (!std::isnan(settle_s)) step->settle_s = ReadNonNegative(s, "settle_s", settle_s);
}

MissionStep ReadStep(const YAML::Node& node, const std::string& source, std::size_t index) {
  YamlSection s(node, source, fmt::format("steps[{}]", index));
  if (!s.present()) throw ConfigError(source, fmt::format("steps[{}]", index), "expected a map with a type");
  MissionStep step;
  std::string type;
  s.Read("type", &type);
  s.Read("name", &step.label);
  if (type == "goto") {
    step.type = StepType::kGoto;
    ReadGoto(&s, &step);
  } else if (type == "home") {
    step.type = StepType::kHome;
  } else if (type == "gripper") {
    step.type = StepType::kGripper;
    ReadGripper(&s, &step);
  } else if (type == "wait") {
    step.type = StepType::kWait;
    double duration_s = std::nan("");
    s.Read("duration_s", &duration_s);
    if (std::isnan(duration_s)) throw ConfigError(source, s.FieldPath("duration_s"), "missing (required)");
    step.duration_s = ReadNonNegative(&s, "duration_s", duration_s);
  } else if (type.empty()) {
    throw ConfigError(source, s.FieldPath("type"), "missing: goto, gripper, wait or home");
  } else {
    throw ConfigError(source, s.FieldPath("type"), "unknown step type '" + type + "' (goto, gripper, wait, home)");
  }
  if (step.type == StepType::kGoto || step.type == StepType::kHome) {
    step.tolerance = ReadTolerance(s.Section("tolerance"));
    step.timeout_s = ReadOptionalPositive(&s, "timeout_s");
  }
  s.Finish();
  return step;
}

}  // namespace

const char* ToString(StepType type) {
  switch (type) {
    case StepType::kGoto: return "goto";
    case StepType::kGripper: return "gripper";
    case StepType::kWait: return "wait";
    case StepType::kHome: return "home";
  }
  return "?";
}

std::string MissionStep::Describe() const {
  std::string text = ToString(type);
  if (type == StepType::kGripper) {
    text += gripper_position == 0.0   ? " open"
            : gripper_position == 1.0 ? " close"
                                      : fmt::format(" {:.2f}", gripper_position);
  } else if (type == StepType::kWait) {
    text += fmt::format(" {:.1f} s", duration_s);
  }
  if (!label.empty()) text += " " + label;
  return text;
}

Mission ParseMission(const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source, "", std::string("cannot read YAML: ") + e.what());
  }
  Mission mission;
  mission.source = source;
  YamlSection top(root, source);
  top.Read("name", &mission.name);
  if (mission.name.empty()) throw ConfigError(source, "name", "missing (required)");
  const YAML::Node steps = top.Raw("steps");
  if (!steps.IsDefined() || steps.IsNull()) throw ConfigError(source, "steps", "missing (required)");
  if (!steps.IsSequence() || steps.size() == 0) throw ConfigError(source, "steps", "expected a non-empty list of steps");
  for (std::size_t i = 0; i < steps.size(); ++i) mission.steps.push_back(ReadStep(steps[i], source, i));
  top.Finish();
  return mission;
}

Mission LoadMission(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw ConfigError(path, "", "cannot open the file");
  std::stringstream text;
  text << file.rdbuf();
  return ParseMission(text.str(), path);
}

void CheckMissionForRobot(const Mission& mission, int num_joints) {
  for (std::size_t i = 0; i < mission.steps.size(); ++i) {
    const MissionStep& step = mission.steps[i];
    if (step.hint && step.hint->num_joints() != num_joints) {
      throw ConfigError(mission.source, fmt::format("steps[{}].hint.q_rad", i),
                        fmt::format("expected {} joint angles (the robot's), got {}", num_joints,
                                    step.hint->num_joints()));
    }
  }
}

}  // namespace topay::mission
