#pragma once

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace topay {

/// Reads optional fields of one YAML map into existing option structs: a field that is absent
/// keeps the struct's default; a field that is present must have the right type (numbers
/// finite, integers whole, booleans true/false) or a ConfigError names the file and the
/// dotted field path (e.g. "config/planner/topay.yaml: front_end.rrt.goal_bias: expected a
/// number, got 'high'"). Sections nest. Finish() rejects keys that no Read/Section asked
/// for, so a misspelt option is an error, not silently ignored.
class YamlSection {
 public:
  /// `node` must be a map or null (null: an empty section). `path` is the dotted prefix.
  YamlSection(const YAML::Node& node, std::string source, std::string path = "");

  void Read(const char* key, double* value);
  void Read(const char* key, int* value);
  void Read(const char* key, bool* value);
  void Read(const char* key, std::uint64_t* value);
  void Read(const char* key, std::string* value);
  /// A list of numbers, e.g. `q_rad: [0, 0.5, 0]` (every entry finite).
  void Read(const char* key, std::vector<double>* value);
  /// The raw node of `key` (undefined if absent), marked as read; for structures the typed
  /// readers do not cover (lists of maps). Errors about it should name FieldPath(key).
  YAML::Node Raw(const char* key) { return Child(key); }
  /// A sub-map (empty if absent). Finish it before finishing this one.
  YamlSection Section(const char* key);
  /// Throws ConfigError for the first key of this map that nothing read.
  void Finish() const;

  /// True if the section exists in the file (a map).
  bool present() const { return node_.IsMap(); }
  const std::string& source() const { return source_; }
  std::string FieldPath(const char* key) const;

 private:
  YAML::Node Child(const char* key);
  std::string Scalar(const YAML::Node& node, const char* key) const;

  YAML::Node node_;
  std::string source_;
  std::string path_;
  std::set<std::string> used_;
};

/// The YAML file at `path`; throws ConfigError(path, "", "cannot read YAML: ...") if it
/// cannot be read or parsed.
YAML::Node LoadYamlFile(const std::string& path);

/// `path` as written in the file `config_path`: a relative path is taken beside that file;
/// an empty or absolute one is returned as is.
std::string ResolveBeside(const std::string& path, const std::string& config_path);

/// Reads the optional `robot_urdf` and `robot_yaml` keys of `top` (the processes' robot
/// files), each resolved beside the file `top` came from (ResolveBeside).
void ReadRobotFiles(YamlSection* top, std::string* robot_urdf, std::string* robot_yaml);

}  // namespace topay
