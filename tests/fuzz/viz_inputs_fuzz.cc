// topay-viz's subscription (every channel of the graph, raw) through its pipeline (VizPipeline:
// CheckedDecode, the conversions to the viewer's JSON channels, decimation at unlimited rates
// so that every message is converted) and its flush, with the shipped robot and a clock the
// input advances. Checked: every payload forwarded to the browser is valid JSON.
// Input: subscriber_fuzz.h with the 25 channels of topay::channels::kAll (the selector's high
// bit is ignored: the pipeline decodes the raw bytes itself).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

#include "procs/viz/robot_view.h"
#include "procs/viz/viz_pipeline.h"
#include "tests/fuzz/subscriber_fuzz.h"
#include "topay_msgs/channels.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  static const viz::RobotView robot(ShippedConfig("robot/topay_mm.urdf"), ShippedConfig("robot/topay_mm.yaml"));
  viz::VizPipelineOptions options;
  options.rates = viz::VizRates::Unlimited();
  viz::VizPipeline pipeline(robot, options, [](viz::Topic, std::int64_t, const std::string& payload) {
    FuzzCheck(nlohmann::json::accept(payload), "the viewer is sent valid JSON");
  });
  constexpr int kNumChannels = static_cast<int>(channels::kAll.size());
  FuzzReader in(data, size);
  std::int64_t now = kFuzzT0Utime;
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, kNumChannels);
    if (!op) break;
    if (op->tick) {
      now += op->advance_us;
      pipeline.Flush(now);
      continue;
    }
    // A copy of exactly the message's size: reads past it are reads past an allocation.
    const std::vector<std::uint8_t> bytes(op->bytes.begin(), op->bytes.end());
    pipeline.Handle(channels::kAll[static_cast<std::size_t>(op->channel)], bytes.data(), bytes.size(), now);
  }
  pipeline.Flush(now);
  return 0;
}
