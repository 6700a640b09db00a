// FaultInjector's bus faults on a real LCM bus in a private network namespace (skipped, with
// the reason, where none can be made): hostile payloads reach every channel; reordered copies
// arrive late, once each (the injector does not copy its own copies); the nftables rules drop
// BASE_POSE only, MAP_UPDATE only (whole or in fragments), or about one datagram in ten, and are gone after End() (skipped, with the
// reason, where nft is missing or refused); the goal faults publish decodable goals of their kind.

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <cstdlib>
#include <cstring>
#include <cmath>
#include <map>
#include <set>
#include <thread>

#include "tests/procs/graph_test_support.h"
#include "tools/topay_faults/fault_injector.h"
#include "topay/goal_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::tools {
namespace {

constexpr const char* kUrl = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304";

// Everything received on the bus: per channel, the payloads.
struct Received {
  std::map<std::string, std::vector<std::vector<std::uint8_t>>> by_channel;
  void On(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
    const auto* data = static_cast<const std::uint8_t*>(rbuf->data);
    by_channel[channel].emplace_back(data, data + rbuf->data_size);
  }
  std::size_t Count(const std::string& channel) const {
    const auto it = by_channel.find(channel);
    return it == by_channel.end() ? 0 : it->second.size();
  }
};

std::vector<std::uint8_t> Counter(std::uint64_t n) {
  std::vector<std::uint8_t> bytes(8);
  std::memcpy(bytes.data(), &n, 8);
  return bytes;
}

class FaultInjectorTest : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!test::EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = test::TestDir("injector");
    listener_ = std::make_unique<lcm::LCM>(kUrl);
    listener_->subscribe(".*", &Received::On, &received_);
    publisher_ = std::make_unique<lcm::LCM>(kUrl);
    monitor_ = std::make_unique<GraphMonitor>(kUrl);
    FaultInjectorOptions options;
    options.lcm_url = kUrl;
    options.work_dir = dir_;
    options.graph_ancestor = getpid();
    injector_ = std::make_unique<FaultInjector>(options, monitor_.get());
  }
  // Receives for `seconds`, ticking the injector every ms; `each_ms` runs once per ms.
  void Pump(double seconds, const std::function<void(int)>& each_ms = nullptr) {
    for (int ms = 0; ms < static_cast<int>(seconds * 1000); ++ms) {
      if (each_ms) each_ms(ms);
      injector_->Tick();
      while (listener_->handleTimeout(0) > 0) {
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    for (int ms = 0; ms < 30; ++ms) listener_->handleTimeout(1);  // what is still on its way
  }
  void Publish(const std::string& channel, std::uint64_t n) {
    const std::vector<std::uint8_t> bytes = Counter(n);
    publisher_->publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
  }
  // nft must exist and accept the rules; else the test is skipped with the reason.
  bool BeginOrSkip(const std::string& fault) {
    if (std::system("command -v nft > /dev/null 2>&1") != 0) {
      skip_reason_ = "nft is not installed (package nftables)";
      return false;
    }
    if (!injector_->Begin(SelectFaults({fault})[0])) {
      skip_reason_ = "nft refused the rules: " + injector_->Notes();
      return false;
    }
    return true;
  }

  std::string dir_, skip_reason_;
  Received received_;
  std::unique_ptr<lcm::LCM> listener_, publisher_;
  std::unique_ptr<GraphMonitor> monitor_;
  std::unique_ptr<FaultInjector> injector_;
};

TEST_F(FaultInjectorTest, HostilePayloadsReachEveryChannel) {
  for (std::string_view channel : channels::kAll) Publish(std::string(channel), 1);  // a "last message" each
  Pump(0.3);
  ASSERT_TRUE(injector_->Begin(SelectFaults({"hostile-payloads"})[0]));
  Pump(1.2);  // a round: one channel every 40 ms
  std::size_t largest = 0;
  for (std::string_view channel : channels::kAll) {
    EXPECT_GE(received_.Count(std::string(channel)), 5u) << channel;  // 1 + random x2, oversized, truncated
    for (const auto& p : received_.by_channel[std::string(channel)]) largest = std::max(largest, p.size());
  }
  EXPECT_GE(largest, 256u * 1024u);
  injector_->End();
}

// The goal faults' GOALs decode, and are what they claim: NaN, far outside the room, and a new
// goal every 50 ms inside the room with a yaw-only, unit quaternion and fresh goal ids.
TEST_F(FaultInjectorTest, GoalFaultsPublishGoalsOfTheirKind) {
  injector_.reset();
  FaultInjectorOptions options;
  options.lcm_url = kUrl;
  options.work_dir = dir_;
  options.graph_ancestor = getpid();
  options.room_min_m = Eigen::Vector3d(-2.0, -3.0, 0.5);
  options.room_max_m = Eigen::Vector3d(4.0, 5.0, 1.0);
  injector_ = std::make_unique<FaultInjector>(options, monitor_.get());
  const auto goals = [&] {
    std::vector<goal_t> out;
    for (const auto& bytes : received_.by_channel["GOAL"]) {
      goal_t goal;
      EXPECT_EQ(goal.decode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
      out.push_back(goal);
    }
    received_.by_channel.clear();
    return out;
  };
  ASSERT_TRUE(injector_->Begin(SelectFaults({"goal-nan"})[0]));
  Pump(0.1);
  injector_->End();
  std::vector<goal_t> got = goals();
  ASSERT_EQ(got.size(), 1u);
  EXPECT_TRUE(std::isnan(got[0].p_WE[0]));
  EXPECT_FALSE(got[0].has_hint);

  ASSERT_TRUE(injector_->Begin(SelectFaults({"goal-unreachable"})[0]));
  Pump(0.1);
  injector_->End();
  got = goals();
  ASSERT_EQ(got.size(), 1u);
  EXPECT_GT(got[0].p_WE[0], options.room_max_m.x() + 50.0);

  ASSERT_TRUE(injector_->Begin(SelectFaults({"goal-every-50ms"})[0]));
  Pump(0.6);
  injector_->End();
  got = goals();
  EXPECT_GE(got.size(), 8u);
  std::set<std::int64_t> ids;
  for (const goal_t& goal : got) {
    ids.insert(goal.goal_id);
    for (int i = 0; i < 3; ++i) {
      EXPECT_GE(goal.p_WE[i], options.room_min_m[i] - 1e-9);
      EXPECT_LE(goal.p_WE[i], options.room_max_m[i] + 1e-9);
    }
    const double norm2 = goal.quat_WE[0] * goal.quat_WE[0] + goal.quat_WE[3] * goal.quat_WE[3];
    EXPECT_NEAR(norm2, 1.0, 1e-9);  // unit, and about z only
    EXPECT_NEAR(goal.quat_WE[1], 0.0, 1e-12);
    EXPECT_NEAR(goal.quat_WE[2], 0.0, 1e-12);
  }
  EXPECT_EQ(ids.size(), got.size());
}

TEST_F(FaultInjectorTest, ReorderedCopiesArriveLateOnceEach) {
  ASSERT_TRUE(injector_->Begin(SelectFaults({"lcm-reorder"})[0]));
  std::uint64_t sent = 0;
  Pump(1.0, [&](int ms) {
    if (ms % 5 == 0) Publish("ROBOT_STATE", ++sent);
  });
  injector_->End();
  Pump(0.2);
  const auto& got = received_.by_channel["ROBOT_STATE"];
  std::uint64_t newest = 0;
  int older_after_newer = 0;
  for (const auto& bytes : got) {
    std::uint64_t n = 0;
    std::memcpy(&n, bytes.data(), 8);
    if (n < newest) ++older_after_newer;
    newest = std::max(newest, n);
  }
  EXPECT_GT(older_after_newer, static_cast<int>(sent) / 2);  // the late copies
  EXPECT_LE(got.size(), 2 * sent + 2);  // one copy each, not copies of copies
  EXPECT_GE(got.size(), 2 * sent - 10);
}

TEST_F(FaultInjectorTest, StaleLocalisationDropsBasePoseOnlyUntilCleared) {
  if (!BeginOrSkip("lcm-stale-localisation")) GTEST_SKIP() << skip_reason_;
  Pump(0.5, [&](int ms) {
    if (ms % 5 == 0) Publish("BASE_POSE", ms), Publish("BASE_POSE_X", ms), Publish("ROBOT_STATE", ms);
  });
  EXPECT_EQ(received_.Count("BASE_POSE"), 0u);
  EXPECT_EQ(received_.Count("BASE_POSE_X"), 100u);  // only the channel named exactly BASE_POSE
  EXPECT_EQ(received_.Count("ROBOT_STATE"), 100u);
  injector_->End();
  Pump(0.1, [&](int ms) {
    if (ms % 5 == 0) Publish("BASE_POSE", ms);
  });
  EXPECT_EQ(received_.Count("BASE_POSE"), 20u);
}

TEST_F(FaultInjectorTest, FrozenMapDropsMapUpdatesSmallAndFragmented) {
  if (!BeginOrSkip("lcm-map-frozen")) GTEST_SKIP() << skip_reason_;
  const std::vector<std::uint8_t> large(100 * 1024, 7);  // above LCM's fragment size: sent in fragments
  Pump(0.3, [&](int ms) {
    if (ms % 10 != 0) return;
    Publish("MAP_UPDATE", ms);
    publisher_->publish("MAP_UPDATE", large.data(), static_cast<unsigned>(large.size()));
    publisher_->publish("MAP_UPDATES", large.data(), static_cast<unsigned>(large.size()));
  });
  EXPECT_EQ(received_.Count("MAP_UPDATE"), 0u);
  EXPECT_EQ(received_.Count("MAP_UPDATES"), 30u);
  injector_->End();
  Pump(0.1, [&](int ms) {
    if (ms % 10 == 0) publisher_->publish("MAP_UPDATE", large.data(), static_cast<unsigned>(large.size()));
  });
  EXPECT_EQ(received_.Count("MAP_UPDATE"), 10u);
}

TEST_F(FaultInjectorTest, LcmDropLosesAboutOneDatagramInTen) {
  if (!BeginOrSkip("lcm-drop")) GTEST_SKIP() << skip_reason_;
  Pump(1.0, [&](int ms) { Publish("ROBOT_STATE", ms); });
  injector_->End();
  const std::size_t got = received_.Count("ROBOT_STATE");
  EXPECT_GT(got, 800u);  // 1000 sent; binomial(1000, 0.1) losses: mean 100, sd 9.5
  EXPECT_LT(got, 960u);
  Pump(0.1, [&](int ms) { Publish("BASE_VELOCITY", ms); });
  EXPECT_EQ(received_.Count("BASE_VELOCITY"), 100u);  // the rule is gone
}

}  // namespace
}  // namespace topay::tools
