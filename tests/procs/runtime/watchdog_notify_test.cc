// The watchdog datagrams beside the HEARTBEAT (procs/runtime/watchdog_notify.h): a notifier
// reaches a bound socket, which names the sender's pid from the kernel's credentials; without
// NOTIFY_SOCKET a notifier does nothing; bad socket names are errors that name the socket.

#include "procs/runtime/watchdog_notify.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace topay::procs {
namespace {

struct Received {
  std::vector<std::pair<pid_t, std::string>> messages;
  void Read(WatchdogSocket& socket) {
    socket.ReadAll([this](pid_t pid, std::string_view text) { messages.emplace_back(pid, std::string(text)); });
  }
};

TEST(WatchdogNotify, ADatagramReachesTheAbstractSocketWithTheSendersPid) {
  WatchdogSocket socket("@topay-watchdog-test-" + std::to_string(getpid()));
  WatchdogNotifier notifier(socket.name());
  ASSERT_TRUE(notifier.enabled());
  ASSERT_TRUE(notifier.Notify()) << notifier.error();
  ASSERT_TRUE(notifier.Notify()) << notifier.error();
  Received r;
  r.Read(socket);
  ASSERT_EQ(r.messages.size(), 2u);
  EXPECT_EQ(r.messages[0].first, getpid());
  EXPECT_EQ(r.messages[0].second, kWatchdogMessage);
  r.messages.clear();
  r.Read(socket);  // nothing left: returns at once
  EXPECT_TRUE(r.messages.empty());
}

TEST(WatchdogNotify, APathSocketWorksAndIsRemovedWithIt) {
  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/watchdog_notify";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/notify.sock";
  {
    WatchdogSocket socket(path);
    EXPECT_TRUE(std::filesystem::exists(path));
    WatchdogNotifier notifier(path);
    ASSERT_TRUE(notifier.Notify()) << notifier.error();
    Received r;
    r.Read(socket);
    ASSERT_EQ(r.messages.size(), 1u);
    EXPECT_EQ(r.messages[0].first, getpid());
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(WatchdogNotify, WithoutNotifySocketTheNotifierDoesNothing) {
  unsetenv(kNotifySocketEnv);
  WatchdogNotifier notifier;
  EXPECT_FALSE(notifier.enabled());
  EXPECT_FALSE(notifier.Notify());
}

TEST(WatchdogNotify, ASocketNobodyListensOnIsAnErrorNamingIt) {
  WatchdogNotifier notifier("@topay-watchdog-test-nobody-" + std::to_string(getpid()));
  ASSERT_TRUE(notifier.enabled());
  EXPECT_FALSE(notifier.Notify());
  EXPECT_NE(notifier.error().find("topay-watchdog-test-nobody"), std::string::npos) << notifier.error();
}

TEST(WatchdogNotify, ANameTooLongOrEmptyIsRefusedWithTheName) {
  try {
    WatchdogSocket socket("/tmp/" + std::string(200, 'x'));
    FAIL() << "a 205-character path was bound";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("longer than"), std::string::npos) << e.what();
  }
  EXPECT_THROW(WatchdogSocket(""), std::runtime_error);
}

}  // namespace
}  // namespace topay::procs
