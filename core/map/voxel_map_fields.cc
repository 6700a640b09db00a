#include "core/map/voxel_map_fields.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/map/box_cell_overlap.h"

namespace topay {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void RequirePositive(double value, const char* name) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("VoxelMapFieldsOptions: ") + name +
                                " must be finite and > 0, got " + std::to_string(value));
  }
}

// Validates the options (naming the field at fault) and returns them.
const VoxelMapFieldsOptions& Validated(const VoxelMapFieldsOptions& options) {
  RequirePositive(options.resolution_m, "resolution_m");
  RequirePositive(options.field_3d_cap_m, "field_3d_cap_m");
  RequirePositive(options.base_resolution_m, "base_resolution_m");
  RequirePositive(options.base_cap_m, "base_cap_m");
  ValidateSignedDistanceFieldOptions(options.field);
  ValidateBand(options.base_band, "VoxelMapFieldsOptions: base_band");
  if (options.base_upper_band) {
    ValidateBand(*options.base_upper_band, "VoxelMapFieldsOptions: base_upper_band");
  }
  if (!(std::isfinite(options.base_upper_band_offset_m) &&
        options.base_upper_band_offset_m >= 0.0)) {
    throw std::invalid_argument(
        "VoxelMapFieldsOptions: base_upper_band_offset_m must be finite and >= 0, got " +
        std::to_string(options.base_upper_band_offset_m));
  }
  if (options.tile_voxels < 1) {
    throw std::invalid_argument("VoxelMapFieldsOptions: tile_voxels must be >= 1");
  }
  if (static_cast<int>(options.unknown) < 0 || static_cast<int>(options.unknown) > 2 ||
      static_cast<int>(options.initial_state) > 2) {
    throw std::invalid_argument("VoxelMapFieldsOptions: unknown policy or initial_state invalid");
  }
  return options;
}

GridGeometry2 BaseGeometryOf(const VoxelMapFieldsOptions& options) {
  const Eigen::AlignedBox3d& b = options.bounds_W_m;
  return GridGeometry2::FromBounds(Eigen::AlignedBox2d(b.min().head<2>(), b.max().head<2>()),
                                   options.base_resolution_m);
}

CellRange LayersOf(const HeightBand& band, const GridGeometry3& g) {
  return CellsOverlapping(band.z_min_m, band.z_max_m, g.origin_W_m.z(), g.resolution_m, g.dims.z());
}

// The initial 3D field: every value at the cap (no obstacle), the EDT field's margin.
SignedDistanceField3 InitialField3d(const GridGeometry3& g, const VoxelMapFieldsOptions& options) {
  return SignedDistanceField3::FromCellValues(
      g, std::vector<float>(g.NumCells(), static_cast<float>(options.field_3d_cap_m)),
      options.field_3d_cap_m, std::sqrt(3.0) * g.resolution_m);
}

// The initial 2D field: the base band's field, lowered by the upper band's if set, so that it
// holds a primary band and declares its offset band as BuildSceneDistanceFields does.
SignedDistanceField2 InitialField2d(const GridGeometry2& g, const VoxelMapFieldsOptions& options) {
  auto empty = [&] {
    return SignedDistanceField2::FromCellValues(
        g, std::vector<float>(g.NumCells(), static_cast<float>(options.base_cap_m)),
        options.base_cap_m, g.resolution_m / std::sqrt(2.0));
  };
  SignedDistanceField2 field = empty();
  if (options.base_upper_band) {
    field.LowerTo(empty(), options.base_upper_band_offset_m);
    field.set_offset_band({*options.base_upper_band, options.base_upper_band_offset_m});
  }
  return field;
}

}  // namespace

VoxelMapFieldsOptions VoxelMapFieldsOptionsFrom(const SceneDistanceFieldsOptions& scene_options,
                                                const Eigen::AlignedBox3d& bounds_W_m) {
  VoxelMapFieldsOptions options;
  options.bounds_W_m = bounds_W_m;
  options.resolution_m = scene_options.resolution_m;
  options.field = scene_options.field;
  options.base_resolution_m = scene_options.base_resolution_m > 0.0
                                  ? scene_options.base_resolution_m
                                  : scene_options.resolution_m;
  options.base_cap_m = scene_options.base_exact_cap_m > 0.0 ? scene_options.base_exact_cap_m : 1.0;
  options.base_band = scene_options.base_band;
  options.base_upper_band = scene_options.base_upper_band;
  options.base_upper_band_offset_m = scene_options.base_upper_band_offset_m;
  if (options.base_upper_band) {
    // The band's top holds the box-built 3D field's margin (PlannerFieldOptions); this map's
    // 3D field is an EDT one, so the base must stay out from under what lies the difference
    // higher (none unless the box-built field is exact).
    SceneDistanceFieldsOptions edt = scene_options;
    edt.arm_exact_cap_m = 0.0;
    options.base_upper_band->z_max_m += ArmFieldMargin(edt) - ArmFieldMargin(scene_options);
  }
  return options;
}

