// CANopen COB-IDs (CiA 301 predefined connection set): building and classifying them, and the
// frame shape check every decoder uses.
#include "drivers/arm/canopen_ids.h"

#include <gtest/gtest.h>

namespace topay::canopen {
namespace {

TEST(CanopenIdsTest, CobIdOfEveryFunction) {
  struct Row { CanopenFunction function; std::uint32_t base; };
  const Row rows[] = {
      {CanopenFunction::kEmcy, 0x080},  {CanopenFunction::kTpdo1, 0x180},
      {CanopenFunction::kRpdo1, 0x200}, {CanopenFunction::kTpdo2, 0x280},
      {CanopenFunction::kRpdo2, 0x300}, {CanopenFunction::kTpdo3, 0x380},
      {CanopenFunction::kRpdo3, 0x400}, {CanopenFunction::kTpdo4, 0x480},
      {CanopenFunction::kRpdo4, 0x500}, {CanopenFunction::kSdoTx, 0x580},
      {CanopenFunction::kSdoRx, 0x600}, {CanopenFunction::kHeartbeat, 0x700}};
  for (const Row& row : rows) {
    SCOPED_TRACE(std::string(ToString(row.function)));
    EXPECT_EQ(FunctionBaseCobId(row.function), row.base);
    for (int node : {1, 5, 127}) {
      const auto id = CobIdOf(row.function, node, nullptr);
      ASSERT_TRUE(id.has_value());
      EXPECT_EQ(*id, row.base + node);
      const auto back = ClassifyCobId(*id, nullptr);
      ASSERT_TRUE(back.has_value());
      EXPECT_EQ(back->function, row.function);
      EXPECT_EQ(back->node_id, node);
    }
  }
  EXPECT_EQ(CobIdOf(CanopenFunction::kNmt, 0, nullptr), 0x000u);
  EXPECT_EQ(CobIdOf(CanopenFunction::kSync, 0, nullptr), 0x080u);
}

TEST(CanopenIdsTest, NodeIdsOutsideOneTo127AreRejected) {
  std::string error;
  EXPECT_FALSE(CobIdOf(CanopenFunction::kTpdo1, 0, &error).has_value());
  EXPECT_EQ(error, "TPDO1: node id 0 is outside 1..127");
  EXPECT_FALSE(CobIdOf(CanopenFunction::kHeartbeat, 128, &error).has_value());
  EXPECT_EQ(error, "heartbeat: node id 128 is outside 1..127");
  EXPECT_FALSE(CobIdOf(CanopenFunction::kSdoRx, -1, nullptr).has_value());
  EXPECT_EQ(CheckNodeId(1), "");
  EXPECT_EQ(CheckNodeId(127), "");
}

TEST(CanopenIdsTest, ClassifiesNmtSyncAndRejectsUnknownIds) {
  auto nmt = ClassifyCobId(0x000, nullptr);
  ASSERT_TRUE(nmt);
  EXPECT_EQ(nmt->function, CanopenFunction::kNmt);
  EXPECT_EQ(nmt->node_id, 0);
  auto sync = ClassifyCobId(0x080, nullptr);
  ASSERT_TRUE(sync);
  EXPECT_EQ(sync->function, CanopenFunction::kSync);
  std::string error;
  EXPECT_FALSE(ClassifyCobId(0x180, &error));  // TPDO1 range, node 0
  EXPECT_EQ(error, "COB-ID 0x180 (TPDO1) has node id 0, outside 1..127");
  for (std::uint32_t id : {0x001u, 0x07Fu, 0x100u, 0x17Fu, 0x680u, 0x6FFu, 0x780u, 0x7FFu}) {
    EXPECT_FALSE(ClassifyCobId(id, &error)) << id;
    EXPECT_NE(error.find("not a CANopen object this stack uses"), std::string::npos) << error;
  }
  EXPECT_FALSE(ClassifyCobId(0x800, &error));
  EXPECT_EQ(error, "COB-ID 0x800 is above 0x7FF");
}

TEST(CanopenIdsTest, FrameCheckNamesTheFrameAndTheProblem) {
  std::string error;
  const auto ok = CheckCanopenFrame(can::CanFrame::Standard(0x705, {0x05}),
                                    CanopenFunction::kHeartbeat, 1, 1, "heartbeat", &error);
  ASSERT_TRUE(ok);
  EXPECT_EQ(*ok, 5);
  EXPECT_FALSE(CheckCanopenFrame(can::CanFrame::Standard(0x705, {0x05, 0}),
                                 CanopenFunction::kHeartbeat, 1, 1, "heartbeat", &error));
  EXPECT_EQ(error, "heartbeat frame '705#0500': DLC 2, expected 1");
  EXPECT_FALSE(CheckCanopenFrame(can::CanFrame::Standard(0x185, {0x05}),
                                 CanopenFunction::kHeartbeat, 1, 1, "heartbeat", &error));
  EXPECT_EQ(error, "heartbeat frame '185#05': id 0x185 is TPDO1, expected heartbeat");
  EXPECT_FALSE(CheckCanopenFrame(can::CanFrame::Extended(0x705, {0x05}),
                                 CanopenFunction::kHeartbeat, 1, 1, "heartbeat", &error));
  EXPECT_NE(error.find("extended"), std::string::npos);
  EXPECT_FALSE(CheckCanopenFrame(can::CanFrame::Remote(0x705, 1), CanopenFunction::kHeartbeat,
                                 1, 1, "heartbeat", &error));
  EXPECT_NE(error.find("remote"), std::string::npos);
  can::CanFrame bad_dlc = can::CanFrame::Standard(0x705, {0x05});
  bad_dlc.dlc = 9;
  EXPECT_FALSE(CheckCanopenFrame(bad_dlc, CanopenFunction::kHeartbeat, 1, 1, "heartbeat",
                                 &error));
  EXPECT_NE(error.find("DLC 9 is above 8"), std::string::npos) << error;
}

}  // namespace
}  // namespace topay::canopen
