#include "sim/world/sim_world.h"

#include <cmath>

namespace topay::sim {

std::string CheckBox(const OrientedBox& box) {
  if (!box.center_W_m.allFinite() || !std::isfinite(box.yaw_rad)) return "centre and yaw must be finite";
  if (!box.size_m.allFinite() || (box.size_m.array() <= 0.0).any()) return "sizes must be finite and > 0";
  return "";
}

SimWorld::SimWorld(const Scene& scene) : initial_(scene) {
  for (int i = 0; i < static_cast<int>(scene.boxes.size()); ++i) boxes_[i] = Entry{scene.boxes[i], true};
  Rebuild();
}

bool SimWorld::Appear(int id, const std::optional<OrientedBox>& box, std::string* error) {
  if (id < 0) {
    *error = "box id " + std::to_string(id) + " is negative";
    return false;
  }
  auto it = boxes_.find(id);
  if (box) {
    const std::string why = CheckBox(*box);
    if (!why.empty()) {
      *error = "box " + std::to_string(id) + ": " + why;
      return false;
    }
    boxes_[id] = Entry{*box, true};
  } else {
    if (it == boxes_.end()) {
      *error = "box " + std::to_string(id) + " does not exist and the event gives no geometry";
      return false;
    }
    if (it->second.present) return true;
    it->second.present = true;
  }
  Rebuild();
  return true;
}

bool SimWorld::Disappear(int id, std::string* error) {
  auto it = boxes_.find(id);
  if (it == boxes_.end()) {
    *error = "box " + std::to_string(id) + " does not exist";
    return false;
  }
  if (!it->second.present) return true;
  it->second.present = false;
  Rebuild();
  return true;
}

const OrientedBox* SimWorld::Find(int id) const {
  auto it = boxes_.find(id);
  return it == boxes_.end() ? nullptr : &it->second.box;
}

bool SimWorld::IsPresent(int id) const {
  auto it = boxes_.find(id);
  return it != boxes_.end() && it->second.present;
}

int SimWorld::IdOfPresentIndex(int index) const {
  if (index < 0 || index >= static_cast<int>(present_ids_.size())) return -1;
  return present_ids_[index];
}

void SimWorld::Rebuild() {
  present_boxes_.clear();
  present_ids_.clear();
  for (const auto& [id, entry] : boxes_) {
    if (!entry.present) continue;
    present_boxes_.push_back(entry.box);
    present_ids_.push_back(id);
  }
  ++version_;
}

}  // namespace topay::sim