VoxelMapFields::VoxelMapFields(const VoxelMapFieldsOptions& options)
    : options_(Validated(options)),
      occupancy_3d_(GridGeometry3::FromBounds(options.bounds_W_m, options.resolution_m)),
      base_columns_(GridGeometry2::FootprintOf(occupancy_3d_.geometry())),
      base_layers_(LayersOf(options.base_band, occupancy_3d_.geometry())),
      field_3d_(InitialField3d(occupancy_3d_.geometry(), options)),
      base_field_2d_(InitialField2d(BaseGeometryOf(options), options)) {
  states_.assign(static_cast<std::size_t>(geometry().NumCells()),
                 static_cast<std::uint8_t>(options.initial_state));
  if (options.base_upper_band) {
    upper_columns_.emplace(base_columns_.geometry());
    upper_layers_ = LayersOf(*options.base_upper_band, geometry());
    upper_values_.assign(static_cast<std::size_t>(base_geometry().NumCells()), 0.0f);
  }
  RebuildAll();
}

bool VoxelMapFields::Occupied3d(std::uint8_t state) const {
  return state == static_cast<std::uint8_t>(VoxelState::kOccupied) ||
         (state == static_cast<std::uint8_t>(VoxelState::kUnknown) &&
          options_.unknown == UnknownVoxelPolicy::kOccupied);
}

bool VoxelMapFields::OccupiedInBands(std::uint8_t state) const {
  return state == static_cast<std::uint8_t>(VoxelState::kOccupied) ||
         (state == static_cast<std::uint8_t>(VoxelState::kUnknown) &&
          options_.unknown != UnknownVoxelPolicy::kFree);
}

void VoxelMapFields::RecomputeColumns() {
  const GridGeometry3& g = geometry();
  std::vector<Eigen::Vector3i> ignored;
  for (int iy = 0; iy < g.dims.y(); ++iy) {
    for (int ix = 0; ix < g.dims.x(); ++ix) {
      UpdateColumn(base_layers_, ix, iy, &base_columns_, &ignored);
      if (upper_columns_) UpdateColumn(upper_layers_, ix, iy, &*upper_columns_, &ignored);
    }
  }
}

void VoxelMapFields::RebuildAll() {
  // The voxels as each field counts them.
  const GridGeometry3& g = geometry();
  for (int iz = 0; iz < g.dims.z(); ++iz) {
    for (int iy = 0; iy < g.dims.y(); ++iy) {
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        occupancy_3d_.SetOccupied(ix, iy, iz, Occupied3d(states_[g.Index(ix, iy, iz)]));
      }
    }
  }
  RecomputeColumns();
  // The 3D field over the whole grid (in place), then the 2D field's bands and their lowering.
  RecomputeSignedDistanceWindow(occupancy_3d_.cells().data(), g.dims, 3, g.resolution_m,
                                options_.field_3d_cap_m, options_.field,
                                CellBox{Eigen::Vector3i::Zero(), g.dims}, &window_workspace_,
                                field_3d_.mutable_values()->data());
  const GridGeometry2& fg = base_geometry();
  const CellBox all{Eigen::Vector3i::Zero(), Eigen::Vector3i(fg.dims.x(), fg.dims.y(), 1)};
  if (!upper_columns_) {
    FillColumnDistanceWindow(base_columns_, fg, all, options_.base_cap_m, &column_workspace_,
                             base_field_2d_.mutable_values()->data());
    return;
  }
  FillColumnDistanceWindow(base_columns_, fg, all, options_.base_cap_m, &column_workspace_,
                           base_field_2d_.mutable_primary_band_values()->data());
  FillColumnDistanceWindow(*upper_columns_, fg, all, options_.base_cap_m, &column_workspace_,
                           upper_values_.data());
  LowerWindow(all);
}

void VoxelMapFields::UpdateColumn(const CellRange& layers, int ix, int iy, OccupancyGrid2* columns,
                                  std::vector<Eigen::Vector3i>* changed) const {
  bool occupied = false;
  for (int iz = layers.begin; iz < layers.end && !occupied; ++iz) {
    occupied = OccupiedInBands(states_[geometry().Index(ix, iy, iz)]);
  }
  if (occupied == columns->IsOccupied(ix, iy)) return;
  columns->SetOccupied(ix, iy, occupied);
  changed->emplace_back(ix, iy, 0);
}

