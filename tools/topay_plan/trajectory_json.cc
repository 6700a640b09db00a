#include "tools/topay_plan/trajectory_json.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "sim/scenes/json_fields.h"

namespace topay::plan {
namespace {

using Json = nlohmann::ordered_json;
constexpr const char* kFormat = "topay-trajectory";
constexpr int kVersion = 1;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- Writing -------------------------------------------------------------------------------

Json NumberOrNull(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json VectorJson(const Eigen::Ref<const Eigen::VectorXd>& v) {
  Json json = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) json.push_back(v(i));
  return json;
}

Json StateJson(const WholeBodyState& state) {
  Json json;
  json["x_m"] = state.x_m;
  json["y_m"] = state.y_m;
  json["yaw_rad"] = state.yaw_rad;
  json["q_rad"] = VectorJson(state.q_rad);
  return json;
}

Json PoseJson(const Eigen::Isometry3d& X_WE) {
  const Eigen::Quaterniond q(X_WE.rotation());
  Json json;
  json["position_m"] = VectorJson(X_WE.translation());
  json["quaternion_wxyz"] = Json::array({q.w(), q.x(), q.y(), q.z()});
  return json;
}

Json ValidationJson(const TrajectoryValidationFigures& f) {
  Json json;
  json["ok"] = f.ok;
  json["duration_s"] = f.duration_s;
  json["num_samples"] = f.num_samples;
  json["min_clearance_m"] = NumberOrNull(f.min_clearance_m);
  json["min_clearance_part"] = f.min_clearance_part;
  json["min_self_clearance_m"] = NumberOrNull(f.min_self_clearance_m);
  json["worst_limit_ratio"] = f.worst_limit_ratio;
  json["worst_limit"] = f.worst_limit;
  json["worst_limit_t_s"] = NumberOrNull(f.worst_limit_t_s);
  json["end_position_error_m"] = NumberOrNull(f.end_position_error_m);
  json["end_orientation_error_rad"] = NumberOrNull(f.end_orientation_error_rad);
  return json;
}

Json MetadataJson(const TrajectoryMetadata& m) {
  Json json;
  json["scene"] = {{"kind", m.scene_kind},
                   {"seed", m.scene_seed},
                   {"file", m.scene_file},
                   {"num_boxes", m.num_boxes}};
  json["task"] = {{"source", m.task_source},     {"file", m.task_file},
                  {"range", m.task_range},       {"seed", m.task_seed},
                  {"start", StateJson(m.start)}, {"goal_end_effector", PoseJson(m.X_WE_goal)}};
  const BaseLimits& b = m.base_limits;
  json["base_limits"] = {{"source", m.base_limits_source},
                         {"v_max_mps", b.v_max_mps},
                         {"a_max_mps2", b.a_max_mps2},
                         {"omega_max_radps", b.omega_max_radps},
                         {"beta_max_radps2", b.beta_max_radps2}};
  const PlanTimings& t = m.timings;
  json["plan"] = {{"status", m.status},
                  {"failure_reason", m.failure_reason},
                  {"timings_ms",
                   {{"map_build", m.map_build_ms},
                    {"search", t.search_ms},
                    {"sampling", t.sampling_ms},
                    {"front_end", t.front_end_ms},
                    {"optimization", t.optimization_ms},
                    {"wait", t.wait_ms},
                    {"total", t.total_ms}}}};
  json["validation"] = m.validation ? ValidationJson(*m.validation) : Json(nullptr);
  return json;
}

Json TrajectoryJson(const TrajectoryPieces& p) {
  const int num_joints = static_cast<int>(p.coefficients.cols()) - 2;
  Json json;
  Json names = Json::array({"s", "yaw"});
  for (int k = 0; k < num_joints; ++k) names.push_back("q" + std::to_string(k + 1));
  json["dimensions"] = names;
  json["p0_m"] = VectorJson(p.p0_W_m);
  json["panels_per_piece"] = p.panels_per_piece;
  json["duration_s"] = p.durations_s.sum();
  Json pieces = Json::array();
  for (Eigen::Index j = 0; j < p.durations_s.size(); ++j) {
    Json coefficients = Json::array();
    for (Eigen::Index d = 0; d < p.coefficients.cols(); ++d) {
      coefficients.push_back(VectorJson(p.coefficients.block(6 * j, d, 6, 1)));
    }
    pieces.push_back({{"duration_s", p.durations_s(j)}, {"coefficients", coefficients}});
  }
  json["pieces"] = pieces;
  return json;
}

// Sample rows use short keys ({"t", "x", "y", "yaw", "q"}, plus
// s, v, omega, a, beta); their units are stated once, in samples.units.
Json SamplesJson(const TrajectoryFile& file) {
  Json rows = Json::array();
  for (const TrajectorySample& s : file.samples) {
    rows.push_back({{"t", s.t_s},
                    {"x", s.state.x_m},
                    {"y", s.state.y_m},
                    {"yaw", s.state.yaw_rad},
                    {"s", s.s_m},
                    {"v", s.v_mps},
                    {"omega", s.omega_radps},
                    {"a", s.a_mps2},
                    {"beta", s.beta_radps2},
                    {"q", VectorJson(s.state.q_rad)}});
  }
  const Json units = {{"t", "s"},       {"x", "m"},       {"y", "m"},
                      {"yaw", "rad"},   {"s", "m"},       {"v", "m/s"},
                      {"omega", "rad/s"}, {"a", "m/s^2"}, {"beta", "rad/s^2"},
                      {"q", "rad (revolute) or m (prismatic)"}};
  return {{"period_s", file.sample_period_s},
          {"count", file.samples.size()},
          {"units", units},
          {"rows", rows}};
}

// Indented layout, except that arrays without objects and objects inside arrays (one piece,
// one sample) are written on one line.
void Write(const Json& value, int indent, bool inside_array, std::string* out) {
  const bool compact = inside_array || (value.is_array() &&
                                        std::none_of(value.begin(), value.end(),
                                                     [](const Json& e) { return e.is_object(); }));
  if (compact || !value.is_structured() || value.empty()) {
    *out += value.dump();
    return;
  }
  const std::string pad(indent + 2, ' ');
  *out += value.is_object() ? "{\n" : "[\n";
  bool first = true;
  if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      *out += (first ? "" : ",\n") + pad + Json(key).dump() + ": ";
      Write(member, indent + 2, false, out);
      first = false;
    }
  } else {
    for (const Json& element : value) {
      *out += (first ? "" : ",\n") + pad;
      Write(element, indent + 2, true, out);
      first = false;
    }
  }
  *out += "\n" + std::string(indent, ' ') + (value.is_object() ? "}" : "]");
}

