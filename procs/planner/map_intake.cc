#include "procs/planner/map_intake.h"

#include <algorithm>
#include <tuple>

#include "core/map/voxel_boxes.h"

namespace topay::planner {

int ClearBaseFootprint(const GridGeometry3& geometry, const Eigen::Vector2d& p_WB_m,
                       const BaseCylinder& base, UnknownVoxelPolicy unknown,
                       std::vector<std::uint8_t>* states) {
  const Eigen::Vector3d r(base.radius_m, base.radius_m, 0.0);
  const Eigen::Vector3d p(p_WB_m.x(), p_WB_m.y(), 0.0);
  const CellBox cells = VoxelsOverlapping(
      geometry, {p - r, p + r + Eigen::Vector3d(0.0, 0.0, base.height_m)});
  int cleared = 0;
  for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz) {
    for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy) {
      for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) {
        const Eigen::Vector3d c = geometry.CellCenter(ix, iy, iz);
        std::uint8_t& state = (*states)[geometry.Index(ix, iy, iz)];
        // Every voxel reaching into the cylinder: its bottom below the top, its square nearer
        // the axis than the radius.
        const double half = 0.5 * geometry.resolution_m;
        const Eigen::Vector2d outside = ((c.head<2>() - p_WB_m).cwiseAbs().array() - half).max(0.0);
        if (c.z() - half >= base.height_m || outside.norm() >= base.radius_m ||
            !VoxelBlocksPlanner(static_cast<VoxelState>(state), unknown)) {
          continue;
        }
        state = static_cast<std::uint8_t>(VoxelState::kFree);
        ++cleared;
      }
    }
  }
  return cleared;
}

int ClearArmOverlaps(const GridGeometry3& geometry, const Kinematics& kinematics, const WholeBodyState& state,
                     double max_depth_m, UnknownVoxelPolicy unknown, std::vector<std::uint8_t>* states) {
  KinematicsCache cache = kinematics.MakeCache();
  kinematics.Update(state, &cache);
  const double half = 0.5 * geometry.resolution_m;
  int cleared = 0;
  for (std::size_t s = 0; s < cache.p_WS.size(); ++s) {
    const Eigen::Vector3d& p_WS = cache.p_WS[s];
    const double r = kinematics.model().spheres[s].radius_m;
    const CellBox cells = VoxelsOverlapping(geometry, {p_WS - Eigen::Vector3d::Constant(r), p_WS + Eigen::Vector3d::Constant(r)});
    for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz) {
      for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy) {
        for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) {
          std::uint8_t& voxel = (*states)[geometry.Index(ix, iy, iz)];
          if (!VoxelBlocksPlanner(static_cast<VoxelState>(voxel), unknown)) continue;
          // Distance from the sphere's centre to the voxel's box (0 inside it).
          const Eigen::Vector3d c = geometry.CellCenter(ix, iy, iz);
          const double d = ((p_WS - c).cwiseAbs().array() - half).max(0.0).matrix().norm();
          if (d >= r || d <= r - max_depth_m) continue;
          voxel = static_cast<std::uint8_t>(VoxelState::kFree);
          ++cleared;
        }
      }
    }
  }
  return cleared;
}

MapIntake::MapIntake(UnknownVoxelPolicy unknown, const msgs::MapCodecOptions& codec)
    : unknown_(unknown), receiver_(codec) {}

std::optional<MapWork> MapIntake::Accept(const map_update_t& msg, msgs::MapAcceptResult* result) {
  *result = receiver_.Accept(msg);
  MapWork work;
  work.map_seq = receiver_.map_seq();
  work.map_utime = receiver_.utime();
  work.geometry = receiver_.geometry();
  if (result->outcome == msgs::MapUpdateOutcome::kDeltaApplied) {
    for (const VoxelChange& c : result->changes) {
      forwarded_[receiver_.geometry().Index(c.voxel.x(), c.voxel.y(), c.voxel.z())] =
          static_cast<std::uint8_t>(c.state);
    }
    work.changes = result->changes;
    return work;
  }
  if (result->outcome != msgs::MapUpdateOutcome::kSnapshotApplied) return std::nullopt;
  const std::span<const std::uint8_t> states = receiver_.states();
  if (forwarded_.size() != states.size() || !SameGeometry(forwarded_geometry_, receiver_.geometry())) {
    forwarded_.assign(states.begin(), states.end());
    forwarded_geometry_ = receiver_.geometry();
    work.reset = true;
    work.states = forwarded_;
    return work;
  }
  // A snapshot of the grid held: only what differs (usually nothing: the deltas had it all), found
  // by comparing the two arrays in runs (std::mismatch), in index order.
  const GridGeometry3& g = receiver_.geometry();
  auto held = forwarded_.begin();
  auto sent = states.begin();
  while (true) {
    std::tie(held, sent) = std::mismatch(held, forwarded_.end(), sent, states.end());
    if (held == forwarded_.end()) break;
    *held = *sent;
    work.changes.push_back({g.CellAt(held - forwarded_.begin()), static_cast<VoxelState>(*sent)});
    ++held;
    ++sent;
  }
  if (work.changes.empty()) return std::nullopt;
  return work;
}

std::vector<OrientedBox> MapIntake::BlockedBoxesNear(const Eigen::AlignedBox3d& region_W_m) const {
  if (!receiver_.has_map()) return {};
  const GridGeometry3& g = receiver_.geometry();
  return BlockedVoxelBoxes(g, receiver_.states(), unknown_, VoxelsOverlapping(g, region_W_m));
}

std::vector<OrientedBox> MapIntake::BlockedBoxesNear(const Eigen::AlignedBox3d& region_W_m,
                                                    const Kinematics& kinematics,
                                                    const StandingRobot& standing) const {
  if (!receiver_.has_map()) return {};
  const GridGeometry3& g = receiver_.geometry();
  // Far from where it stood (most of a trajectory's checks) the robot's voxels are not in the
  // region: no copy of the grid.
  if (!region_W_m.intersects(StandingRobotBounds(kinematics, standing, g.resolution_m))) {
    return BlockedBoxesNear(region_W_m);
  }
  std::vector<std::uint8_t> states(receiver_.states().begin(), receiver_.states().end());
  ClearStandingRobot(g, kinematics, standing, unknown_, &states);
  return BlockedVoxelBoxes(g, states, unknown_, VoxelsOverlapping(g, region_W_m));
}

bool MapIntake::NearBlocked(const Eigen::Vector3d& p_W, double clearance_m) const {
  if (!receiver_.has_map()) return false;
  const GridGeometry3& g = receiver_.geometry();
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(clearance_m);
  const CellBox cells = VoxelsOverlapping(g, Eigen::AlignedBox3d(p_W - r, p_W + r));
  for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz) {
    for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy) {
      for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) {
        if (!VoxelBlocksPlanner(receiver_.state(ix, iy, iz), unknown_)) continue;
        const Eigen::Vector3d lo = g.origin_W_m + g.resolution_m * Eigen::Vector3d(ix, iy, iz);
        const Eigen::AlignedBox3d voxel(lo, lo + Eigen::Vector3d::Constant(g.resolution_m));
        if (voxel.exteriorDistance(p_W) <= clearance_m) return true;
      }
    }
  }
  return false;
}

}  // namespace topay::planner