void VoxelMapFields::ValidateChanges(std::span<const VoxelChange> changes) const {
  const Eigen::Vector3i& dims = geometry().dims;
  for (std::size_t i = 0; i < changes.size(); ++i) {
    const Eigen::Vector3i& v = changes[i].voxel;
    if ((v.array() < 0).any() || (v.array() >= dims.array()).any()) {
      throw std::invalid_argument(
          "VoxelMapFields::ApplyChanges: change " + std::to_string(i) + ": voxel (" +
          std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " + std::to_string(v.z()) +
          ") outside the grid of " + std::to_string(dims.x()) + " x " + std::to_string(dims.y()) +
          " x " + std::to_string(dims.z()) + " voxels");
    }
    if (static_cast<std::uint8_t>(changes[i].state) > 2) {
      throw std::invalid_argument("VoxelMapFields::ApplyChanges: change " + std::to_string(i) +
                                  ": state " + std::to_string(static_cast<int>(changes[i].state)) +
                                  " is not a VoxelState (0 free, 1 occupied, 2 unknown)");
    }
  }
}

VoxelMapUpdateSummary VoxelMapFields::ApplyChanges(std::span<const VoxelChange> changes) {
  const Clock::time_point start = Clock::now();
  VoxelMapUpdateSummary summary;
  summary.num_changes = static_cast<int>(changes.size());
  ValidateChanges(changes);
  changed_3d_.clear();
  changed_base_.clear();
  changed_upper_.clear();
  const GridGeometry3& g = geometry();
  for (const VoxelChange& change : changes) {
    const Eigen::Vector3i& v = change.voxel;
    std::uint8_t& state = states_[g.Index(v.x(), v.y(), v.z())];
    const std::uint8_t old_state = state;
    state = static_cast<std::uint8_t>(change.state);
    if (state == old_state) continue;
    ++summary.num_voxels_changed;
    if (Occupied3d(state) != Occupied3d(old_state)) {
      occupancy_3d_.SetOccupied(v.x(), v.y(), v.z(), Occupied3d(state));
      changed_3d_.push_back(v);
    }
    if (OccupiedInBands(state) == OccupiedInBands(old_state)) continue;
    auto in = [&v](const CellRange& layers) { return v.z() >= layers.begin && v.z() < layers.end; };
    if (in(base_layers_)) UpdateColumn(base_layers_, v.x(), v.y(), &base_columns_, &changed_base_);
    if (upper_columns_ && in(upper_layers_)) {
      UpdateColumn(upper_layers_, v.x(), v.y(), &*upper_columns_, &changed_upper_);
    }
  }
  summary.num_voxels_changed_3d = static_cast<int>(changed_3d_.size());
  summary.num_columns_changed = static_cast<int>(changed_base_.size() + changed_upper_.size());
  summary.apply_s = SecondsSince(start);
  Clock::time_point phase = Clock::now();
  Update3d(&summary);
  summary.field_3d_s = SecondsSince(phase);
  phase = Clock::now();
  Update2d(&summary);
  summary.field_2d_s = SecondsSince(phase);
  summary.total_s = SecondsSince(start);
  return summary;
}

void VoxelMapFields::Update3d(VoxelMapUpdateSummary* summary) {
  if (changed_3d_.empty()) return;
  const GridGeometry3& g = geometry();
  // Every cell a changed voxel can alter lies within the reach of it (target windows); the
  // recomputation of a window reads the voxels within the reach of it (source windows).
  const Eigen::Vector3i reach =
      Eigen::Vector3i::Constant(SignedDistanceReachCells(options_.field_3d_cap_m, g.resolution_m));
  std::vector<CellBox> windows =
      TileBoundsOfCells(changed_3d_, Eigen::Vector3i::Constant(options_.tile_voxels));
  for (CellBox& window : windows) window = window.Dilated(reach, g.dims);
  windows = MergeCellBoxes(std::move(windows), reach, g.dims);
  float* values = field_3d_.mutable_values()->data();
  for (const CellBox& window : windows) {
    RecomputeSignedDistanceWindow(occupancy_3d_.cells().data(), g.dims, 3, g.resolution_m,
                                  options_.field_3d_cap_m, options_.field, window,
                                  &window_workspace_, values);
    summary->num_cells_3d += window.NumCells();
  }
  summary->num_windows_3d = static_cast<int>(windows.size());
}

std::vector<CellBox> VoxelMapFields::ColumnWindows(
    const std::vector<Eigen::Vector3i>& changed) const {
  const GridGeometry2& fg = base_geometry();
  const Eigen::Vector3i field_dims(fg.dims.x(), fg.dims.y(), 1);
  std::vector<CellBox> windows =
      TileBoundsOfCells(changed, Eigen::Vector3i(options_.tile_voxels, options_.tile_voxels, 1));
  std::vector<CellBox> targets;
  for (const CellBox& columns : windows) {
    const CellBox target =
        FieldCellsNearColumns(base_columns_.geometry(), columns, fg, options_.base_cap_m);
    if (!target.empty()) targets.push_back(target);
  }
  // A window's fill reads the columns within the cap plus one column of it.
  const int reach = static_cast<int>(std::ceil((options_.base_cap_m + geometry().resolution_m) /
                                               fg.resolution_m)) +
                    1;
  return MergeCellBoxes(std::move(targets), Eigen::Vector3i(reach, reach, 0), field_dims);
}

