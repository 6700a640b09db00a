// The map journal (procs/mapper/map_journal.h): what a mapper restarted after a crash reads
// back is the map it last published; a torn tail, garbage, a missing file and an unwritable
// place each do what the header says.

#include "procs/mapper/map_journal.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "procs/msgs/map_codec.h"
#include "procs/msgs/map_receiver.h"
#include "tests/common/temp_path.h"

namespace topay::mapper {
namespace {

GridGeometry3 Grid() {
  return GridGeometry3::FromBounds(Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 0.5)), 0.05);
}

// A map with a wall of occupied voxels at ix = 30 and free voxels before it.
std::vector<std::uint8_t> WallStates(const GridGeometry3& g) {
  std::vector<std::uint8_t> states(g.NumCells(), static_cast<std::uint8_t>(VoxelState::kUnknown));
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix <= 30; ++ix)
        states[g.Index(ix, iy, iz)] = static_cast<std::uint8_t>(ix == 30 ? VoxelState::kOccupied : VoxelState::kFree);
  return states;
}

map_update_t Delta(const GridGeometry3& g, int ix, VoxelState state, std::int64_t seq) {
  const std::vector<VoxelChange> changes{{Eigen::Vector3i(ix, 5, 2), state}};
  return msgs::EncodeMapDelta(g, changes, 1000 + seq, seq);
}

std::size_t FileSize(const std::string& path) { return std::filesystem::file_size(path); }

TEST(MapJournalTest, ReadsBackTheSnapshotAndTheDeltasAfterIt) {
  const std::string path = UniqueTempPath("journal.bin");
  const GridGeometry3 g = Grid();
  msgs::MapReceiver published;
  {
    MapJournal journal(path);
    std::vector<map_update_t> msgs{msgs::EncodeFullMap(g, WallStates(g), 1001, 1), Delta(g, 10, VoxelState::kOccupied, 2),
                                   Delta(g, 35, VoxelState::kFree, 3), Delta(g, 10, VoxelState::kFree, 4)};
    for (const map_update_t& m : msgs) {
      journal.Record(m);
      published.Accept(m);
    }
    EXPECT_EQ(journal.records(), 4);
  }
  const std::optional<JournaledMap> map = ReadMapJournal(path);
  ASSERT_TRUE(map.has_value());
  EXPECT_EQ(map->records, 4);
  EXPECT_TRUE(map->stopped_early.empty()) << map->stopped_early;
  EXPECT_EQ(map->geometry.dims, g.dims);
  EXPECT_EQ(map->utime, 1004);
  EXPECT_TRUE(std::equal(map->states.begin(), map->states.end(), published.states().begin(), published.states().end()));
  EXPECT_EQ(map->states[g.Index(35, 5, 2)], static_cast<std::uint8_t>(VoxelState::kFree));
  EXPECT_EQ(map->states[g.Index(30, 0, 0)], static_cast<std::uint8_t>(VoxelState::kOccupied));
}

TEST(MapJournalTest, ASnapshotStartsTheFileAfresh) {
  const std::string path = UniqueTempPath("journal.bin");
  const GridGeometry3 g = Grid();
  MapJournal journal(path);
  journal.Record(msgs::EncodeFullMap(g, WallStates(g), 1, 1));
  for (int k = 2; k < 50; ++k) journal.Record(Delta(g, k % 20, VoxelState::kOccupied, k));
  const std::size_t long_file = FileSize(path);
  std::vector<std::uint8_t> empty(g.NumCells(), static_cast<std::uint8_t>(VoxelState::kUnknown));
  journal.Record(msgs::EncodeFullMap(g, empty, 50, 50));
  EXPECT_EQ(journal.records(), 1);
  EXPECT_LT(FileSize(path), long_file);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const std::optional<JournaledMap> map = ReadMapJournal(path);
  ASSERT_TRUE(map.has_value());
  EXPECT_EQ(map->records, 1);
  EXPECT_EQ(map->states, empty);
}

