#include "core/io/yaml_section.h"

#include <filesystem>

#include <cmath>
#include <limits>
#include <utility>

#include "core/common/error.h"

namespace topay {

YamlSection::YamlSection(const YAML::Node& node, std::string source, std::string path)
    : node_(node), source_(std::move(source)), path_(std::move(path)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    throw ConfigError(source_, path_.empty() ? "(top level)" : path_, "expected a map of fields");
  }
}

std::string YamlSection::FieldPath(const char* key) const {
  return path_.empty() ? std::string(key) : path_ + "." + key;
}

YAML::Node YamlSection::Child(const char* key) {
  used_.insert(key);
  if (!node_.IsMap()) return YAML::Node();
  return node_[key];
}

std::string YamlSection::Scalar(const YAML::Node& node, const char* key) const {
  if (!node.IsScalar()) throw ConfigError(source_, FieldPath(key), "expected a single value");
  return node.Scalar();
}

void YamlSection::Read(const char* key, double* value) {
  const YAML::Node child = Child(key);
  if (!child.IsDefined() || child.IsNull()) return;
  const std::string text = Scalar(child, key);
  double parsed = 0.0;
  if (text == ".inf" || text == "inf") {
    parsed = std::numeric_limits<double>::infinity();
  } else if (!YAML::convert<double>::decode(child, parsed) || std::isnan(parsed)) {
    throw ConfigError(source_, FieldPath(key), "expected a number, got '" + text + "'");
  }
  *value = parsed;
}

void YamlSection::Read(const char* key, int* value) {
  double number = 0.0;
  const YAML::Node child = Child(key);
  if (!child.IsDefined() || child.IsNull()) return;
  const std::string text = Scalar(child, key);
  if (!YAML::convert<double>::decode(child, number) || !std::isfinite(number) ||
      number != std::floor(number) || std::abs(number) > std::numeric_limits<int>::max()) {
    throw ConfigError(source_, FieldPath(key), "expected a whole number, got '" + text + "'");
  }
  *value = static_cast<int>(number);
}

void YamlSection::Read(const char* key, std::uint64_t* value) {
  const YAML::Node child = Child(key);
  if (!child.IsDefined() || child.IsNull()) return;
  const std::string text = Scalar(child, key);
  std::uint64_t parsed = 0;
  if (text.empty() || text[0] == '-' || !YAML::convert<std::uint64_t>::decode(child, parsed)) {
    throw ConfigError(source_, FieldPath(key),
                      "expected a whole number >= 0, got '" + text + "'");
  }
  *value = parsed;
}

void YamlSection::Read(const char* key, std::string* value) {
  const YAML::Node child = Child(key);
  if (!child.IsDefined() || child.IsNull()) return;
  *value = Scalar(child, key);
}

void YamlSection::Read(const char* key, bool* value) {
  const YAML::Node child = Child(key);
  if (!child.IsDefined() || child.IsNull()) return;
  const std::string text = Scalar(child, key);
  bool parsed = false;
  if (!YAML::convert<bool>::decode(child, parsed)) {
    throw ConfigError(source_, FieldPath(key), "expected true or false, got '" + text + "'");
  }
  *value = parsed;
}

void YamlSection::Read(const char* key, std::vector<double>* value) {
  const YAML::Node child = Child(key);
  if (!child.IsDefined() || child.IsNull()) return;
  if (!child.IsSequence()) throw ConfigError(source_, FieldPath(key), "expected a list of numbers");
  std::vector<double> parsed;
  for (std::size_t i = 0; i < child.size(); ++i) {
    double number = 0.0;
    const std::string item = FieldPath(key) + "[" + std::to_string(i) + "]";
    if (!child[i].IsScalar() || !YAML::convert<double>::decode(child[i], number) || !std::isfinite(number)) {
      throw ConfigError(source_, item, "expected a finite number");
    }
    parsed.push_back(number);
  }
  *value = std::move(parsed);
}

YamlSection YamlSection::Section(const char* key) {
  return YamlSection(Child(key), source_, FieldPath(key));
}

void YamlSection::Finish() const {
  if (!node_.IsMap()) return;
  for (const auto& entry : node_) {
    const std::string key = entry.first.as<std::string>("?");
    if (used_.count(key) == 0) {
      throw ConfigError(source_, FieldPath(key.c_str()), "unknown field (misspelt?)");
    }
  }
}

YAML::Node LoadYamlFile(const std::string& path) {
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path, "", std::string("cannot read YAML: ") + e.what());
  }
}

std::string ResolveBeside(const std::string& path, const std::string& config_path) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(config_path).parent_path() / path).string();
}

void ReadRobotFiles(YamlSection* top, std::string* robot_urdf, std::string* robot_yaml) {
  top->Read("robot_urdf", robot_urdf);
  top->Read("robot_yaml", robot_yaml);
  *robot_urdf = ResolveBeside(*robot_urdf, top->source());
  *robot_yaml = ResolveBeside(*robot_yaml, top->source());
}

}  // namespace topay
