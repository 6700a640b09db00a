// Scene files from untrusted text (sim/scenes/scene_json.h SceneFromJson), with and without
// the box roles. Bad input must be a ConfigError naming the file; a scene that loads must hold
// what the format promises (finite numbers, positive sizes, min < max bounds, one role per
// box) and round-trip: SceneToJson then SceneFromJson gives the same scene (same doubles,
// kind, seed and roles), and writing that again gives the same bytes.
// Input: [flags][scene JSON text]; flags bit 0: ask for the roles.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "sim/scenes/scene_json.h"
#include "tests/fuzz/fuzz_reader.h"
#include "tests/fuzz/loader_checks.h"

namespace topay::fuzz {
namespace {

constexpr const char* kSource = "fuzz_scene.json";
constexpr const char* kRoundTripSource = "fuzz_scene_written.json";

void CheckScene(const Scene& scene) {
  const Eigen::AlignedBox3d& bounds = scene.bounds_W_m;
  FuzzCheck(bounds.min().allFinite() && bounds.max().allFinite() && (bounds.min().array() < bounds.max().array()).all(),
            "scene bounds are finite with min < max");
  for (const OrientedBox& box : scene.boxes) {
    FuzzCheck(box.center_W_m.allFinite() && std::isfinite(box.yaw_rad), "a box's centre and yaw are finite");
    FuzzCheck(box.size_m.allFinite() && (box.size_m.array() > 0.0).all(), "a box's size is finite and positive");
  }
}

bool SameBox(const OrientedBox& a, const OrientedBox& b) {
  return a.center_W_m == b.center_W_m && a.size_m == b.size_m && a.yaw_rad == b.yaw_rad;
}

bool SameScene(const Scene& a, const Scene& b) {
  if (a.kind != b.kind || a.seed != b.seed || a.boxes.size() != b.boxes.size()) return false;
  if (a.bounds_W_m.min() != b.bounds_W_m.min() || a.bounds_W_m.max() != b.bounds_W_m.max()) return false;
  for (std::size_t i = 0; i < a.boxes.size(); ++i) {
    if (!SameBox(a.boxes[i], b.boxes[i])) return false;
  }
  return true;
}

void CheckRoundTrip(const Scene& scene, const std::vector<BoxRole>* roles) {
  const std::string written = SceneToJson(scene, roles);
  std::vector<BoxRole> read_roles;
  Scene again;
  try {
    again = SceneFromJson(written, kRoundTripSource, roles != nullptr ? &read_roles : nullptr);
  } catch (const ConfigError&) {
    FuzzCheck(false, "a written scene reads back");
  }
  FuzzCheck(SameScene(scene, again), "a scene round-trips through its JSON");
  if (roles != nullptr) FuzzCheck(read_roles == *roles, "box roles round-trip");
  FuzzCheck(SceneToJson(again, roles) == written, "a read-back scene writes the same bytes");
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  const bool with_roles = (in.Byte() & 1) != 0;
  const std::string text = in.RestAsString();
  std::vector<BoxRole> roles{BoxRole::kWall};  // replaced by the reader
  Scene scene;
  try {
    scene = SceneFromJson(text, kSource, with_roles ? &roles : nullptr);
  } catch (const ConfigError& e) {
    CheckConfigError(e, kSource);
    return 0;
  }
  CheckScene(scene);
  if (with_roles) FuzzCheck(roles.size() == scene.boxes.size(), "one role per box");
  CheckRoundTrip(scene, with_roles ? &roles : nullptr);
  return 0;
}
