#include "sim/monitor/contact_events.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

namespace topay::sim {
namespace {

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c);
  return buffer;
}

}  // namespace

ContactEvents::ContactEvents(std::vector<std::string> body_names,
                             std::int64_t max_recorded_events)
    : body_names_(std::move(body_names)), max_recorded_events_(max_recorded_events) {}

const std::vector<Contact>& ContactEvents::Step(double t_s, std::vector<RawContact>* contacts) {
  std::sort(contacts->begin(), contacts->end(),
            [](const RawContact& a, const RawContact& b) { return a.pair < b.pair; });
  started_.clear();
  active_.clear();
  next_open_.clear();
  std::size_t j = 0;  // open_ (sorted by pair), merged with the sorted contacts
  auto close_before = [&](std::int64_t pair) {
    for (; j < open_.size() && open_[j].pair < pair; ++j) {
      if (open_[j].event >= 0) events_[open_[j].event].active = false;
    }
  };
  for (const RawContact& raw : *contacts) {
    close_before(raw.pair);
    const Contact contact{t_s, body_names_[raw.body], raw.box, raw.depth_m};
    if (j < open_.size() && open_[j].pair == raw.pair) {  // the event goes on
      Open open = open_[j++];
      open.max_depth_m = std::max(open.max_depth_m, raw.depth_m);
      if (open.event >= 0) {
        ContactEvent& event = events_[open.event];
        event.max_depth_m = open.max_depth_m;
        event.last_t_s = t_s;
        ++event.steps;
      }
      next_open_.push_back(open);
    } else {  // a new event
      ++counts_.events;
      std::int64_t index = -1;
      if (static_cast<std::int64_t>(events_.size()) < max_recorded_events_) {
        index = static_cast<std::int64_t>(events_.size());
        events_.push_back({contact, raw.depth_m, t_s, 1, true});
      }
      next_open_.push_back({raw.pair, index, raw.depth_m});
      started_.push_back(contact);
    }
    active_.push_back(contact);
    counts_.max_depth_m = std::max(counts_.max_depth_m, raw.depth_m);
  }
  close_before(std::numeric_limits<std::int64_t>::max());
  std::swap(open_, next_open_);
  ++counts_.steps;
  if (!contacts->empty()) {
    ++counts_.steps_in_contact;
    if (std::isnan(counts_.first_contact_t_s)) counts_.first_contact_t_s = t_s;
  }
  return started_;
}

std::string ContactEvents::Report(int max_listed) const {
  if (counts_.events == 0) {
    return "collision monitor: no contact in " + std::to_string(counts_.steps) + " steps\n";
  }
  std::string out = "collision monitor: " + std::to_string(counts_.events) +
                    " contact events, " + std::to_string(counts_.steps_in_contact) + " of " +
                    std::to_string(counts_.steps) + " steps in contact" +
                    Format(", max depth %.4f m, first contact at t = %.3f s\n",
                           counts_.max_depth_m, counts_.first_contact_t_s);
  // The deepest recorded events first (ties: earlier first).
  std::vector<std::size_t> order(events_.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return events_[a].max_depth_m > events_[b].max_depth_m;
  });
  const std::size_t listed = std::min<std::size_t>(order.size(), std::max(max_listed, 0));
  for (std::size_t k = 0; k < listed; ++k) {
    const ContactEvent& e = events_[order[k]];
    out += "  " + Format("t = %.3f s: ", e.first.t_s) + e.first.body;
    if (e.first.box >= 0) out += " vs box " + std::to_string(e.first.box);
    out += Format(": depth %.4f m for %.3f s", e.max_depth_m, e.duration_s()) + " (" +
           std::to_string(e.steps) + " steps" + (e.active ? ", still in contact)\n" : ")\n");
  }
  if (listed < static_cast<std::size_t>(counts_.events)) {
    out += "  ... " + std::to_string(counts_.events - static_cast<std::int64_t>(listed)) +
           " more\n";
  }
  return out;
}

}  // namespace topay::sim
