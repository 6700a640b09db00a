#include "procs/mapper/octomap_mirror.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/common/stopwatch.h"

namespace topay::mapper {
namespace {

void Require(bool ok, const std::string& field, const std::string& what) {
  if (!ok) throw std::invalid_argument("OctomapMirrorOptions." + field + ": " + what);
}

bool InOpenUnit(double p) { return std::isfinite(p) && p > 0.0 && p < 1.0; }

}  // namespace

octomap::point3d ToOctomapPoint(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

void CheckOctomapMirrorOptions(const OctomapMirrorOptions& o) {
  Require(std::isfinite(o.resolution_m) && o.resolution_m > 0.0, "resolution_m",
          "expected a finite size > 0");
  Require(InOpenUnit(o.prob_hit) && InOpenUnit(o.prob_miss) && InOpenUnit(o.occupancy_threshold),
          "prob_hit/prob_miss/occupancy_threshold", "expected probabilities in (0, 1)");
  Require(o.prob_miss < o.occupancy_threshold && o.occupancy_threshold < o.prob_hit,
          "occupancy_threshold", "expected prob_miss < occupancy_threshold < prob_hit");
  Require(InOpenUnit(o.clamping_min) && InOpenUnit(o.clamping_max) &&
              o.clamping_min < o.occupancy_threshold && o.occupancy_threshold < o.clamping_max,
          "clamping_min/clamping_max",
          "expected 0 < clamping_min < occupancy_threshold < clamping_max < 1");
  Require(o.bounds_W_m.min().allFinite() && o.bounds_W_m.max().allFinite() &&
              (o.bounds_W_m.max() - o.bounds_W_m.min()).minCoeff() >= o.resolution_m,
          "bounds_W_m", "expected finite bounds at least one voxel wide on each axis");
  Require(std::isfinite(o.max_range_m), "max_range_m", "expected a finite range (<= 0: none)");
}

void ApplySensorModel(const OctomapMirrorOptions& o, octomap::OcTree* tree) {
  tree->setProbHit(o.prob_hit);
  tree->setProbMiss(o.prob_miss);
  tree->setClampingThresMin(o.clamping_min);
  tree->setClampingThresMax(o.clamping_max);
  tree->setOccupancyThres(o.occupancy_threshold);
}

OctomapMirror::OctomapMirror(const OctomapMirrorOptions& options)
    : OctomapMirror(options, nullptr) {}

OctomapMirror::OctomapMirror(const OctomapMirrorOptions& options,
                             std::unique_ptr<octomap::OcTree> tree)
    : options_((CheckOctomapMirrorOptions(options), options)), tree_(std::move(tree)) {
  if (!tree_) tree_ = std::make_unique<octomap::OcTree>(options_.resolution_m);
  ApplySensorModel(options_, tree_.get());
  const Eigen::Vector3d half_voxel = Eigen::Vector3d::Constant(0.5 * options_.resolution_m);
  const Eigen::AlignedBox3d& bounds = options_.bounds_W_m;
  if (!tree_->coordToKeyChecked(ToOctomapPoint(bounds.min() + half_voxel), key_min_) ||
      !tree_->coordToKeyChecked(ToOctomapPoint(bounds.max() - half_voxel), key_max_)) {
    throw std::invalid_argument("OctomapMirrorOptions.bounds_W_m: outside the OcTree's range");
  }
}

OctomapMirror OctomapMirror::LoadPrior(const std::string& path,
                                       const OctomapMirrorOptions& options) {
  std::unique_ptr<octomap::OcTree> tree = ReadOcTreeFile(path);
  if (std::abs(tree->getResolution() - options.resolution_m) > 1e-9) {
    throw std::runtime_error("OctoMap prior " + path + ": resolution " +
                             std::to_string(tree->getResolution()) + " m, the map's is " +
                             std::to_string(options.resolution_m) + " m");
  }
  return OctomapMirror(options, std::move(tree));
}

bool OctomapMirror::InBounds(const octomap::OcTreeKey& key) const {
  for (int a = 0; a < 3; ++a) {
    if (key[a] < key_min_[a] || key[a] > key_max_[a]) return false;
  }
  return true;
}

void OctomapMirror::AddFreeRay(const octomap::point3d& p_WS, const octomap::point3d& p_end) {
  if (!tree_->computeRayKeys(p_WS, p_end, ray_)) return;  // leaves the tree's range
  bool entered = false;
  for (const octomap::OcTreeKey& key : ray_) {
    if (InBounds(key)) {
      free_.insert(key);
      entered = true;
    } else if (entered) {
      break;  // the box is convex: once out, the ray stays out
    }
  }
}

OctomapInsertSummary OctomapMirror::Insert(const Eigen::Vector3d& p_WS,
                                           std::span<const Eigen::Vector3f> p_WP) {
  const Stopwatch watch;
  OctomapInsertSummary summary;
  summary.num_points = static_cast<int>(p_WP.size());
  free_.clear();
  occupied_.clear();
  const octomap::point3d origin = ToOctomapPoint(p_WS);
  const float max_range = static_cast<float>(options_.max_range_m);
  for (const Eigen::Vector3f& p : p_WP) {
    if (!p.allFinite()) continue;
    octomap::point3d end(p.x(), p.y(), p.z());
    const float range = (end - origin).norm();
    const bool beyond = max_range > 0.0f && range > max_range;
    if (beyond) end = origin + (end - origin) * (max_range / range);
    AddFreeRay(origin, end);
    octomap::OcTreeKey key;
    if (!beyond && tree_->coordToKeyChecked(end, key) && InBounds(key)) {
      occupied_.insert(key);
      ++summary.num_returns;
    }
  }
  for (const octomap::OcTreeKey& key : free_) {
    if (occupied_.count(key) == 0) {
      tree_->updateNode(key, false);
      ++summary.num_free_voxels;
    }
  }
  for (const octomap::OcTreeKey& key : occupied_) tree_->updateNode(key, true);
  summary.num_occupied_voxels = static_cast<int>(occupied_.size());
  summary.ms = watch.ElapsedMs();
  return summary;
}

void OctomapMirror::Save(const std::string& path) const { WriteOcTreeFile(*tree_, path); }

std::unique_ptr<octomap::OcTree> ReadOcTreeFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw std::runtime_error("OctoMap file " + path + ": not found (or not a regular file)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("OctoMap file " + path + ": cannot be opened");
  auto tree = std::make_unique<octomap::OcTree>(0.1);  // readBinary sets the file's resolution
  if (!tree->readBinary(in) || in.bad()) {
    throw std::runtime_error("OctoMap file " + path +
                             ": not a readable OcTree binary file (.bt, OcTree::writeBinary)");
  }
  return tree;
}

void WriteOcTreeFile(const octomap::OcTree& tree, const std::string& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("OctoMap file " + path + ": cannot be opened for writing");
  // writeBinaryConst: the tree itself is not pruned or changed (writeBinary would prune it).
  if (!tree.writeBinaryConst(out) || !out.flush()) {
    throw std::runtime_error("OctoMap file " + path + ": write failed");
  }
}

}  // namespace topay::mapper
