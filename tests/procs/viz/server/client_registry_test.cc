// The registry of open clients: add / remove / With under the lock, TakeAll, WaitEmpty.
#include "procs/viz/server/client_registry.h"

#include <gtest/gtest.h>

#include <thread>

namespace topay::viz {
namespace {

struct FakeSession {
  int value = 0;
};

TEST(ClientRegistryTest, AddWithRemove) {
  ClientRegistry<FakeSession> registry;
  registry.Add(1, std::make_shared<FakeSession>(FakeSession{10}));
  registry.Add(2, std::make_shared<FakeSession>(FakeSession{20}));
  EXPECT_EQ(registry.size(), 2u);
  int seen = 0;
  EXPECT_TRUE(registry.With(2, [&](FakeSession& session) { seen = session.value; }));
  EXPECT_EQ(seen, 20);
  EXPECT_FALSE(registry.With(3, [&](FakeSession&) { seen = -1; }));
  EXPECT_EQ(seen, 20);
  registry.Remove(2);
  registry.Remove(7);  // unknown: nothing
  EXPECT_FALSE(registry.With(2, [](FakeSession&) {}));
  EXPECT_EQ(registry.All().size(), 1u);
}

TEST(ClientRegistryTest, TakeAllEmptiesIt) {
  ClientRegistry<FakeSession> registry;
  registry.Add(5, std::make_shared<FakeSession>());
  registry.Add(6, std::make_shared<FakeSession>());
  const auto taken = registry.TakeAll();
  EXPECT_EQ(taken.size(), 2u);
  EXPECT_EQ(registry.size(), 0u);
}

TEST(ClientRegistryTest, WaitEmptyWakesWhenTheLastGoes) {
  ClientRegistry<FakeSession> registry;
  EXPECT_TRUE(registry.WaitEmpty(std::chrono::milliseconds(0)));
  registry.Add(1, std::make_shared<FakeSession>());
  EXPECT_FALSE(registry.WaitEmpty(std::chrono::milliseconds(10)));
  std::thread remover([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    registry.Remove(1);
  });
  EXPECT_TRUE(registry.WaitEmpty(std::chrono::seconds(5)));
  remover.join();
}

}  // namespace
}  // namespace topay::viz
