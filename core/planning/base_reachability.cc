#include "core/planning/base_reachability.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/oriented_box.h"
#include "core/map/grid_geometry.h"
#include "core/planning/base_band.h"
#include "core/robot/whole_body_ik.h"

namespace topay {
namespace {

// A rigid sphere as the test needs it: centre height, radius, horizontal centre offset bound.
struct RigidSphere {
  double z_m, radius_m, offset_m;
};

std::vector<RigidSphere> RigidSpheres(const RigidLowerBody& body) {
  std::vector<RigidSphere> spheres;
  for (const RigidLowerBody::Sphere& s : body.spheres) {
    const double r = 0.5 * (s.top_m - s.bottom_m);
    spheres.push_back({0.5 * (s.top_m + s.bottom_m), r, std::max(0.0, s.reach_m - r)});
  }
  return spheres;
}

// The least signed footprint distance d_b(p) any allowed base centre p has from `box`
// (-infinity: the box constrains nothing).
double RequiredDistance(const OrientedBox& box, const BaseCylinder& chassis,
                        const std::vector<RigidSphere>& spheres) {
  const double z_min = box.center_W_m.z() - 0.5 * box.size_m.z();
  const double z_max = box.center_W_m.z() + 0.5 * box.size_m.z();
  double need = -std::numeric_limits<double>::infinity();
  if (z_min < chassis.height_m && z_max > 0.0) need = chassis.radius_m;
  for (const RigidSphere& s : spheres) {
    const double gap = std::max({0.0, z_min - s.z_m, s.z_m - z_max});
    if (gap >= s.radius_m) continue;
    need = std::max(need, std::sqrt(s.radius_m * s.radius_m - gap * gap) - s.offset_m);
  }
  return need;
}

// Clears allowed[] on the cells whose centre is closer to `box` than need - slack.
void MarkBlocked(const GridGeometry2& g, const OrientedBox& box, double need, double slack,
                 std::vector<std::uint8_t>* allowed) {
  const Eigen::AlignedBox3d bounds = box.WorldBounds();
  const double pad = std::max(need, 0.0) + g.resolution_m;
  const Eigen::Vector2i lo = g.CellOf(bounds.min().head<2>() - Eigen::Vector2d::Constant(pad));
  const Eigen::Vector2i hi = g.CellOf(bounds.max().head<2>() + Eigen::Vector2d::Constant(pad));
  for (int iy = std::max(lo.y(), 0); iy <= std::min(hi.y(), g.dims.y() - 1); ++iy) {
    for (int ix = std::max(lo.x(), 0); ix <= std::min(hi.x(), g.dims.x() - 1); ++ix) {
      if (SignedDistanceToFootprint(box, g.CellCenter(ix, iy)) < need - slack) {
        (*allowed)[g.Index(ix, iy)] = 0;
      }
    }
  }
}

// 8-connected flood fill over allowed cells from `seed`; with join_outside, the outside of
// the grid joins all allowed border cells (the first time a border cell is reached, all of
// them are queued).
std::vector<std::uint8_t> FloodFill(const GridGeometry2& g, const std::vector<std::uint8_t>& allowed,
                                    const Eigen::Vector2i& seed, bool join_outside = true) {
  const int nx = g.dims.x(), ny = g.dims.y();
  std::vector<std::uint8_t> reached(allowed.size(), 0);
  std::vector<Eigen::Vector2i> stack;
  auto push = [&](int ix, int iy) {
    const std::int64_t i = g.Index(ix, iy);
    if (allowed[i] == 0 || reached[i] != 0) return;
    reached[i] = 1;
    stack.emplace_back(ix, iy);
  };
  bool outside_joined = false;
  push(seed.x(), seed.y());
  while (!stack.empty()) {
    const Eigen::Vector2i c = stack.back();
    stack.pop_back();
    const bool on_border = c.x() == 0 || c.y() == 0 || c.x() == nx - 1 || c.y() == ny - 1;
    if (join_outside && on_border && !outside_joined) {
      outside_joined = true;
      for (int ix = 0; ix < nx; ++ix) { push(ix, 0); push(ix, ny - 1); }
      for (int iy = 0; iy < ny; ++iy) { push(0, iy); push(nx - 1, iy); }
    }
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int ix = c.x() + dx, iy = c.y() + dy;
        if (ix >= 0 && iy >= 0 && ix < nx && iy < ny) push(ix, iy);
      }
    }
  }
  return reached;
}

