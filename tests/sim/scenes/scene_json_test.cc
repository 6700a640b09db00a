#include "sim/scenes/scene_json.h"
#include "tests/common/temp_path.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "sim/scenes/benchmark_scene.h"

namespace topay {
namespace {

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A valid file with one box, where `box` replaces the box's JSON.
std::string OneBox(const std::string& box) { return "{\"boxes\": [" + box + "]}"; }

// Reads the text as a file and expects a ConfigError naming the file and the field.
void ExpectConfigError(const std::string& text, const std::string& field,
                       const std::string& message_part) {
  const std::string path = UniqueTempPath("bad.json");
  WriteText(path, text);
  try {
    ReadSceneJson(path);
    ADD_FAILURE() << "no error for " << text;
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.field(), field) << error.what();
    EXPECT_NE(std::string(error.what()).find(message_part), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos);
  }
}

TEST(SceneJsonTest, RoundTripIsExactForGeneratedScenes) {
  for (const SceneKind kind : {SceneKind::kCuboids, SceneKind::kTables}) {
    const GeneratedScene generated = GenerateBenchmarkScene(kind, 77);
    const std::string path = UniqueTempPath("round_trip.json");
    WriteSceneJson(path, generated.scene, &generated.roles);
    std::vector<BoxRole> roles;
    const Scene read = ReadSceneJson(path, &roles);
    EXPECT_EQ(read.kind, generated.scene.kind);
    EXPECT_EQ(read.seed, generated.scene.seed);
    EXPECT_EQ(read.bounds_W_m.min(), generated.scene.bounds_W_m.min());
    EXPECT_EQ(read.bounds_W_m.max(), generated.scene.bounds_W_m.max());
    EXPECT_EQ(roles, generated.roles);
    ASSERT_EQ(read.boxes.size(), generated.scene.boxes.size());
    for (std::size_t i = 0; i < read.boxes.size(); ++i) {
      EXPECT_EQ(read.boxes[i].center_W_m, generated.scene.boxes[i].center_W_m);
      EXPECT_EQ(read.boxes[i].size_m, generated.scene.boxes[i].size_m);
      EXPECT_EQ(read.boxes[i].yaw_rad, generated.scene.boxes[i].yaw_rad);
    }
    // Writing what was read gives the same bytes.
    EXPECT_EQ(SceneToJson(read, &roles), SceneToJson(generated.scene, &generated.roles));
  }
}

TEST(SceneJsonTest, RoundTripIsExactForArbitraryDoubles) {
  Scene scene;
  scene.kind = "hand made \"quoted\"";
  OrientedBox box;
  box.center_W_m = {0.1 + 0.2, -1.0 / 3.0, 1e-17};
  box.size_m = {M_PI, 1e-3, 123456.789};
  box.yaw_rad = -2.0 / 7.0;
  scene.boxes = {box};
  const Scene read = SceneFromJson(SceneToJson(scene), "memory");
  EXPECT_EQ(read.kind, scene.kind);
  EXPECT_EQ(read.boxes[0].center_W_m, box.center_W_m);
  EXPECT_EQ(read.boxes[0].size_m, box.size_m);
  EXPECT_EQ(read.boxes[0].yaw_rad, box.yaw_rad);
}

TEST(SceneJsonTest, OptionalKeysMayBeAbsent) {
  std::vector<BoxRole> roles;
  const Scene scene = SceneFromJson(
      OneBox(R"({"center": [1, 2, 0.5], "size": [1, 1, 1], "yaw": 0})"), "memory", &roles);
  ASSERT_EQ(scene.boxes.size(), 1u);
  EXPECT_EQ(scene.boxes[0].center_W_m, Eigen::Vector3d(1, 2, 0.5));
  EXPECT_EQ(roles, std::vector<BoxRole>{BoxRole::kOther});
  EXPECT_EQ(scene.seed, 0u);
  EXPECT_TRUE(SceneFromJson(R"({"boxes": []})", "memory").boxes.empty());
}

TEST(SceneJsonTest, MissingFile) {
  const std::string path = UniqueTempPath("does_not_exist.json");
  std::remove(path.c_str());
  try {
    ReadSceneJson(path);
    FAIL();
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_NE(std::string(error.what()).find("cannot open"), std::string::npos);
  }
}

TEST(SceneJsonTest, UnknownKeysNameTheKey) {
  ExpectConfigError(R"({"boxes": [], "colour": "red"})", "colour", "unknown field");
  ExpectConfigError(R"({"boxes": [], "bounds": {"min": [0, 0, 0], "max": [1, 1, 1], "mid": 0}})",
                    "bounds.mid", "unknown field");
  ExpectConfigError(OneBox(R"({"center": [0, 0, 0], "size": [1, 1, 1], "yaw": 0, "yow": 1})"),
                    "boxes[0].yow", "unknown field");
}

TEST(SceneJsonTest, DirectoriesDevicesAndOversizedFilesAreErrors) {
  for (const std::string& path : {::testing::TempDir(), std::string("/dev/zero")}) {
    if (::access(path.c_str(), R_OK) != 0) continue;
    try {
      ReadSceneJson(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const ConfigError& error) {
      EXPECT_EQ(error.file(), path);
      EXPECT_NE(std::string(error.what()).find("scene JSON"), std::string::npos) << error.what();
    }
  }
}

TEST(SceneJsonTest, MalformedJson) {
  ExpectConfigError(R"({"boxes": [ {"center": [1, 2, 3], )", "", "malformed JSON");
  ExpectConfigError("", "", "malformed JSON");
  ExpectConfigError(R"({"boxes": [NaN]})", "", "malformed JSON");
}

TEST(SceneJsonTest, NanWrittenIsRejectedOnReading) {
  // JSON has no NaN: nlohmann::json writes it as null, which the reader rejects.
  Scene scene;
  scene.boxes.resize(2);
  scene.boxes[1].size_m.y() = std::numeric_limits<double>::quiet_NaN();
  ExpectConfigError(SceneToJson(scene), "boxes[1].size[1]", "expected a number, got null");
}

TEST(SceneJsonTest, BadFieldsNameTheField) {
  const std::string good = R"({"center": [0, 0, 0.5], "size": [1, 1, 1], "yaw": 0})";
  ExpectConfigError("[]", "", "expected an object");
  ExpectConfigError("{}", "boxes", "missing");
  ExpectConfigError(R"({"boxes": {}})", "boxes", "expected an array");
  ExpectConfigError(OneBox("3"), "boxes[0]", "expected an object");
  ExpectConfigError(OneBox(R"({"size": [1, 1, 1], "yaw": 0})"), "boxes[0].center", "missing");
  ExpectConfigError(OneBox(R"({"center": [0, 0], "size": [1, 1, 1], "yaw": 0})"),
                    "boxes[0].center", "expected 3 numbers");
  ExpectConfigError(OneBox(R"({"center": [0, 0, 0], "size": [1, null, 1], "yaw": 0})"),
                    "boxes[0].size[1]", "expected a number");
  // JSON has no NaN or infinity; a number beyond the double range is rejected by the parser
  // (which knows no field names).
  ExpectConfigError(OneBox(R"({"center": [0, 0, 0], "size": [1, 1, 1e999], "yaw": 0})"), "",
                    "out of range");
  ExpectConfigError(OneBox(R"({"center": [0, 0, 0], "size": [1, 1, 1], "yaw": "0"})"),
                    "boxes[0].yaw", "expected a number");
  ExpectConfigError(OneBox(R"({"center": [0, 0, 0], "size": [1, 1, 1]})"), "boxes[0].yaw",
                    "missing");
  ExpectConfigError(OneBox(R"({"center": [0, 0, 0], "size": [1, 1, 1], "yaw": 0, "role": "x"})"),
                    "boxes[0].role", "unknown role");
  // The thirteenth box has a negative size.
  std::string boxes;
  for (int i = 0; i < 12; ++i) boxes += good + ",";
  boxes += R"({"center": [0, 0, 0], "size": [1, -0.3, 1], "yaw": 0})";
  ExpectConfigError(OneBox(boxes), "boxes[12].size", "must be positive");
  ExpectConfigError(OneBox(R"({"center": [0, 0, 0], "size": [0, 1, 1], "yaw": 0})"),
                    "boxes[0].size", "must be positive");
  ExpectConfigError(R"({"seed": -4, "boxes": []})", "seed", "negative");
  ExpectConfigError(R"({"seed": 1.5, "boxes": []})", "seed", "non-negative integer");
  ExpectConfigError(R"({"kind": 3, "boxes": []})", "kind", "expected a string");
  ExpectConfigError(R"({"bounds": {"min": [0, 0, 0], "max": [1, 1, 0]}, "boxes": []})",
                    "bounds", "min must be below max");
  ExpectConfigError(R"({"bounds": {"min": [0, 0, 0]}, "boxes": []})", "bounds.max", "missing");
}

}  // namespace
}  // namespace topay
