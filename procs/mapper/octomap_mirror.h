#pragma once

#include <memory>
#include <span>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <octomap/OcTree.h>

namespace topay::mapper {

/// The OctoMap mirror's tree: the dense map's resolution, bounds and sensor model.
struct OctomapMirrorOptions {
  /// Voxel side (m): the dense map's (VoxelMapFieldsOptions::resolution_m).
  double resolution_m = 0.05;
  /// Sensor model, as the dense map's: the probability that a voxel holding a return is
  /// occupied, that one a ray passed through is, the clamping bounds of a voxel's
  /// probability (so that it can change again after a few scans) and the threshold above
  /// which a voxel counts as occupied. 0 < miss < threshold < hit < 1,
  /// 0 < clamping_min < threshold < clamping_max < 1.
  double prob_hit = 0.7;
  double prob_miss = 0.4;
  double clamping_min = 0.12;
  double clamping_max = 0.97;
  double occupancy_threshold = 0.5;
  /// The map volume (m), as the dense map's: 20 x 20 x 1.6 m from (-10, -10, 0). Nothing
  /// outside is stored: rays are cut where they leave it, returns outside it mark no voxel.
  Eigen::AlignedBox3d bounds_W_m{Eigen::Vector3d(-10.0, -10.0, 0.0),
                                 Eigen::Vector3d(10.0, 10.0, 1.6)};
  /// A return farther than this from the sensor (m) marks only the free space up to this
  /// range; <= 0: no limit. 20 m, the scan filter's range_max_m.
  double max_range_m = 20.0;
};

/// Throws std::invalid_argument (naming the field) unless the resolution is finite and > 0,
/// the probabilities are ordered as OctomapMirrorOptions says and the bounds are finite and
/// not empty.
void CheckOctomapMirrorOptions(const OctomapMirrorOptions& options);

/// Applies `options`' resolution-independent sensor model to `tree`.
void ApplySensorModel(const OctomapMirrorOptions& options, octomap::OcTree* tree);

/// What one OctomapMirror::Insert did.
struct OctomapInsertSummary {
  int num_points = 0;            ///< Points given.
  int num_returns = 0;           ///< Points that marked their voxel occupied.
  int num_occupied_voxels = 0;   ///< Distinct voxels updated as occupied.
  int num_free_voxels = 0;       ///< Distinct voxels updated as free (none also occupied).
  double ms = 0.0;               ///< Wall-clock time (steady clock).
};

/// An octomap::OcTree kept beside the dense map, for octovis (.bt files) and as the
/// store of a prior map. Each Insert is one scan with free-space ray casting, as
/// OcTree::insertPointCloud (per scan, each voxel is updated once; a voxel both passed
/// through and holding a return counts as occupied), except at the map bounds: a return
/// outside the bounds still clears the voxels its ray crosses inside them (insertPointCloud
/// with a bounding box drops such rays whole, losing the free space seen towards walls and
/// tall objects), and a ray longer than max_range_m clears up to that range.
/// Movable, not copyable; not thread safe.
class OctomapMirror {
 public:
  /// An empty tree. Throws std::invalid_argument for bad options.
  explicit OctomapMirror(const OctomapMirrorOptions& options = {});

  /// The tree of a .bt file (OcTree::writeBinary, e.g. from Save or octovis) as the mirror's
  /// start, with `options`' sensor model. Throws std::runtime_error naming the path for a
  /// missing, unreadable or malformed file, or one at another resolution than options'.
  static OctomapMirror LoadPrior(const std::string& path, const OctomapMirrorOptions& options = {});

  /// Integrates one scan: returns p_WP (m, in W) seen from the sensor origin p_WS.
  OctomapInsertSummary Insert(const Eigen::Vector3d& p_WS, std::span<const Eigen::Vector3f> p_WP);

  /// Writes the tree as a .bt file (OcTree::writeBinary: maximum-likelihood states, opened by
  /// octovis). Throws std::runtime_error naming the path if it cannot be written.
  void Save(const std::string& path) const;

  const octomap::OcTree& tree() const { return *tree_; }
  const OctomapMirrorOptions& options() const { return options_; }

 private:
  OctomapMirror(const OctomapMirrorOptions& options, std::unique_ptr<octomap::OcTree> tree);
  bool InBounds(const octomap::OcTreeKey& key) const;
  // Adds the voxels of the ray from p_WS to p_end inside the bounds to free_.
  void AddFreeRay(const octomap::point3d& p_WS, const octomap::point3d& p_end);

  OctomapMirrorOptions options_;
  std::unique_ptr<octomap::OcTree> tree_;
  octomap::OcTreeKey key_min_, key_max_;  // the bounds' voxels, inclusive
  octomap::KeyRay ray_;
  octomap::KeySet free_, occupied_;
};

/// p (m, double) as OctoMap's float point.
octomap::point3d ToOctomapPoint(const Eigen::Vector3d& p);

/// Reads a .bt file into a tree; throws std::runtime_error naming the path for a missing,
/// unreadable or malformed file.
std::unique_ptr<octomap::OcTree> ReadOcTreeFile(const std::string& path);

/// Writes `tree` as a .bt file; throws std::runtime_error naming the path on failure.
void WriteOcTreeFile(const octomap::OcTree& tree, const std::string& path);

}  // namespace topay::mapper