// ---- Reading -------------------------------------------------------------------------------

using topay::JsonFieldReader;

std::string Path(const std::string& parent, const std::string& key) {
  return JsonFieldReader::Child(parent, key);
}

// Number at `key` of `object`; null gives `null_value` (for figures written as null).
double NumberOr(const JsonFieldReader& r, const nlohmann::json& object, const std::string& path,
                const std::string& key, double null_value) {
  const nlohmann::json& v = r.Member(object, path, key);
  return v.is_null() ? null_value : r.Number(v, Path(path, key));
}

double NumberAt(const JsonFieldReader& r, const nlohmann::json& object, const std::string& path,
                const std::string& key) {
  return r.Number(r.Member(object, path, key), Path(path, key));
}

std::string StringAt(const JsonFieldReader& r, const nlohmann::json& object,
                     const std::string& path, const std::string& key) {
  return r.String(r.Member(object, path, key), Path(path, key));
}

const nlohmann::json& ObjectAt(const JsonFieldReader& r, const nlohmann::json& object,
                               const std::string& path, const std::string& key) {
  const nlohmann::json& v = r.Member(object, path, key);
  r.RequireObject(v, Path(path, key));
  return v;
}

int IntAt(const JsonFieldReader& r, const nlohmann::json& object, const std::string& path,
          const std::string& key) {
  const std::uint64_t value = r.Unsigned(r.Member(object, path, key), Path(path, key));
  if (value > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    r.Fail(Path(path, key), "too large");
  }
  return static_cast<int>(value);
}

