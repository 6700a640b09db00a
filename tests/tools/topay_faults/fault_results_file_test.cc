// results.json of a fault campaign: what is written reads back the same; a damaged file is an
// error naming the file, the episode and the field; a resumed campaign numbers its missions after
// the folders already there.

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tools/topay_faults/fault_results_file.h"

namespace topay::tools {
namespace {

namespace fs = std::filesystem;

EpisodeResult Episode(const std::string& fault, double safe_ms) {
  EpisodeResult e;
  e.fault = fault;
  e.seed = 7;
  e.injected = true;
  e.notes = "kill -9 2110 (topay-tracker)";
  e.safe_ms = safe_ms;
  e.safe_evidence = "bridge STOPPED: stale command";
  e.recovered = true;
  e.recover_s = 1.5;
  e.reaction = "restarted as pid 2136";
  e.other_restarts = 1;
  e.contacts = 0;
  return e;
}

class FaultResultsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(testing::TempDir()) / ("fault_results_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  // The error message ReadEpisodes gives for the file holding `text` ("" if it read it).
  std::string ReadError(const std::string& text) const {
    const std::string path = Write("bad.json", text);
    try {
      ReadEpisodes(path);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

TEST_F(FaultResultsFile, WhatIsWrittenReadsBackTheSame) {
  EpisodeResult refused = Episode("can-bus-off", -1.0);
  refused.injected = false;
  refused.refused = true;
  refused.recovered = false;
  refused.recover_s = -1.0;
  refused.contacts = 3;
  refused.reaction = "bad \xff byte";  // texts off the bus may be any bytes
  std::vector<EpisodeResult> written = {Episode("kill-tracker", 96.25), refused};
  written[0].zero_ms = 412.5;
  const std::string path = (dir_ / "results.json").string();
  ASSERT_TRUE(WriteEpisodes(path, written));
  const std::vector<EpisodeResult> read = ReadEpisodes(path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].fault, "kill-tracker");
  EXPECT_EQ(read[0].seed, 7u);
  EXPECT_DOUBLE_EQ(read[0].safe_ms, 96.25);
  EXPECT_DOUBLE_EQ(read[0].zero_ms, 412.5);
  EXPECT_DOUBLE_EQ(read[1].zero_ms, -1.0);
  EXPECT_EQ(read[0].safe_evidence, "bridge STOPPED: stale command");
  EXPECT_EQ(read[0].other_restarts, 1);
  EXPECT_TRUE(read[0].recovered);
  EXPECT_DOUBLE_EQ(read[0].recover_s, 1.5);
  EXPECT_FALSE(read[1].injected);
  EXPECT_TRUE(read[1].refused);
  EXPECT_EQ(read[1].contacts, 3);
  EXPECT_EQ(read[1].reaction, "bad \xef\xbf\xbd byte");  // replaced by U+FFFD
}

TEST_F(FaultResultsFile, ADamagedFileIsAnErrorNamingFileEpisodeAndField) {
  const nlohmann::json good = ToJson(Episode("kill-tracker", 96.0));
  auto with = [&](const char* key, const nlohmann::json& value) {
    nlohmann::json e = good;
    if (value.is_null()) e.erase(key); else e[key] = value;
    return nlohmann::json{{"episodes", {good, e}}}.dump();
  };
  EXPECT_NE(ReadError("{\"episodes\": [").find("bad.json: not JSON"), std::string::npos);
  EXPECT_NE(ReadError("[]").find("no \"episodes\" list"), std::string::npos);
  EXPECT_NE(ReadError("{\"episodes\": [3]}").find("episode 0: not an object"), std::string::npos);
  EXPECT_NE(ReadError(with("fault", nullptr)).find("episode 1: no \"fault\""), std::string::npos);
  EXPECT_NE(ReadError(with("fault", "")).find("\"fault\": empty"), std::string::npos);
  EXPECT_NE(ReadError(with("injected", 1)).find("\"injected\": not a boolean"), std::string::npos);
  EXPECT_NE(ReadError(with("safe_ms", "96")).find("\"safe_ms\": not a number"), std::string::npos);
  EXPECT_NE(ReadError(with("seed", -1)).find("\"seed\": not a whole number >= 0"), std::string::npos);
  EXPECT_NE(ReadError(with("other_restarts", 1e300)).find("\"other_restarts\": not a whole number"),
            std::string::npos);
  EXPECT_NE(ReadError(with("other_restarts", 4294967296LL)).find("\"other_restarts\": out of range"),
            std::string::npos);
  EXPECT_NE(ReadError(with("contacts", 18446744073709551615ULL)).find("\"contacts\": out of range"),
            std::string::npos);
  EXPECT_EQ(ReadError(with("notes", "fine")), "");
  try {
    ReadEpisodes((dir_ / "missing.json").string());
    ADD_FAILURE() << "a missing file was read";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("missing.json: cannot read"), std::string::npos) << e.what();
  }
}

TEST_F(FaultResultsFile, MissionsAreNumberedAfterTheFoldersThere) {
  EXPECT_EQ(NextMissionIndex(dir_.string()), 1);
  EXPECT_EQ(NextMissionIndex((dir_ / "absent").string()), 1);
  fs::create_directories(dir_ / "mission-1");
  fs::create_directories(dir_ / "mission-12");
  fs::create_directories(dir_ / "mission-x");
  fs::create_directories(dir_ / "mission-99999999999");
  Write("mission-40", "a file, not a mission folder");
  EXPECT_EQ(NextMissionIndex(dir_.string()), 13);
}

}  // namespace
}  // namespace topay::tools
