#include "tools/topay_bench/bench_record_json.h"

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "sim/scenes/task_json.h"

namespace topay::bench {
namespace {

using Json = nlohmann::ordered_json;

Json Number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json StateJson(const WholeBodyState& state) {
  return Json{
      {"x_m", state.x_m},
      {"y_m", state.y_m},
      {"yaw_rad", state.yaw_rad},
      {"q_rad", std::vector<double>(state.q_rad.data(), state.q_rad.data() + state.q_rad.size())}};
}

Json TargetJson(const Eigen::Isometry3d& X_WE) {
  const Eigen::Vector3d p = X_WE.translation();
  const Eigen::Quaterniond quaternion(X_WE.rotation());
  return Json{
      {"position_m", {p.x(), p.y(), p.z()}},
      {"quaternion_wxyz", {quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z()}}};
}

Json TimingsJson(const PlanTimings& t) {
  return Json{{"search", t.search_ms},       {"sampling", t.sampling_ms},
              {"front_end", t.front_end_ms}, {"optimization", t.optimization_ms},
              {"wait", t.wait_ms},           {"total", t.total_ms}};
}

Json ValidationJson(const std::optional<plan::TrajectoryValidationFigures>& figures) {
  if (!figures) return Json(nullptr);
  const plan::TrajectoryValidationFigures& v = *figures;
  return Json{{"ok", v.ok},
              {"min_clearance_m", Number(v.min_clearance_m)},
              {"min_clearance_part", v.min_clearance_part},
              {"min_self_clearance_m", Number(v.min_self_clearance_m)},
              {"worst_limit_ratio", Number(v.worst_limit_ratio)},
              {"worst_limit", v.worst_limit},
              {"worst_limit_t_s", Number(v.worst_limit_t_s)},
              {"end_position_error_m", Number(v.end_position_error_m)},
              {"end_orientation_error_rad", Number(v.end_orientation_error_rad)}};
}

Json OptimizerJson(const std::optional<OptimizerWork>& work) {
  if (!work) return Json(nullptr);
  return Json{{"pieces", work->num_pieces},
              {"stage1_iterations", work->stage1_iterations},
              {"stage2_iterations", work->stage2_iterations},
              {"outer_iterations", work->outer_iterations},
              {"evaluations", work->evaluations},
              {"penalty_escalations", work->penalty_escalations}};
}

Json SensedJson(const std::optional<SensedMapFigures>& f) {
  if (!f) return Json(nullptr);
  Json json;
  json["scans"] = f->scans;
  json["points"] = f->points;
  json["points_mapped"] = f->points_mapped;
  json["self_points"] = f->self_points;
  json["voxels_occupied"] = f->voxels.occupied;
  json["voxels_free"] = f->voxels.free;
  json["voxels_unknown"] = f->voxels.unknown;
  json["voxel_boxes"] = f->voxel_boxes;
  json["lidar_ms"] = f->lidar_ms;
  json["mapping_ms"] = f->mapping_ms;
  json["fields_ms"] = f->fields_ms;
  json["boxes_ms"] = f->boxes_ms;
  return json;
}

}  // namespace

nlohmann::ordered_json RecordToJson(const BenchRecord& r) {
  Json json;
  json["task"] = r.task;
  json["task_seed"] = r.task_seed;
  json["scene_seed"] = r.scene_seed;
  json["scene"] = r.scene;
  json["range"] = r.range;
  json["cell"] = r.cell();
  json["method"] = r.method;
  json["order"] = r.order;
  json["start"] = StateJson(r.start);
  json["goal_hint"] = StateJson(r.goal_hint);
  json["used_hint"] = r.used_hint;
  json["target"] = TargetJson(r.X_WE_goal);
  json["base_distance_m"] = r.base_distance_m;
  json["base_unreachable"] = r.base_unreachable;
  json["tight"] = r.tight_info ? TightInfoToJson(*r.tight_info) : Json(nullptr);
  json["success"] = r.success;
  json["status"] = r.status;
  json["failure_reason"] = r.failure_reason;
  json["failure_category"] = std::string(FailureCategoryName(r.failure));
  json["timings_ms"] = TimingsJson(r.timings);
  json["map_ms"] = r.map_ms;
  json["sensed_map"] = SensedJson(r.sensed);
  json["duration_s"] = Number(r.duration_s);
  json["num_candidates"] = r.num_candidates;
  json["num_paths"] = r.num_paths;
  json["num_classes"] = r.num_classes;
  json["num_base_paths"] = r.num_base_paths;
  json["plan_rounds"] = r.plan_rounds;
  json["validation"] = ValidationJson(r.validation);
  json["optimizer"] = OptimizerJson(r.optimizer);
  return json;
}

std::string RecordJsonLine(const BenchRecord& record) { return RecordToJson(record).dump(); }

}  // namespace topay::bench
