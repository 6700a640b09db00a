#include "sim/scenes/scene_json.h"

#include <fstream>
#include <stdexcept>

#include "core/common/error.h"
#include "sim/scenes/json_fields.h"

namespace topay {
namespace {

using Json = nlohmann::ordered_json;

Json VectorJson(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json BoxJson(const OrientedBox& box, const BoxRole* role) {
  Json json;
  json["center"] = VectorJson(box.center_W_m);
  json["size"] = VectorJson(box.size_m);
  json["yaw"] = box.yaw_rad;
  if (role != nullptr) json["role"] = std::string(BoxRoleName(*role));
  return json;
}

OrientedBox ReadBox(const JsonFieldReader& reader, const nlohmann::json& value,
                    const std::string& path) {
  reader.RequireKnownKeys(value, path, {"center", "size", "yaw", "role"});
  OrientedBox box;
  box.center_W_m = reader.Vector3(reader.Member(value, path, "center"),
                                  JsonFieldReader::Child(path, "center"));
  const std::string size_path = JsonFieldReader::Child(path, "size");
  box.size_m = reader.Vector3(reader.Member(value, path, "size"), size_path);
  for (int i = 0; i < 3; ++i) {
    if (!(box.size_m(i) > 0.0)) {
      reader.Fail(size_path, "entry " + std::to_string(i) + " must be positive, got " +
                                 JsonNumberText(box.size_m(i)));
    }
  }
  box.yaw_rad = reader.Number(reader.Member(value, path, "yaw"),
                              JsonFieldReader::Child(path, "yaw"));
  return box;
}

BoxRole ReadRole(const JsonFieldReader& reader, const nlohmann::json& box,
                 const std::string& path) {
  const nlohmann::json* role = reader.OptionalMember(box, "role");
  if (role == nullptr) return BoxRole::kOther;
  const std::string role_path = JsonFieldReader::Child(path, "role");
  const std::string name = reader.String(*role, role_path);
  const std::optional<BoxRole> parsed = ParseBoxRole(name);
  if (!parsed) reader.Fail(role_path, "unknown role \"" + name + "\"");
  return *parsed;
}

Eigen::AlignedBox3d ReadBounds(const JsonFieldReader& reader, const nlohmann::json& value) {
  reader.RequireKnownKeys(value, "bounds", {"min", "max"});
  const Eigen::Vector3d min = reader.Vector3(reader.Member(value, "bounds", "min"), "bounds.min");
  const Eigen::Vector3d max = reader.Vector3(reader.Member(value, "bounds", "max"), "bounds.max");
  if (!(min.array() < max.array()).all()) {
    reader.Fail("bounds", "min must be below max in x, y and z");
  }
  return Eigen::AlignedBox3d(min, max);
}

Scene SceneFromDocument(const JsonFieldReader& reader, const nlohmann::json& document,
                        std::vector<BoxRole>* roles) {
  reader.RequireKnownKeys(document, "", {"kind", "seed", "bounds", "boxes"});
  Scene scene;
  if (const auto* kind = reader.OptionalMember(document, "kind")) {
    scene.kind = reader.String(*kind, "kind");
  }
  if (const auto* seed = reader.OptionalMember(document, "seed")) {
    scene.seed = reader.Unsigned(*seed, "seed");
  }
  if (const auto* bounds = reader.OptionalMember(document, "bounds")) {
    scene.bounds_W_m = ReadBounds(reader, *bounds);
  }
  const nlohmann::json& boxes = reader.Member(document, "", "boxes");
  reader.RequireArray(boxes, "boxes");
  if (roles != nullptr) roles->clear();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string path = JsonFieldReader::Index("boxes", i);
    scene.boxes.push_back(ReadBox(reader, boxes[i], path));
    const BoxRole role = ReadRole(reader, boxes[i], path);
    if (roles != nullptr) roles->push_back(role);
  }
  return scene;
}

}  // namespace

std::string SceneToJson(const Scene& scene, const std::vector<BoxRole>* roles) {
  if (roles != nullptr && roles->size() != scene.boxes.size()) {
    throw std::invalid_argument("SceneToJson: roles must have one entry per box");
  }
  Json header;
  header["kind"] = scene.kind;
  header["seed"] = scene.seed;
  header["bounds"] = {{"min", VectorJson(scene.bounds_W_m.min())},
                      {"max", VectorJson(scene.bounds_W_m.max())}};
  std::string text = "{\n";
  for (const auto& [key, value] : header.items()) {
    text += "  \"" + key + "\": " + value.dump() + ",\n";
  }
  text += "  \"boxes\": [";
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    text += (i == 0 ? "\n    " : ",\n    ");
    text += BoxJson(scene.boxes[i], roles != nullptr ? &(*roles)[i] : nullptr).dump();
  }
  text += scene.boxes.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return text;
}

void WriteSceneJson(const std::string& path, const Scene& scene,
                    const std::vector<BoxRole>* roles) {
  const std::string text = SceneToJson(scene, roles);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw ConfigError(path, "", "cannot write the scene file");
}

Scene ReadSceneJson(const std::string& path, std::vector<BoxRole>* roles) {
  const JsonFieldReader reader(path);
  return SceneFromDocument(reader, reader.ParseFile(kMaxSceneJsonBytes, "scene JSON"), roles);
}

Scene SceneFromJson(const std::string& text, const std::string& file_name,
                    std::vector<BoxRole>* roles) {
  const JsonFieldReader reader(file_name);
  return SceneFromDocument(reader, reader.ParseText(text), roles);
}

}  // namespace topay