WholeBodyState ReadState(const JsonFieldReader& r, const nlohmann::json& v,
                         const std::string& path) {
  r.RequireObject(v, path);
  WholeBodyState state;
  state.x_m = NumberAt(r, v, path, "x_m");
  state.y_m = NumberAt(r, v, path, "y_m");
  state.yaw_rad = NumberAt(r, v, path, "yaw_rad");
  state.q_rad = r.NumberArray(r.Member(v, path, "q_rad"), Path(path, "q_rad"), -1);
  return state;
}

Eigen::Isometry3d ReadPose(const JsonFieldReader& r, const nlohmann::json& v,
                           const std::string& path) {
  r.RequireObject(v, path);
  const Eigen::Vector3d p = r.Vector3(r.Member(v, path, "position_m"), Path(path, "position_m"));
  const std::string q_path = Path(path, "quaternion_wxyz");
  const Eigen::VectorXd q = r.NumberArray(r.Member(v, path, "quaternion_wxyz"), q_path, 4);
  if (std::abs(q.norm() - 1.0) > 1e-6) r.Fail(q_path, "not a unit quaternion");
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
  X.translation() = p;
  return X;
}

TrajectoryValidationFigures ReadValidation(const JsonFieldReader& r, const nlohmann::json& v,
                                           const std::string& path) {
  r.RequireObject(v, path);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  TrajectoryValidationFigures f;
  const nlohmann::json& ok = r.Member(v, path, "ok");
  if (!ok.is_boolean()) r.Fail(Path(path, "ok"), "expected true or false");
  f.ok = ok.get<bool>();
  f.duration_s = NumberAt(r, v, path, "duration_s");
  f.num_samples = IntAt(r, v, path, "num_samples");
  f.min_clearance_m = NumberOr(r, v, path, "min_clearance_m", kInf);
  f.min_clearance_part = StringAt(r, v, path, "min_clearance_part");
  f.min_self_clearance_m = NumberOr(r, v, path, "min_self_clearance_m", kInf);
  f.worst_limit_ratio = NumberAt(r, v, path, "worst_limit_ratio");
  f.worst_limit = StringAt(r, v, path, "worst_limit");
  f.worst_limit_t_s = NumberOr(r, v, path, "worst_limit_t_s", kNaN);
  f.end_position_error_m = NumberOr(r, v, path, "end_position_error_m", kNaN);
  f.end_orientation_error_rad = NumberOr(r, v, path, "end_orientation_error_rad", kNaN);
  return f;
}

