#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/geometry/scene.h"
#include "sim/scenes/box_role.h"

namespace topay {

// Scene files: a JSON object
//   {"kind": "cuboids", "seed": 7,
//    "bounds": {"min": [-10, -10, 0], "max": [10, 10, 1.6]},
//    "boxes": [{"center": [x, y, z], "size": [sx, sy, sz], "yaw": rad, "role": "wall"}, ...]}
// Lengths in metres, yaw in radians about W's z (see OrientedBox). Only "boxes" (with center,
// size, yaw per box) is required; "kind", "seed", "bounds" and each box's "role" are optional
// and validated when present; any other key, at any level, is an error. Numbers are written in shortest round-trip form, one box per
// line, keys in a fixed order: the same Scene always gives the same bytes, and reading gives
// back the same doubles.

/// Largest scene file read (bytes): about 1.7 million boxes of 150 bytes (a 100,000-box scene
/// is about 10 MB).
inline constexpr std::size_t kMaxSceneJsonBytes = std::size_t{256} << 20;  // 256 MiB

/// The JSON text of a scene. roles, if given, must have one entry per box.
std::string SceneToJson(const Scene& scene, const std::vector<BoxRole>* roles = nullptr);

/// Writes SceneToJson to path; throws ConfigError(path, "", ...) if it cannot be written.
void WriteSceneJson(const std::string& path, const Scene& scene,
                    const std::vector<BoxRole>* roles = nullptr);

/// Reads and validates a scene file. Throws ConfigError("<path>", "<field>", "<message>") for a
/// missing file, a directory, a file above kMaxSceneJsonBytes, malformed JSON, a missing or
/// unknown field (e.g. "boxes[3].colour"), a wrong type, a non-finite number, a size that is
/// not positive, an unknown role, or bounds with min >= max (e.g. field "boxes[12].size"). roles, if given, receives each box's role (kOther when absent).
Scene ReadSceneJson(const std::string& path, std::vector<BoxRole>* roles = nullptr);

/// As ReadSceneJson, from text; file_name is used in error messages.
Scene SceneFromJson(const std::string& text, const std::string& file_name,
                    std::vector<BoxRole>* roles = nullptr);

}  // namespace topay
