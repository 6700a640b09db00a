// The one file of the mapper that includes PCL (its headers compile slowly).
#include "procs/mapper/scan_filter.h"

#include <string>

#include <pcl/filters/radius_outlier_removal.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "core/common/stopwatch.h"

namespace topay::mapper {

using PclCloud = pcl::PointCloud<pcl::PointXYZ>;

// Kept between scans: the clouds keep their capacity, the filters their settings.
struct ScanFilter::PclStages {
  PclCloud::Ptr input = std::make_shared<PclCloud>();
  PclCloud output;
  pcl::VoxelGrid<pcl::PointXYZ> voxel_grid;
  pcl::RadiusOutlierRemoval<pcl::PointXYZ> radius;
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> statistical;

  explicit PclStages(const ScanFilterOptions& o) {
    const float leaf = static_cast<float>(o.voxel_leaf_m);
    voxel_grid.setLeafSize(leaf, leaf, leaf);
    radius.setRadiusSearch(o.outlier_radius_m);
    radius.setMinNeighborsInRadius(o.outlier_min_neighbors);
    statistical.setMeanK(o.outlier_mean_k);
    statistical.setStddevMulThresh(o.outlier_stddev_mul);
  }

  void Load(const std::vector<Eigen::Vector3f>& p_WP) {
    input->resize(p_WP.size());  // width = size, height = 1
    for (std::size_t i = 0; i < p_WP.size(); ++i) {
      (*input)[i] = pcl::PointXYZ(p_WP[i].x(), p_WP[i].y(), p_WP[i].z());
    }
    input->is_dense = true;  // the range stage dropped every non-finite point
  }

  void Store(std::vector<Eigen::Vector3f>* p_WP) const {
    p_WP->resize(output.size());
    for (std::size_t i = 0; i < output.size(); ++i) {
      (*p_WP)[i] = {output[i].x, output[i].y, output[i].z};
    }
  }

  // Runs `filter` on *p_WP in place.
  template <typename Filter>
  void Run(Filter* filter, std::vector<Eigen::Vector3f>* p_WP) {
    if (p_WP->empty()) return;
    Load(*p_WP);
    filter->setInputCloud(input);
    filter->filter(output);
    Store(p_WP);
  }
};

ScanFilter::ScanFilter(const ScanFilterOptions& options, const Kinematics& kinematics)
    : options_((CheckScanFilterOptions(options), options)),
      kinematics_(kinematics),
      cache_(kinematics.MakeCache()),
      body_(options.self_margin_m),
      pcl_(std::make_unique<PclStages>(options)) {}

ScanFilter::~ScanFilter() = default;

void ScanFilter::CropRange(const msgs::CheckedCloud& cloud, std::vector<Eigen::Vector3f>* p_WP,
                           ScanFilterSummary* summary) const {
  const Eigen::Matrix3f R_WS = cloud.X_WS.linear().cast<float>();
  const Eigen::Vector3f p_WS = cloud.X_WS.translation().cast<float>();
  const float min_squared = static_cast<float>(options_.range_min_m * options_.range_min_m);
  const float max_squared = static_cast<float>(options_.range_max_m * options_.range_max_m);
  int non_finite = 0;
  for (const Eigen::Vector3f& p_SP : cloud.p_SP) {
    if (!p_SP.allFinite()) {
      ++non_finite;
      continue;
    }
    const float range_squared = p_SP.squaredNorm();
    if (range_squared < min_squared || range_squared > max_squared) continue;
    p_WP->push_back(R_WS * p_SP + p_WS);
  }
  summary->num_non_finite = non_finite;
}

void ScanFilter::RemoveGround(std::vector<Eigen::Vector3f>* p_WP) const {
  const float z_min = static_cast<float>(options_.ground_max_z_m);
  std::size_t kept = 0;
  for (const Eigen::Vector3f& p : *p_WP) {
    if (p.z() >= z_min) (*p_WP)[kept++] = p;
  }
  p_WP->resize(kept);
}

void ScanFilter::RemoveSelf(const std::optional<WholeBodyState>& state, const Eigen::Vector3d& p_WS,
                            std::vector<Eigen::Vector3f>* p_WP, ScanFilterSummary* summary) {
  if (!state) {
    summary->warning = "no robot state at the scan's time: the points near the robot were dropped";
  } else if (state->num_joints() != kinematics_.num_joints() || !state->IsFinite()) {
    summary->warning = "robot state unusable (" + std::to_string(state->num_joints()) +
                       " joints, model has " + std::to_string(kinematics_.num_joints()) +
                       (state->IsFinite() ? "" : "; not finite") +
                       "): the points near the robot were dropped";
  } else {
    kinematics_.Update(*state, &cache_);
    body_.Update(kinematics_.model(), cache_);
    body_.RemoveFrom(p_WP);
    return;
  }
  summary->self_filter_skipped = true;
  const float radius = static_cast<float>(options_.no_state_radius_m);
  if (radius <= 0.0f) return;
  const Eigen::Vector2f p_WS_xy = p_WS.head<2>().cast<float>();
  std::erase_if(*p_WP, [&](const Eigen::Vector3f& p) { return (p.head<2>() - p_WS_xy).squaredNorm() < radius * radius; });
}

ScanFilterSummary ScanFilter::Filter(const msgs::CheckedCloud& cloud,
                                     const std::optional<WholeBodyState>& state,
                                     std::vector<Eigen::Vector3f>* p_WP) {
  ScanFilterSummary summary;
  const Stopwatch total;
  Stopwatch stage;
  const auto lap = [&stage](double* ms) {
    *ms = stage.ElapsedMs();
    stage.Restart();
  };
  p_WP->clear();
  summary.num_input = static_cast<int>(cloud.p_SP.size());
  CropRange(cloud, p_WP, &summary);
  summary.num_after_range = static_cast<int>(p_WP->size());
  lap(&summary.range_ms);
  RemoveGround(p_WP);
  summary.num_after_ground = static_cast<int>(p_WP->size());
  lap(&summary.ground_ms);
  RemoveSelf(state, cloud.X_WS.translation(), p_WP, &summary);
  summary.num_after_self = static_cast<int>(p_WP->size());
  lap(&summary.self_ms);
  if (options_.voxel_leaf_m > 0.0) pcl_->Run(&pcl_->voxel_grid, p_WP);
  summary.num_after_voxel = static_cast<int>(p_WP->size());
  lap(&summary.voxel_ms);
  if (options_.outlier_method == OutlierMethod::kRadius) pcl_->Run(&pcl_->radius, p_WP);
  if (options_.outlier_method == OutlierMethod::kStatistical) {
    pcl_->Run(&pcl_->statistical, p_WP);
  }
  summary.num_output = static_cast<int>(p_WP->size());
  lap(&summary.outlier_ms);
  summary.total_ms = total.ElapsedMs();
  return summary;
}

}  // namespace topay::mapper