TEST(MapJournalTest, ATornLastRecordIsDroppedAndTheMapBeforeItKept) {
  const std::string path = UniqueTempPath("journal.bin");
  const GridGeometry3 g = Grid();
  {
    MapJournal journal(path);
    journal.Record(msgs::EncodeFullMap(g, WallStates(g), 1, 1));
    journal.Record(Delta(g, 10, VoxelState::kOccupied, 2));
    journal.Record(Delta(g, 11, VoxelState::kOccupied, 3));
  }
  std::filesystem::resize_file(path, FileSize(path) - 3);
  const std::optional<JournaledMap> map = ReadMapJournal(path);
  ASSERT_TRUE(map.has_value());
  EXPECT_EQ(map->records, 2);
  EXPECT_NE(map->stopped_early.find("torn"), std::string::npos) << map->stopped_early;
  EXPECT_EQ(map->states[g.Index(10, 5, 2)], static_cast<std::uint8_t>(VoxelState::kOccupied));
  EXPECT_EQ(map->states[g.Index(11, 5, 2)], static_cast<std::uint8_t>(VoxelState::kFree));
}

TEST(MapJournalTest, ADeltaThatDoesNotFollowEndsTheReplay) {
  const std::string path = UniqueTempPath("journal.bin");
  const GridGeometry3 g = Grid();
  {
    MapJournal journal(path);
    journal.Record(msgs::EncodeFullMap(g, WallStates(g), 1, 1));
    journal.Record(Delta(g, 10, VoxelState::kOccupied, 2));
    journal.Record(Delta(g, 11, VoxelState::kOccupied, 4));  // 3 missing
    journal.Record(Delta(g, 12, VoxelState::kOccupied, 5));
  }
  const std::optional<JournaledMap> map = ReadMapJournal(path);
  ASSERT_TRUE(map.has_value());
  EXPECT_EQ(map->records, 2);
  EXPECT_FALSE(map->stopped_early.empty());
  EXPECT_EQ(map->states[g.Index(11, 5, 2)], static_cast<std::uint8_t>(VoxelState::kFree));
}

TEST(MapJournalTest, NoFileIsNoMapAndGarbageIsAnErrorNamingTheFile) {
  EXPECT_FALSE(ReadMapJournal(UniqueTempPath("never_written.bin")).has_value());
  const std::string garbage = UniqueTempPath("garbage.bin");
  std::ofstream(garbage) << "this is not a map journal at all";
  try {
    ReadMapJournal(garbage);
    FAIL() << "garbage accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(garbage), std::string::npos) << e.what();
  }
  const std::string empty = UniqueTempPath("empty.bin");
  std::ofstream{empty};
  EXPECT_THROW(ReadMapJournal(empty), ConfigError);
  const std::string dir = UniqueTempPath("a_directory");
  std::filesystem::create_directories(dir);
  EXPECT_THROW(ReadMapJournal(dir), ConfigError);
}

TEST(MapJournalTest, ADeltaBeforeAnySnapshotIsNotWritten) {
  const std::string path = UniqueTempPath("journal.bin");
  const GridGeometry3 g = Grid();
  MapJournal journal(path);
  journal.Record(Delta(g, 10, VoxelState::kOccupied, 2));  // dropped: nothing to replay it on
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(journal.records(), 0);
}

TEST(MapJournalTest, AnUnwritablePlaceThrowsNamingItAndTheNextSnapshotTriesAgain) {
  const std::string dir = UniqueTempPath("later");
  const std::string path = dir + "/journal.bin";
  const GridGeometry3 g = Grid();
  MapJournal journal(path);
  try {
    journal.Record(msgs::EncodeFullMap(g, WallStates(g), 1, 1));
    FAIL() << "wrote into a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  journal.Record(Delta(g, 10, VoxelState::kOccupied, 2));  // dropped, no throw
  std::filesystem::create_directories(dir);
  journal.Record(msgs::EncodeFullMap(g, WallStates(g), 3, 3));
  ASSERT_TRUE(ReadMapJournal(path).has_value());
  EXPECT_EQ(ReadMapJournal(path)->records, 1);
}

}  // namespace
}  // namespace topay::mapper
