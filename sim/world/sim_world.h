#pragma once
// The simulated world: the scene's boxes under stable ids, and which of them are present now.
// Events (sim/events/) make boxes appear and disappear; the LiDAR and the collision monitor see
// the present boxes only.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/oriented_box.h"
#include "core/geometry/scene.h"

namespace topay::sim {

class SimWorld {
 public:
  /// Box i of the scene gets id i and is present; the scene's bounds, kind and seed are kept.
  explicit SimWorld(const Scene& scene);

  /// Makes box `id` present. With `box`, the box takes that geometry (a new id is added, an
  /// existing one replaced); without, `id` must exist. Returns false with *error (naming the
  /// id) for a negative id, an unknown id without geometry, or a box with a non-finite or
  /// non-positive size. Appearing while present is allowed (a no-op without geometry).
  bool Appear(int id, const std::optional<OrientedBox>& box, std::string* error);
  /// Makes box `id` absent. False with *error for an unknown id.
  bool Disappear(int id, std::string* error);

  /// The box with this id (present or not), or nullptr.
  const OrientedBox* Find(int id) const;
  bool IsPresent(int id) const;

  /// The present boxes in id order, and their ids (present_ids()[i] is the id of
  /// present_boxes()[i]: the LiDAR and the monitor index boxes by position in this vector).
  const std::vector<OrientedBox>& present_boxes() const { return present_boxes_; }
  const std::vector<int>& present_ids() const { return present_ids_; }
  /// Id of the present box at `index` of present_boxes(), -1 if out of range.
  int IdOfPresentIndex(int index) const;

  int num_boxes() const { return static_cast<int>(boxes_.size()); }
  int num_present() const { return static_cast<int>(present_boxes_.size()); }
  /// Changes on every Appear / Disappear that changed something (consumers re-read the boxes).
  std::int64_t version() const { return version_; }
  /// The scene as loaded (bounds, kind, seed; boxes as at the start).
  const Scene& initial_scene() const { return initial_; }

 private:
  struct Entry {
    OrientedBox box;
    bool present = true;
  };
  void Rebuild();

  Scene initial_;
  std::map<int, Entry> boxes_;
  std::vector<OrientedBox> present_boxes_;
  std::vector<int> present_ids_;
  std::int64_t version_ = 0;
};

/// Empty if `box` is a valid box (finite centre and yaw, finite positive sizes); else why not.
std::string CheckBox(const OrientedBox& box);

}  // namespace topay::sim
