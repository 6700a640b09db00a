// topay-lcm-latency: one-way LCM latency between two processes on one machine. `--role send`
// publishes --count messages of --size bytes on LATENCY_PROBE at --rate-hz, each starting with
// its CLOCK_MONOTONIC send time; `--role receive` prints the latency statistics once it has
// --count messages or --timeout seconds have passed (lost messages reported).
// Exit codes: 0, 1 LCM error, 2 usage error.

#include <time.h>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstring>
#include <iostream>
#include <vector>

#include "procs/lcm_latency/latency_summary.h"
#include "procs/runtime/process_loop.h"

using namespace topay;

namespace {

std::int64_t MonotonicNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return std::int64_t{ts.tv_sec} * 1'000'000'000 + ts.tv_nsec;
}

struct Receiver {
  std::vector<double> latencies_us;
  void On(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    const std::int64_t now = MonotonicNs();
    if (rbuf->data_size < sizeof(std::int64_t)) return;
    std::int64_t sent = 0;
    std::memcpy(&sent, rbuf->data, sizeof(sent));
    latencies_us.push_back(static_cast<double>(now - sent) * 1e-3);
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-lcm-latency: one-way LCM latency between two processes"};
  procs::ProcessOptions options;
  procs::AddCommonFlags(&app, "topay-lcm-latency", &options);
  std::string role;
  int count = 1000, size = 2048;
  double rate_hz = 100.0, timeout_s = 60.0;
  app.add_option("--role", role, "send or receive")->required()->check(CLI::IsMember({"send", "receive"}));
  app.add_option("--count", count, "messages")->capture_default_str();
  app.add_option("--size", size, "bytes per message (>= 8)")->capture_default_str()->check(CLI::Range(8, 64 << 20));
  app.add_option("--rate-hz", rate_hz, "send rate")->capture_default_str()->check(CLI::Range(0.1, 100000.0));
  app.add_option("--timeout", timeout_s, "receiver gives up after this many s")->capture_default_str();
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  procs::ProcessLoop loop(options);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  const std::string channel = "LATENCY_PROBE";
  Receiver receiver;
  int sent = 0;
  std::vector<std::uint8_t> payload(static_cast<std::size_t>(size), 0x5a);
  if (role == "receive") {
    loop.lcm().subscribe(channel, &Receiver::On, &receiver);
    loop.AddTimer(0.01, [&] {
      if (static_cast<int>(receiver.latencies_us.size()) >= count) loop.Stop();
    });
  } else {
    loop.AddTimer(1.0 / rate_hz, [&] {
      if (sent >= count) return loop.Stop();
      const std::int64_t now = MonotonicNs();
      std::memcpy(payload.data(), &now, sizeof(now));
      loop.lcm().publish(channel, payload.data(), static_cast<unsigned>(payload.size()));
      ++sent;
    });
  }
  const int code = loop.RunUntil(procs::ProcessLoop::Clock::now() +
                                 std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(timeout_s)));
  if (role == "receive") {
    const auto summary = latency::Summarize(receiver.latencies_us);
    std::cout << "size " << size << " B: " << latency::Format(summary) << ", lost " << count - summary.count << " of "
              << count << "\n";
  }
  return code;
}
