#include "procs/viz/live_source.h"

namespace topay::viz {
namespace {

void OnMessage(const lcm::ReceiveBuffer* rbuf, const std::string& channel, VizFeed* feed) {
  feed->Handle(channel, rbuf->data, rbuf->data_size, rbuf->recv_utime);
}

}  // namespace

lcm::Subscription* SubscribeAllChannels(lcm::LCM* lcm, VizFeed* feed, int queue_capacity) {
  lcm::Subscription* subscription = lcm->subscribeFunction(".*", &OnMessage, feed);
  if (subscription != nullptr) subscription->setQueueCapacity(queue_capacity);
  return subscription;
}

}  // namespace topay::viz