TrajectoryMetadata ReadMetadata(const JsonFieldReader& r, const nlohmann::json& doc) {
  const std::string path = "metadata";
  const nlohmann::json& v = ObjectAt(r, doc, "", path);
  TrajectoryMetadata m;
  const std::string scene_path = Path(path, "scene");
  const nlohmann::json& scene = ObjectAt(r, v, path, "scene");
  m.scene_kind = StringAt(r, scene, scene_path, "kind");
  m.scene_seed = r.Unsigned(r.Member(scene, scene_path, "seed"), Path(scene_path, "seed"));
  m.scene_file = StringAt(r, scene, scene_path, "file");
  m.num_boxes = IntAt(r, scene, scene_path, "num_boxes");
  const std::string task_path = Path(path, "task");
  const nlohmann::json& task = ObjectAt(r, v, path, "task");
  m.task_source = StringAt(r, task, task_path, "source");
  m.task_file = StringAt(r, task, task_path, "file");
  m.task_range = StringAt(r, task, task_path, "range");
  m.task_seed = r.Unsigned(r.Member(task, task_path, "seed"), Path(task_path, "seed"));
  m.start = ReadState(r, r.Member(task, task_path, "start"), Path(task_path, "start"));
  m.X_WE_goal = ReadPose(r, r.Member(task, task_path, "goal_end_effector"),
                         Path(task_path, "goal_end_effector"));
  const std::string limits_path = Path(path, "base_limits");
  const nlohmann::json& limits = ObjectAt(r, v, path, "base_limits");
  m.base_limits_source = StringAt(r, limits, limits_path, "source");
  m.base_limits.v_max_mps = NumberAt(r, limits, limits_path, "v_max_mps");
  m.base_limits.a_max_mps2 = NumberAt(r, limits, limits_path, "a_max_mps2");
  m.base_limits.omega_max_radps = NumberAt(r, limits, limits_path, "omega_max_radps");
  m.base_limits.beta_max_radps2 = NumberAt(r, limits, limits_path, "beta_max_radps2");
  const std::string plan_path = Path(path, "plan");
  const nlohmann::json& plan = ObjectAt(r, v, path, "plan");
  m.status = StringAt(r, plan, plan_path, "status");
  m.failure_reason = StringAt(r, plan, plan_path, "failure_reason");
  const std::string t_path = Path(plan_path, "timings_ms");
  const nlohmann::json& t = ObjectAt(r, plan, plan_path, "timings_ms");
  m.map_build_ms = NumberAt(r, t, t_path, "map_build");
  m.timings.search_ms = NumberAt(r, t, t_path, "search");
  m.timings.sampling_ms = NumberAt(r, t, t_path, "sampling");
  m.timings.front_end_ms = NumberAt(r, t, t_path, "front_end");
  m.timings.optimization_ms = NumberAt(r, t, t_path, "optimization");
  m.timings.wait_ms = NumberAt(r, t, t_path, "wait");
  m.timings.total_ms = NumberAt(r, t, t_path, "total");
  const nlohmann::json& validation = r.Member(v, path, "validation");
  if (!validation.is_null()) m.validation = ReadValidation(r, validation, Path(path, "validation"));
  return m;
}

TrajectoryPieces ReadPieces(const JsonFieldReader& r, const nlohmann::json& v, int num_joints) {
  const std::string path = "trajectory";
  r.RequireObject(v, path);
  const int dims = 2 + num_joints;
  TrajectoryPieces p;
  p.p0_W_m = r.NumberArray(r.Member(v, path, "p0_m"), Path(path, "p0_m"), 2);
  p.panels_per_piece = IntAt(r, v, path, "panels_per_piece");
  if (p.panels_per_piece < 1) r.Fail(Path(path, "panels_per_piece"), "must be at least 1");
  const std::string pieces_path = Path(path, "pieces");
  const nlohmann::json& pieces = r.Member(v, path, "pieces");
  r.RequireArray(pieces, pieces_path);
  if (pieces.empty()) r.Fail(pieces_path, "no pieces");
  const auto m = static_cast<Eigen::Index>(pieces.size());
  p.durations_s.resize(m);
  p.coefficients.resize(6 * m, dims);
  for (Eigen::Index j = 0; j < m; ++j) {
    const std::string piece_path = JsonFieldReader::Index(pieces_path, j);
    const nlohmann::json& piece = pieces[j];
    r.RequireObject(piece, piece_path);
    p.durations_s(j) = NumberAt(r, piece, piece_path, "duration_s");
    if (!(p.durations_s(j) > 0.0)) r.Fail(Path(piece_path, "duration_s"), "must be > 0");
    const std::string c_path = Path(piece_path, "coefficients");
    const nlohmann::json& c = r.Member(piece, piece_path, "coefficients");
    r.RequireArray(c, c_path);
    if (static_cast<int>(c.size()) != dims) {
      r.Fail(c_path, "has " + std::to_string(c.size()) + " dimensions, expected " +
                         std::to_string(dims) + " (s, yaw and " + std::to_string(num_joints) +
                         " joints)");
    }
    for (int d = 0; d < dims; ++d) {
      p.coefficients.block(6 * j, d, 6, 1) =
          r.NumberArray(c[d], JsonFieldReader::Index(c_path, d), 6);
    }
  }
  return p;
}

