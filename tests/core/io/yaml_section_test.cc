// YamlSection (core/io/yaml_section.h): the list-of-numbers reader and the raw node accessor.

#include "core/io/yaml_section.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"

namespace topay {
namespace {

TEST(YamlSection, ReadsListsOfNumbersAndNamesTheBadEntry) {
  const YAML::Node root = YAML::Load("q: [0, 0.5, -1.25]\nempty: []\nbad: [1, x]\nscalar: 3\nraw: {a: 1}\n");
  YamlSection s(root, "f.yaml");
  std::vector<double> q = {9.0}, empty = {9.0}, absent = {7.0};
  s.Read("q", &q);
  EXPECT_EQ(q, (std::vector<double>{0.0, 0.5, -1.25}));
  s.Read("empty", &empty);
  EXPECT_TRUE(empty.empty());
  s.Read("absent", &absent);
  EXPECT_EQ(absent, std::vector<double>{7.0});  // absent: unchanged
  std::vector<double> bad;
  try {
    s.Read("bad", &bad);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.field(), "bad[1]");
  }
  try {
    s.Read("scalar", &bad);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.field(), "scalar");
  }
  EXPECT_TRUE(s.Raw("raw").IsMap());
  EXPECT_NO_THROW(s.Finish());  // every key was read (Raw marks its key)
}

TEST(YamlSection, FilesLoadAndRobotFilesResolveBesideTheConfig) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "topay_yaml_section_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "options.yaml").string();
  std::ofstream(path) << "robot_urdf: robot/r.urdf\nrobot_yaml: /abs/r.yaml\n";
  YamlSection top(LoadYamlFile(path), path);
  std::string urdf, yaml;
  ReadRobotFiles(&top, &urdf, &yaml);
  top.Finish();
  EXPECT_EQ(urdf, (dir / "robot/r.urdf").string());
  EXPECT_EQ(yaml, "/abs/r.yaml");
  EXPECT_EQ(ResolveBeside("", path), "");
  try {
    LoadYamlFile((dir / "missing.yaml").string());
    ADD_FAILURE() << "a missing file loaded";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.yaml"), std::string::npos) << e.what();
  }
  std::ofstream(path) << "a: [1, 2\n";
  EXPECT_THROW(LoadYamlFile(path), ConfigError);
}

}  // namespace
}  // namespace topay
