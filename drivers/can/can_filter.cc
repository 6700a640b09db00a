#include "drivers/can/can_filter.h"

#include <cstdio>

namespace topay::can {

CanFilter CanFilter::Standard(std::uint32_t id, std::uint32_t mask) {
  // The EFF flag in the mask (and not in the id) keeps extended frames out.
  return CanFilter{id & CAN_SFF_MASK, (mask & CAN_SFF_MASK) | CAN_EFF_FLAG};
}

CanFilter CanFilter::Extended(std::uint32_t id, std::uint32_t mask) {
  return CanFilter{(id & CAN_EFF_MASK) | CAN_EFF_FLAG, (mask & CAN_EFF_MASK) | CAN_EFF_FLAG};
}

bool Matches(const CanFilter& filter, const CanFrame& frame) {
  if (frame.error) return true;
  std::uint32_t frame_id = frame.id;
  if (frame.extended) frame_id |= CAN_EFF_FLAG;
  if (frame.remote) frame_id |= CAN_RTR_FLAG;
  const bool invert = (filter.can_id & CAN_INV_FILTER) != 0;
  const std::uint32_t want = filter.can_id & ~CAN_INV_FILTER;
  const bool match = (frame_id & filter.can_mask) == (want & filter.can_mask);
  return match != invert;
}

bool PassesFilters(const std::vector<CanFilter>& filters, const CanFrame& frame) {
  if (filters.empty()) return true;
  for (const CanFilter& filter : filters) {
    if (Matches(filter, frame)) return true;
  }
  return false;
}

std::string ToString(const CanFilter& filter) {
  char text[32];
  const bool invert = (filter.can_id & CAN_INV_FILTER) != 0;
  std::snprintf(text, sizeof(text), "%X%c%X", filter.can_id & ~CAN_INV_FILTER, invert ? '~' : ':',
                filter.can_mask);
  return text;
}

}  // namespace topay::can
