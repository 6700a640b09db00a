#include "tools/topay_bench/bench_options.h"

#include "tools/topay_bench/sensing_tour.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tools/topay_plan/base_limit_choice.h"
#include "tools/common/usage_error.h"
#include "sim/scenes/distance_range.h"
#include "sim/scenes/scene_kind.h"

namespace topay::bench {
namespace {

using plan::UsageError;

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::string KnownMethods() {
  std::string names;
  for (BenchMethod method : AllBenchMethods()) {
    names += (names.empty() ? "" : ", ") + std::string(BenchMethodName(method));
  }
  return names;
}

void RequireIn(double value, double lo, double hi, const std::string& option) {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream out;
    out << option << ": " << value << " is outside [" << lo << ", " << hi << "]";
    throw UsageError(out.str());
  }
}

void RequireGiven(const std::string& value, const std::string& option) {
  if (value.empty()) throw UsageError(option + ": a path is required");
}

}  // namespace

std::vector<std::string> ParseMethodList(const std::string& text, const std::string& option) {
  std::vector<std::string> methods;
  if (Trim(text).empty()) throw UsageError(option + ": no method given");
  std::size_t begin = 0;
  while (true) {  // every item, the empty one after a trailing comma too
    const std::size_t end = text.find(',', begin);
    const std::string name = Trim(text.substr(begin, end - begin));  // npos: to the end
    if (name.empty()) throw UsageError(option + ": empty method name in '" + text + "'");
    if (!ParseBenchMethod(name)) {
      throw UsageError(option + ": unknown method '" + name + "' (" + KnownMethods() + ")");
    }
    if (std::find(methods.begin(), methods.end(), name) != methods.end()) {
      throw UsageError(option + ": method '" + name + "' is listed twice");
    }
    methods.push_back(name);
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return methods;
}

void CheckBenchOptions(const BenchOptions& o) {
  if (!ParseSceneKind(o.scene)) {
    throw UsageError("--scene: unknown kind '" + o.scene + "' (cuboids or tables)");
  }
  if (!ParseDistanceRange(o.range)) {
    throw UsageError("--range: unknown range '" + o.range + "' (small, medium or large)");
  }
  RequireIn(o.num_tasks, 1, 1e6, "--tasks");
  std::string joined;
  for (const std::string& m : o.methods) joined += (joined.empty() ? "" : ",") + m;
  ParseMethodList(joined, "--method/--compare");
  if (o.num_threads) RequireIn(*o.num_threads, 0, 256, "--threads");
  if (o.time_limit_ms) RequireIn(*o.time_limit_ms, 10.0, 600000.0, "--time-limit-ms");
  if (!o.base_limits.empty() && !plan::ParseBaseLimitChoice(o.base_limits)) {
    throw UsageError("--base-limits: unknown choice '" + o.base_limits +
                     "' (benchmark, robot or config)");
  }
  if (!o.sensed_map.empty()) {
    if (!ParseSensingTourKind(o.sensed_map)) {
      throw UsageError("--sensed-map: unknown tour '" + o.sensed_map + "' (line or tour)");
    }
    if (o.sensed_unknown != "free" && o.sensed_unknown != "occupied") {
      throw UsageError("--sensed-unknown: '" + o.sensed_unknown + "' (free or occupied)");
    }
    RequireIn(o.sensed_margin_m, 0.0, 0.5, "--sensed-margin-m");
    RequireGiven(o.mapper_config, "--mapper-config");
    RequireGiven(o.lidar_config, "--lidar-config");
  }
  RequireGiven(o.out_dir, "--out");
  RequireGiven(o.planner_config, "--config");
  RequireGiven(o.robot_urdf, "--robot");
  RequireGiven(o.robot_yaml, "--robot-config");
}

std::vector<BenchMethod> MethodsOf(const BenchOptions& options) {
  std::vector<BenchMethod> methods;
  for (const std::string& name : options.methods) methods.push_back(*ParseBenchMethod(name));
  return methods;
}

std::vector<std::string> RunMethodNames(const BenchOptions& options) {
  std::vector<std::string> names = options.methods;
  if (options.sensed_map.empty()) return names;
  for (const std::string& name : options.methods) names.push_back(name + "@sensed");
  return names;
}

}  // namespace topay::bench