TrajectorySample ReadSample(const JsonFieldReader& r, const nlohmann::json& v,
                            const std::string& path, int num_joints) {
  r.RequireObject(v, path);
  TrajectorySample s;
  s.t_s = NumberAt(r, v, path, "t");
  s.state.x_m = NumberAt(r, v, path, "x");
  s.state.y_m = NumberAt(r, v, path, "y");
  s.state.yaw_rad = NumberAt(r, v, path, "yaw");
  s.s_m = NumberAt(r, v, path, "s");
  s.v_mps = NumberAt(r, v, path, "v");
  s.omega_radps = NumberAt(r, v, path, "omega");
  s.a_mps2 = NumberAt(r, v, path, "a");
  s.beta_radps2 = NumberAt(r, v, path, "beta");
  s.state.q_rad = r.NumberArray(r.Member(v, path, "q"), Path(path, "q"), num_joints);
  return s;
}

void ReadSamples(const JsonFieldReader& r, const nlohmann::json& doc, int num_joints,
                 TrajectoryFile* file) {
  const nlohmann::json& v = ObjectAt(r, doc, "", "samples");
  file->sample_period_s = NumberAt(r, v, "samples", "period_s");
  if (!(file->sample_period_s > 0.0)) r.Fail("samples.period_s", "must be > 0");
  const nlohmann::json& rows = r.Member(v, "samples", "rows");
  r.RequireArray(rows, "samples.rows");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string path = JsonFieldReader::Index("samples.rows", i);
    file->samples.push_back(ReadSample(r, rows[i], path, num_joints));
    if (i > 0 && !(file->samples[i].t_s > file->samples[i - 1].t_s)) {
      r.Fail(Path(path, "t"), "sample times must increase");
    }
  }
  const std::uint64_t count = r.Unsigned(r.Member(v, "samples", "count"), "samples.count");
  if (count != rows.size()) {
    r.Fail("samples.count",
           std::to_string(count) + " but " + std::to_string(rows.size()) + " rows");
  }
}

TrajectoryFile FromDocument(const JsonFieldReader& r, const nlohmann::json& doc) {
  r.RequireObject(doc, "");
  if (StringAt(r, doc, "", "format") != kFormat) {
    r.Fail("format", std::string("expected \"") + kFormat + "\"");
  }
  if (IntAt(r, doc, "", "version") != kVersion) {
    r.Fail("version", "unsupported (this reader knows version " + std::to_string(kVersion) + ")");
  }
  TrajectoryFile file;
  file.metadata = ReadMetadata(r, doc);
  const int num_joints = file.metadata.start.num_joints();
  const nlohmann::json& trajectory = r.Member(doc, "", "trajectory");
  if (!trajectory.is_null()) file.pieces = ReadPieces(r, trajectory, num_joints);
  ReadSamples(r, doc, num_joints, &file);
  return file;
}

}  // namespace

std::string TrajectoryToJson(const TrajectoryFile& file) {
  Json doc;
  doc["format"] = kFormat;
  doc["version"] = kVersion;
  doc["metadata"] = MetadataJson(file.metadata);
  doc["trajectory"] = file.pieces ? TrajectoryJson(*file.pieces) : Json(nullptr);
  doc["samples"] = SamplesJson(file);
  std::string out;
  Write(doc, 0, false, &out);
  return out + "\n";
}

void WriteTrajectoryJson(const std::string& path, const TrajectoryFile& file) {
  const std::string text = TrajectoryToJson(file);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw ConfigError(path, "", "cannot open for writing");
  out << text;
  out.flush();
  if (!out) throw ConfigError(path, "", "write failed");
}

TrajectoryFile ReadTrajectoryJson(const std::string& path) {
  const JsonFieldReader reader(path);
  return FromDocument(reader, reader.ParseFile());
}

TrajectoryFile TrajectoryFromJson(const std::string& text, const std::string& file_name) {
  const JsonFieldReader reader(file_name);
  return FromDocument(reader, reader.ParseText(text));
}

}  // namespace topay::plan
