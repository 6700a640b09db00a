#include "tools/viz/png_io.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

std::filesystem::path TempDir() {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("topay_png_io_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

std::string ErrorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

class PngIoTest : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_ = TempDir();
};

TEST_F(PngIoTest, RoundTripKeepsEveryPixel) {
  Image image(37, 23);
  auto colour = [](int x, int y) {
    return Rgb{static_cast<std::uint8_t>(7 * x), static_cast<std::uint8_t>(11 * y),
               static_cast<std::uint8_t>((x * y) % 256)};
  };
  image.SetPixels([&](int x, int y) { return std::optional<Rgb>(colour(x, y)); });
  const std::string path = (dir_ / "round_trip.png").string();
  WritePng(image, path);
  const Image back = ReadPng(path);
  ASSERT_EQ(back.width(), 37);
  ASSERT_EQ(back.height(), 23);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) ASSERT_EQ(back.At(x, y), colour(x, y)) << x << y;
  }

  // It is a real PNG file: the 8-byte signature.
  std::ifstream file(path, std::ios::binary);
  char signature[8] = {};
  file.read(signature, 8);
  EXPECT_EQ(std::string(signature, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_F(PngIoTest, WriteIntoAMissingFolderNamesTheFile) {
  const std::string path = (dir_ / "no_such_folder" / "x.png").string();
  const std::string message = ErrorOf([&] { WritePng(Image(2, 2), path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
}

TEST_F(PngIoTest, ReadingMissingOrMalformedFilesNamesTheFile) {
  const std::string missing = (dir_ / "missing.png").string();
  std::string message = ErrorOf([&] { ReadPng(missing); });
  EXPECT_NE(message.find(missing), std::string::npos) << message;

  const std::string garbage = (dir_ / "garbage.png").string();
  std::ofstream(garbage) << "this is not a PNG file at all";
  message = ErrorOf([&] { ReadPng(garbage); });
  EXPECT_NE(message.find(garbage), std::string::npos) << message;
  EXPECT_NE(message.find("not a valid PNG"), std::string::npos) << message;
}

}  // namespace
}  // namespace topay::viz