void VoxelMapFields::LowerWindow(const CellBox& window) {
  const GridGeometry2& fg = base_geometry();
  const double offset_m = options_.base_upper_band_offset_m;
  float* lowered = base_field_2d_.mutable_values()->data();
  const float* primary = base_field_2d_.mutable_primary_band_values()->data();
  for (int iy = window.begin.y(); iy < window.end.y(); ++iy) {
    for (std::int64_t i = fg.Index(window.begin.x(), iy), end = fg.Index(window.end.x(), iy);
         i < end; ++i) {
      // The expression of SignedDistanceField2::LowerTo, so the values match it bitwise.
      lowered[i] = std::min(primary[i], static_cast<float>(upper_values_[i] + offset_m));
    }
  }
}

void VoxelMapFields::Update2d(VoxelMapUpdateSummary* summary) {
  if (changed_base_.empty() && changed_upper_.empty()) return;
  const GridGeometry2& fg = base_geometry();
  const double cap_m = options_.base_cap_m;
  const std::vector<CellBox> base_windows = ColumnWindows(changed_base_);
  float* base_values = upper_columns_ ? base_field_2d_.mutable_primary_band_values()->data()
                                      : base_field_2d_.mutable_values()->data();
  for (const CellBox& window : base_windows) {
    FillColumnDistanceWindow(base_columns_, fg, window, cap_m, &column_workspace_, base_values);
    summary->num_cells_2d += window.NumCells();
  }
  summary->num_windows_2d += static_cast<int>(base_windows.size());
  if (!upper_columns_) return;
  const std::vector<CellBox> upper_windows = ColumnWindows(changed_upper_);
  for (const CellBox& window : upper_windows) {
    FillColumnDistanceWindow(*upper_columns_, fg, window, cap_m, &column_workspace_,
                             upper_values_.data());
    summary->num_cells_2d += window.NumCells();
  }
  summary->num_windows_2d += static_cast<int>(upper_windows.size());
  // The lowered field wherever either band changed.
  for (const CellBox& window : base_windows) LowerWindow(window);
  for (const CellBox& window : upper_windows) LowerWindow(window);
}

void VoxelMapFields::ResetFrom(const OccupancyGrid3& occupied) {
  const GridGeometry3& g = occupied.geometry();
  if (g.dims != geometry().dims || g.resolution_m != geometry().resolution_m ||
      g.origin_W_m != geometry().origin_W_m) {
    throw std::invalid_argument("VoxelMapFields::ResetFrom: the grid's geometry is not the map's");
  }
  for (std::size_t i = 0; i < states_.size(); ++i) {
    states_[i] =
        static_cast<std::uint8_t>(occupied.cells()[i] ? VoxelState::kOccupied : VoxelState::kFree);
  }
  RebuildAll();
}

void VoxelMapFields::ResetStates(std::span<const std::uint8_t> states) {
  if (states.size() != states_.size()) {
    throw std::invalid_argument("VoxelMapFields::ResetStates: " + std::to_string(states.size()) +
                                " states for a map of " + std::to_string(states_.size()) + " voxels");
  }
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states[i] > static_cast<std::uint8_t>(VoxelState::kUnknown)) {
      throw std::invalid_argument("VoxelMapFields::ResetStates: voxel " + std::to_string(i) +
                                  " has state " + std::to_string(states[i]) + ", not a VoxelState");
    }
  }
  std::copy(states.begin(), states.end(), states_.begin());
  RebuildAll();
}

VoxelChange VoxelMapFields::ChangeAt(const Eigen::Vector3d& p_W, VoxelState state) const {
  if (!p_W.allFinite()) {
    throw std::invalid_argument("VoxelMapFields::ChangeAt: point has a NaN or infinite coordinate");
  }
  if (!geometry().Contains(p_W)) {
    throw std::invalid_argument("VoxelMapFields::ChangeAt: point (" + std::to_string(p_W.x()) +
                                ", " + std::to_string(p_W.y()) + ", " + std::to_string(p_W.z()) +
                                ") outside the map's volume");
  }
  const Eigen::Vector3i voxel =
      geometry().CellOf(p_W).cwiseMax(0).cwiseMin(geometry().dims - Eigen::Vector3i::Ones());
  return {voxel, state};
}

}  // namespace topay
