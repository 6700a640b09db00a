#include "procs/msgs/convert_map.h"

#include <cmath>

namespace topay::msgs {
namespace {

bool ToOccupied(std::int8_t value, bool unknown_is_occupied, bool* occupied) {
  if (value == map_update_t::OCCUPIED) *occupied = true;
  else if (value == map_update_t::FREE) *occupied = false;
  else if (value == map_update_t::UNKNOWN) *occupied = unknown_is_occupied;
  else return false;
  return true;
}

bool SameGeometry(const map_update_t& msg, const GridGeometry3& geometry) {
  for (int a = 0; a < 3; ++a) {
    if (msg.dims[a] != geometry.dims(a) || msg.origin_W[a] != geometry.origin_W_m(a)) return false;
  }
  return msg.resolution_m == geometry.resolution_m;
}

}  // namespace

map_update_t ToFullMapMessage(const OccupancyGrid<3>& grid, std::int64_t utime,
                              std::int64_t map_seq) {
  const GridGeometry3& geometry = grid.geometry();
  map_update_t msg;
  msg.utime = utime;
  msg.map_seq = map_seq;
  msg.resolution_m = geometry.resolution_m;
  for (int a = 0; a < 3; ++a) {
    msg.origin_W[a] = geometry.origin_W_m(a);
    msg.dims[a] = geometry.dims(a);
  }
  msg.is_full = true;
  msg.num_indices = 0;
  msg.values.resize(grid.cells().size());
  for (std::size_t i = 0; i < grid.cells().size(); ++i) {
    msg.values[i] = grid.cells()[i] != 0 ? map_update_t::OCCUPIED : map_update_t::FREE;
  }
  msg.num_values = static_cast<std::int32_t>(msg.values.size());
  return msg;
}

std::optional<OccupancyGrid<3>> FromFullMapMessage(const map_update_t& msg,
                                                   bool unknown_is_occupied, std::string* error) {
  if (!msg.is_full) {
    *error = "map_update_t.is_full: a delta needs the previous map (ApplyMapDelta)";
    return std::nullopt;
  }
  GridGeometry3 geometry;
  geometry.origin_W_m = {msg.origin_W[0], msg.origin_W[1], msg.origin_W[2]};
  geometry.resolution_m = msg.resolution_m;
  geometry.dims = {msg.dims[0], msg.dims[1], msg.dims[2]};
  try {
    geometry.Validate("map_update_t");
  } catch (const std::exception& e) {
    *error = e.what();
    return std::nullopt;
  }
  if (msg.values.size() != static_cast<std::size_t>(geometry.NumCells())) {
    *error = "map_update_t.values: " + std::to_string(msg.values.size()) + " values for " +
             std::to_string(geometry.NumCells()) + " voxels";
    return std::nullopt;
  }
  OccupancyGrid<3> grid(geometry);
  for (int iz = 0, i = 0; iz < geometry.dims.z(); ++iz) {
    for (int iy = 0; iy < geometry.dims.y(); ++iy) {
      for (int ix = 0; ix < geometry.dims.x(); ++ix, ++i) {
        bool occupied = false;
        if (!ToOccupied(msg.values[i], unknown_is_occupied, &occupied)) {
          *error = "map_update_t.values[" + std::to_string(i) + "]: unknown state";
          return std::nullopt;
        }
        if (occupied) grid.SetOccupied(ix, iy, iz, true);
      }
    }
  }
  return grid;
}

bool ApplyMapDelta(const map_update_t& msg, bool unknown_is_occupied, OccupancyGrid<3>* grid,
                   std::string* error) {
  const GridGeometry3& geometry = grid->geometry();
  if (msg.is_full || !SameGeometry(msg, geometry)) {
    *error = "map_update_t: not a delta of this grid's geometry";
    return false;
  }
  if (msg.indices.size() != msg.values.size()) {
    *error = "map_update_t.indices: must match values";
    return false;
  }
  const std::int64_t nx = geometry.dims.x(), ny = geometry.dims.y();
  for (std::size_t k = 0; k < msg.indices.size(); ++k) {
    bool occupied = false;
    if (msg.indices[k] < 0 || msg.indices[k] >= geometry.NumCells() ||
        !ToOccupied(msg.values[k], unknown_is_occupied, &occupied)) {
      *error = "map_update_t.indices[" + std::to_string(k) + "]: out of range or bad value";
      return false;
    }
  }
  for (std::size_t k = 0; k < msg.indices.size(); ++k) {
    bool occupied = false;
    ToOccupied(msg.values[k], unknown_is_occupied, &occupied);
    const std::int64_t i = msg.indices[k];
    grid->SetOccupied(static_cast<int>(i % nx), static_cast<int>((i / nx) % ny),
                      static_cast<int>(i / (nx * ny)), occupied);
  }
  return true;
}

}  // namespace topay::msgs
