#include "procs/log_info/mcap_conversion.h"

#include <lcm/lcm-cpp.hpp>

#include <array>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "procs/log_info/mcap_writer.h"
#include "procs/viz/robot_view.h"
#include "procs/viz/viz_channels.h"
#include "procs/viz/viz_pipeline.h"

namespace topay::loginfo {
namespace {

using viz::kNumTopics;
using viz::Topic;

// One MCAP channel (with its schema) per viewer channel, registered up front.
std::array<std::uint16_t, kNumTopics> AddChannels(McapWriter* writer) {
  std::array<std::uint16_t, kNumTopics> ids{};
  for (const viz::VizChannel& c : viz::VizChannels()) {
    const std::uint16_t schema = writer->AddSchema(c.schema_name, "jsonschema", c.schema);
    ids[viz::Index(c.topic)] = writer->AddChannel(schema, c.name, "json");
  }
  return ids;
}

}  // namespace

std::string McapConversionSummary::Report() const {
  std::ostringstream out;
  out << events << " LCM events -> " << messages << " MCAP messages (" << malformed << " malformed LCM messages)\n";
  for (const auto& [topic, count] : per_topic) out << "  " << topic << ": " << count << "\n";
  return out.str();
}

McapConversionSummary ConvertLogToMcap(const std::string& log_path, const std::string& mcap_path,
                                       const McapConversionOptions& options) {
  lcm::LogFile log(log_path, "r");
  if (!log.good()) throw std::runtime_error(log_path + ": cannot open the LCM log");
  const viz::RobotView robot(options.robot_urdf, options.robot_yaml);
  McapWriter writer(mcap_path, {.profile = "", .library = "topay-log-info"});
  const std::array<std::uint16_t, kNumTopics> channels = AddChannels(&writer);
  const std::array<viz::VizChannel, kNumTopics> names = viz::VizChannels();
  McapConversionSummary summary;
  std::array<std::uint32_t, kNumTopics> sequence{};
  const auto write = [&](Topic topic, std::int64_t log_utime, const std::string& payload) {
    const std::size_t i = viz::Index(topic);
    const auto time_ns = static_cast<std::uint64_t>(std::max<std::int64_t>(0, log_utime)) * 1000;
    writer.WriteMessage(channels[i], ++sequence[i], time_ns, time_ns, payload);
    ++summary.messages;
    ++summary.per_topic[names[i].name];
  };
  viz::VizPipelineOptions pipeline_options;
  pipeline_options.rates = viz::VizRates::Unlimited();
  viz::VizPipeline pipeline(robot, pipeline_options, write);
  std::int64_t last_utime = 0;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    if (summary.events++ == 0) write(Topic::kRobotDescription, event->timestamp, pipeline.description());
    pipeline.Handle(event->channel, event->data, static_cast<std::size_t>(event->datalen), event->timestamp);
    last_utime = std::max(last_utime, event->timestamp);
  }
  pipeline.Flush(last_utime);
  writer.Close();
  summary.malformed = pipeline.counts().malformed;
  return summary;
}

}  // namespace topay::loginfo
