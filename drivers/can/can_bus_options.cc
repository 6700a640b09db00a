#include "drivers/can/can_bus_options.h"

#include <stdexcept>
#include <string>

namespace topay::can {

void CanBusOptions::Check() const {
  if (receive_buffer_bytes < 0) {
    throw std::invalid_argument("CanBusOptions.receive_buffer_bytes must be >= 0, got " +
                                std::to_string(receive_buffer_bytes));
  }
  if (filters.size() > 512) {  // CAN_RAW_FILTER_MAX
    throw std::invalid_argument("CanBusOptions.filters: at most 512 filters, got " +
                                std::to_string(filters.size()));
  }
}

}  // namespace topay::can
