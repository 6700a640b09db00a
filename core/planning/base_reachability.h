#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/map/grid_geometry.h"
#include "core/robot/kinematics.h"

namespace topay {

/// Options of CertifyBaseUnreachable.
struct BaseReachabilityOptions {
  double resolution_m = 0.01;  ///< Cell size of the test grid over the scene's xy bounds.
  /// The goal is every base position within this distance (m) of the goal position, not just
  /// the goal position: certified only when the start's component reaches none of them.
  double goal_radius_m = 0.0;
};

/// What CertifyBaseUnreachable found.
struct BaseReachability {
  /// True only when no collision-free motion of the robot's rigid lower body joins start and
  /// goal, whatever the planner: the task cannot be solved. False means "not excluded" (the
  /// task may still be unsolvable for reasons the test does not see, e.g. the arm).
  bool certified_unreachable = false;
  std::int64_t component_cells = 0;  ///< Cells reached from the start's cell.
  std::string reason;                ///< Readable account of the verdict.
};

/// A planner-independent test of a task's base connectivity, used by the benchmarks to tell
/// unsolvable generated tasks from planner failures (the paper's protocol does not exclude
/// them). It looks only at what every motion must satisfy, for upright scene boxes (yaw only):
///  - the chassis cylinder (radius R, floor to top) clear of every box whose z extent meets
///    it: the exact xy signed distance d_b(p) from the base centre p to the box's footprint is
///    >= R;
///  - each rigid sphere (core/planning/base_band.h: centre height z, radius r, centre within o
///    of the base axis at every yaw) clear of every box at vertical gap g < r from z: its
///    centre c is at least rho = sqrt(r^2 - g^2) from the footprint in xy, so d_b(p) >= rho - o.
/// Certificate: each d_b is 1-Lipschitz, so every allowed p lies in a cell whose centre meets
/// every bound less resolution / sqrt(2). A motion is a continuous curve of allowed p, so it
/// visits a chain of 8-neighbouring such cells; if the flood fill from the start's cell misses
/// the goal's cell (and every cell meeting the goal disc), no motion exists (yaw and arm are free in the test, so it only ever
/// under-claims). The outside of the grid counts as free and joins every border cell the fill
/// may enter, so scenes without walls are never falsely certified. Start or goal outside the
/// grid: not certified. Throws std::invalid_argument for a non-finite position or
/// resolution <= 0.
BaseReachability CertifyBaseUnreachable(const Scene& scene, const Kinematics& kinematics,
                                        const Eigen::Vector2d& p_WB_start_m,
                                        const Eigen::Vector2d& p_WB_goal_m,
                                        const BaseReachabilityOptions& options = {});

/// The same certificate, local: whether the base at p_WB_m is shut in a pocket, i.e. no motion
/// of the rigid lower body takes its centre out of the square of half side window_m around
/// p_WB_m. The grid covers only that square, grown to whole cells of CertifyBaseUnreachable's
/// grid (the same cells: options.resolution_m from the scene bounds' minimum corner;
/// goal_radius_m unused);
/// certified when the flood fill from the base's cell reaches no border cell (every motion
/// leaving the square passes through one). Cheap (the square's cells, not the room's), so a
/// task generator can reject ends it places where the robot could not have driven to. A
/// position whose own cell is not allowed is certified too (the rigid lower body collides).
/// Throws std::invalid_argument for a non-finite position, window_m <= 0 or resolution <= 0.
BaseReachability CertifyBaseEnclosed(const Scene& scene, const Kinematics& kinematics,
                                     const Eigen::Vector2d& p_WB_m, double window_m,
                                     const BaseReachabilityOptions& options = {});

/// Options of CertifyBaseOpen.
struct BaseOpennessOptions {
  /// Extra clearance (m) every needed footprint distance must keep along the way out (the
  /// base cylinder's radius, each rigid sphere's bound): a passage only this much wider
  /// than the robot counts. >= 0.
  double clearance_m = 0.01;
  /// Within this distance (m) of the position the way out only needs CertifyBaseEnclosed's
  /// lenient cells (the last stretch into a tight spot). >= 0.
  double approach_radius_m = 0.1;
};

/// The converse of CertifyBaseEnclosed, a proof that the base at p_WB_m can leave the square
/// of half side window_m around it: certified_unreachable is false only if a chain of
/// 8-neighbouring cells joins the position's cell to the window's border such that every
/// point of every cell keeps each needed footprint distance + openness.clearance_m (a cell
/// centre keeps it + resolution / sqrt(2)), except within approach_radius_m of the position,
/// where CertifyBaseEnclosed's cells are taken. The rigid spheres count with their best
/// yaw, as in CertifyBaseEnclosed. For task generators: an end it does not prove open lies in
/// a pocket, or behind a passage within a centimetre of the base's width, that no robot
/// would be driven through. Throws std::invalid_argument for a non-finite position,
/// window_m <= 0, resolution_m <= 0 or openness values out of range.
BaseReachability CertifyBaseOpen(const Scene& scene, const Kinematics& kinematics,
                                 const Eigen::Vector2d& p_WB_m, double window_m,
                                 const BaseOpennessOptions& openness = {},
                                 const BaseReachabilityOptions& options = {});

/// The base positions a base at p_start_m is proven able to reach over the whole scene with
/// CertifyBaseOpen's clearance (and its lenient approach disc around the start): the flood
/// fill of those cells over the scene's xy bounds, once; Reaches(p) then joins p's own
/// approach disc to it. For tight task generators: an end the other cannot reach through
/// passages with a centimetre to spare is redrawn. About a room grid's cells in time and
/// bytes (20 x 20 m at 1 cm: 4 M). Throws std::invalid_argument for a non-finite start,
/// resolution_m <= 0 or openness values out of range.
class ProvenBaseRegion {
 public:
  /// The scene and the kinematics must outlive this object.
  ProvenBaseRegion(const Scene& scene, const Kinematics& kinematics,
                   const Eigen::Vector2d& p_start_m, const BaseOpennessOptions& openness = {},
                   const BaseReachabilityOptions& options = {});
  /// Cells reached from the start (0: the start is outside the bounds or not allowed).
  std::int64_t num_cells() const { return num_cells_; }
  /// True if a chain of cells joins the start to p_m: the region's, then lenient cells within
  /// approach_radius_m of p_m.
  bool Reaches(const Eigen::Vector2d& p_m) const;

 private:
  const Scene* scene_;
  const Kinematics* kinematics_;
  BaseOpennessOptions openness_;
  GridGeometry2 grid_;
  std::vector<std::uint8_t> reached_;
  std::int64_t num_cells_ = 0;
};

/// The same test for an end-effector target, whatever goal base pose a planner chooses: the
/// goal disc is centred at the target's wrist centre W (WholeBodyIk::p_EW) with radius
/// |p_BS| + the shoulder-to-wrist reach (triangle-inequality bounds, WholeBodyIk), which
/// holds every base position from which the arm could reach the target. Certified: no base
/// position the start can reach lets the arm touch the target.
BaseReachability CertifyTargetUnreachable(const Scene& scene, const Kinematics& kinematics,
                                          const Eigen::Vector2d& p_WB_start_m,
                                          const Eigen::Isometry3d& X_WE_target,
                                          BaseReachabilityOptions options = {});

}  // namespace topay