// True if a border cell was reached (then the free outside of the grid was too).
bool ReachesOutside(const GridGeometry2& g, const std::vector<std::uint8_t>& reached) {
  const int nx = g.dims.x(), ny = g.dims.y();
  for (int ix = 0; ix < nx; ++ix) {
    if (reached[g.Index(ix, 0)] != 0 || reached[g.Index(ix, ny - 1)] != 0) return true;
  }
  for (int iy = 0; iy < ny; ++iy) {
    if (reached[g.Index(0, iy)] != 0 || reached[g.Index(nx - 1, iy)] != 0) return true;
  }
  return false;
}

// True if the goal's cell, or a cell whose centre is within radius_m of p_goal, was reached,
// or the disc leaves the grid and the fill reached the outside.
bool ReachesGoalDisc(const GridGeometry2& g, const std::vector<std::uint8_t>& reached,
                     const Eigen::Vector2i& goal_cell, const Eigen::Vector2d& p_goal,
                     double radius_m) {
  if (reached[g.Index(goal_cell.x(), goal_cell.y())] != 0) return true;
  const Eigen::AlignedBox2d bounds = g.Bounds();
  const Eigen::Vector2d r(radius_m, radius_m);
  if (!bounds.contains(Eigen::AlignedBox2d(p_goal - r, p_goal + r)) && ReachesOutside(g, reached)) {
    return true;
  }
  const int span = static_cast<int>(std::ceil(radius_m / g.resolution_m)) + 1;
  for (int y = std::max(goal_cell.y() - span, 0); y <= std::min(goal_cell.y() + span, g.dims.y() - 1); ++y) {
    for (int x = std::max(goal_cell.x() - span, 0); x <= std::min(goal_cell.x() + span, g.dims.x() - 1); ++x) {
      if (reached[g.Index(x, y)] != 0 && (g.CellCenter(x, y) - p_goal).norm() <= radius_m) {
        return true;
      }
    }
  }
  return false;
}

// Cells a base centre may occupy, for every box of the scene (see CertifyBaseUnreachable).
std::vector<std::uint8_t> AllowedCells(const Scene& scene, const Kinematics& kinematics,
                                       const GridGeometry2& g, double slack) {
  const BaseCylinder& chassis = kinematics.model().base_cylinder;
  const std::vector<RigidSphere> spheres = RigidSpheres(RigidLowerBodyOf(kinematics));
  std::vector<std::uint8_t> allowed(static_cast<std::size_t>(g.NumCells()), 1);
  for (const OrientedBox& box : scene.boxes) {
    const double need = RequiredDistance(box, chassis, spheres);
    if (std::isfinite(need)) MarkBlocked(g, box, need, slack, &allowed);
  }
  return allowed;
}

// CertifyBaseOpen's cells: those keeping every needed distance + the clearance everywhere
// in them, and within the approach radius of each of `ends` CertifyBaseEnclosed's lenient
// ones.
std::vector<std::uint8_t> OpenCells(const Scene& scene, const Kinematics& kinematics,
                                    const GridGeometry2& g, const BaseOpennessOptions& openness,
                                    const std::vector<Eigen::Vector2d>& ends) {
  const double half_diagonal = g.resolution_m / std::sqrt(2.0);
  std::vector<std::uint8_t> allowed =
      AllowedCells(scene, kinematics, g, -(openness.clearance_m + half_diagonal));
  const std::vector<std::uint8_t> lenient = AllowedCells(scene, kinematics, g, half_diagonal);
  const int span = static_cast<int>(std::ceil(openness.approach_radius_m / g.resolution_m)) + 1;
  for (const Eigen::Vector2d& p : ends) {
    const Eigen::Vector2i c = g.CellOf(p);
    for (int iy = std::max(c.y() - span, 0); iy <= std::min(c.y() + span, g.dims.y() - 1); ++iy) {
      for (int ix = std::max(c.x() - span, 0); ix <= std::min(c.x() + span, g.dims.x() - 1);
           ++ix) {
        if ((g.CellCenter(ix, iy) - p).norm() <= openness.approach_radius_m) {
          allowed[g.Index(ix, iy)] = lenient[g.Index(ix, iy)];
        }
      }
    }
  }
  return allowed;
}

void CheckOpenness(const char* name, const BaseOpennessOptions& openness) {
  if (!(openness.clearance_m >= 0.0) || !std::isfinite(openness.clearance_m) ||
      !(openness.approach_radius_m >= 0.0) || !std::isfinite(openness.approach_radius_m)) {
    throw std::invalid_argument(std::string(name) +
                                ": clearance_m and approach_radius_m must be finite and >= 0");
  }
}

// The grid of a window of half side window_m around p_WB_m: cells of CertifyBaseUnreachable's
// grid (from the scene bounds' minimum corner), so every test sees the same cells.
GridGeometry2 WindowGrid(const Scene& scene, const Eigen::Vector2d& p_WB_m, double window_m,
                         double res) {
  const Eigen::Vector2d origin = scene.bounds_W_m.min().head<2>();
  const Eigen::Vector2d lo =
      origin + res * ((p_WB_m.array() - window_m - origin.array()) / res).floor().matrix();
  const Eigen::Vector2d hi =
      origin + res * ((p_WB_m.array() + window_m - origin.array()) / res).ceil().matrix();
  return GridGeometry2::FromBounds(Eigen::AlignedBox2d(lo, hi), res);
}

// The flood fill of a window's allowed cells from p's cell: true if it reaches the border
// (the way out); out->component_cells gets the cells reached, 0 with out->reason set if p's
// own cell is not allowed.
bool LeavesWindow(const GridGeometry2& g, const std::vector<std::uint8_t>& allowed,
                  const Eigen::Vector2d& p_m, BaseReachability* out) {
  const Eigen::Vector2i cell = g.CellOf(p_m);
  if (allowed[g.Index(cell.x(), cell.y())] == 0) {
    out->reason = "the position is not allowed (the rigid lower body is in collision)";
    return false;
  }
  const std::vector<std::uint8_t> reached = FloodFill(g, allowed, cell);
  for (std::uint8_t r : reached) out->component_cells += r;
  return ReachesOutside(g, reached);
}

void CheckWindowInputs(const char* name, const Eigen::Vector2d& p_WB_m, double window_m,
                       const BaseReachabilityOptions& options) {
  if (!p_WB_m.allFinite() || !(window_m > 0.0) || !std::isfinite(window_m) ||
      !(options.resolution_m > 0.0)) {
    throw std::invalid_argument(std::string(name) +
                                ": need a finite position, window_m > 0 and resolution_m > 0");
  }
}

}  // namespace

BaseReachability CertifyBaseEnclosed(const Scene& scene, const Kinematics& kinematics,
                                     const Eigen::Vector2d& p_WB_m, double window_m,
                                     const BaseReachabilityOptions& options) {
  CheckWindowInputs("CertifyBaseEnclosed", p_WB_m, window_m, options);
  const GridGeometry2 g = WindowGrid(scene, p_WB_m, window_m, options.resolution_m);
  const double slack = options.resolution_m / std::sqrt(2.0);
  BaseReachability out;
  out.certified_unreachable =
      !LeavesWindow(g, AllowedCells(scene, kinematics, g, slack), p_WB_m, &out);
  if (out.component_cells == 0) return out;
  out.reason = out.certified_unreachable
                   ? "shut in a pocket of " + std::to_string(out.component_cells) +
                         " cells inside the window"
                   : "the base can leave the window";
  return out;
}

BaseReachability CertifyBaseOpen(const Scene& scene, const Kinematics& kinematics,
                                 const Eigen::Vector2d& p_WB_m, double window_m,
                                 const BaseOpennessOptions& openness,
                                 const BaseReachabilityOptions& options) {
  CheckWindowInputs("CertifyBaseOpen", p_WB_m, window_m, options);
  CheckOpenness("CertifyBaseOpen", openness);
  const GridGeometry2 g = WindowGrid(scene, p_WB_m, window_m, options.resolution_m);
  // Every point of a cell whose centre keeps need + clearance + half a diagonal keeps
  // need + clearance (each footprint distance is 1-Lipschitz); near the position itself, the
  // lenient cells of CertifyBaseEnclosed.
  BaseReachability out;  // certified_unreachable here: "not proven open"
  out.certified_unreachable =
      !LeavesWindow(g, OpenCells(scene, kinematics, g, openness, {p_WB_m}), p_WB_m, &out);
  if (out.component_cells == 0) return out;
  out.reason = out.certified_unreachable
                   ? "no way out of the window with the clearance (" +
                         std::to_string(out.component_cells) + " cells reached)"
                   : "the base can leave the window with the clearance";
  return out;
}

ProvenBaseRegion::ProvenBaseRegion(const Scene& scene, const Kinematics& kinematics,
                                   const Eigen::Vector2d& p_start_m,
                                   const BaseOpennessOptions& openness,
                                   const BaseReachabilityOptions& options)
    : scene_(&scene),
      kinematics_(&kinematics),
      openness_(openness),
      grid_(GridGeometry2::FromBounds(Eigen::AlignedBox2d(scene.bounds_W_m.min().head<2>(),
                                                          scene.bounds_W_m.max().head<2>()),
                                      options.resolution_m)) {
  CheckOpenness("ProvenBaseRegion", openness);
  if (!p_start_m.allFinite() || !(options.resolution_m > 0.0)) {
    throw std::invalid_argument(
        "ProvenBaseRegion: need a finite start and resolution_m > 0");
  }
  if (!grid_.Contains(p_start_m)) return;
  const std::vector<std::uint8_t> allowed =
      OpenCells(scene, kinematics, grid_, openness, {p_start_m});
  const Eigen::Vector2i cell = grid_.CellOf(p_start_m);
  if (allowed[grid_.Index(cell.x(), cell.y())] == 0) return;
  reached_ = FloodFill(grid_, allowed, cell);
  for (std::uint8_t r : reached_) num_cells_ += r;
}

bool ProvenBaseRegion::Reaches(const Eigen::Vector2d& p_m) const {
  if (reached_.empty() || !p_m.allFinite() || !grid_.Contains(p_m)) return false;
  // The end's approach: lenient cells within approach_radius_m of it, filled from its cell;
  // joined if one of them was reached from the start (or lies next to such a cell).
  const double res = grid_.resolution_m;
  const GridGeometry2 local =
      WindowGrid(*scene_, p_m, openness_.approach_radius_m + res, res);
  std::vector<std::uint8_t> approach =
      AllowedCells(*scene_, *kinematics_, local, res / std::sqrt(2.0));
  for (int iy = 0; iy < local.dims.y(); ++iy) {
    for (int ix = 0; ix < local.dims.x(); ++ix) {
      if ((local.CellCenter(ix, iy) - p_m).norm() > openness_.approach_radius_m) {
        approach[local.Index(ix, iy)] = 0;
      }
    }
  }
  const Eigen::Vector2i cell = local.CellOf(p_m);
  if (approach[local.Index(cell.x(), cell.y())] == 0) return false;
  const std::vector<std::uint8_t> filled = FloodFill(local, approach, cell, false);
  for (int iy = 0; iy < local.dims.y(); ++iy) {
    for (int ix = 0; ix < local.dims.x(); ++ix) {
      if (filled[local.Index(ix, iy)] == 0) continue;
      const Eigen::Vector2i global = grid_.CellOf(local.CellCenter(ix, iy));
      // A reached cell of the start's region next to (or at) a filled approach cell.
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int gx = global.x() + dx, gy = global.y() + dy;
          if (gx < 0 || gy < 0 || gx >= grid_.dims.x() || gy >= grid_.dims.y()) continue;
          if (reached_[grid_.Index(gx, gy)] != 0) return true;
        }
      }
    }
  }
  return false;
}

BaseReachability CertifyBaseUnreachable(const Scene& scene, const Kinematics& kinematics,
                                        const Eigen::Vector2d& p_WB_start_m,
                                        const Eigen::Vector2d& p_WB_goal_m,
                                        const BaseReachabilityOptions& options) {
  if (!p_WB_start_m.allFinite() || !p_WB_goal_m.allFinite()) {
    throw std::invalid_argument("CertifyBaseUnreachable: start or goal position is not finite");
  }
  if (!(options.resolution_m > 0.0) || !(options.goal_radius_m >= 0.0) ||
      !std::isfinite(options.goal_radius_m)) {
    throw std::invalid_argument(
        "CertifyBaseUnreachable: resolution_m must be > 0 and goal_radius_m finite and >= 0");
  }
  const Eigen::AlignedBox2d bounds(scene.bounds_W_m.min().head<2>(),
                                   scene.bounds_W_m.max().head<2>());
  const GridGeometry2 g = GridGeometry2::FromBounds(bounds, options.resolution_m);
  BaseReachability out;
  if (!g.Contains(p_WB_start_m) || !g.Contains(p_WB_goal_m)) {
    out.reason = "start or goal outside the scene's bounds: not tested";
    return out;
  }
  const double slack = options.resolution_m / std::sqrt(2.0);
  const std::vector<std::uint8_t> allowed = AllowedCells(scene, kinematics, g, slack);
  const Eigen::Vector2i start = g.CellOf(p_WB_start_m), goal = g.CellOf(p_WB_goal_m);
  if (allowed[g.Index(start.x(), start.y())] == 0) {
    out.certified_unreachable = true;
    out.reason = "the start position is not allowed (the rigid lower body is in collision)";
    return out;
  }
  const std::vector<std::uint8_t> reached = FloodFill(g, allowed, start);
  for (std::uint8_t r : reached) out.component_cells += r;
  out.certified_unreachable = !ReachesGoalDisc(g, reached, goal, p_WB_goal_m,
                                                options.goal_radius_m + slack);
  out.reason = out.certified_unreachable
                   ? "no chain of cells the rigid lower body could occupy joins start and goal (" +
                         std::to_string(out.component_cells) + " cells reached from the start)"
                   : "start and goal are in one component of the rigid lower body's free space";
  return out;
}

BaseReachability CertifyTargetUnreachable(const Scene& scene, const Kinematics& kinematics,
                                          const Eigen::Vector2d& p_WB_start_m,
                                          const Eigen::Isometry3d& X_WE_target,
                                          BaseReachabilityOptions options) {
  if (!X_WE_target.matrix().allFinite()) {
    throw std::invalid_argument("CertifyTargetUnreachable: target pose is not finite");
  }
  const WholeBodyIk ik(kinematics);
  const Eigen::Vector3d p_W_wrist = X_WE_target * ik.p_EW();
  options.goal_radius_m += ik.p_BS().head<2>().norm() + ik.shoulder_to_wrist_reach_m();
  return CertifyBaseUnreachable(scene, kinematics, p_WB_start_m, p_W_wrist.head<2>(), options);
}

}  // namespace topay
