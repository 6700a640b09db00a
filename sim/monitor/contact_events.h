#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace topay::sim {

/// One body of the robot's collision model in contact with one box (or with itself).
struct Contact {
  double t_s = 0.0;   ///< Plant time, s.
  std::string body;   ///< "base", "sphere 5 (link link4)", "self: sphere 3 - sphere 11",
                      ///< "chassis: sphere 7 (link link5)".
  int box = -1;       ///< Index in the world's boxes; -1 for self and chassis contacts.
  double depth_m = 0.0;  ///< Penetration depth (> 0), m.
};

/// A contact that persists over consecutive checks is one event.
struct ContactEvent {
  Contact first;               ///< The contact at the event's first step.
  double max_depth_m = 0.0;    ///< Deepest over the event.
  double last_t_s = 0.0;       ///< Time of the event's last step in contact.
  std::int64_t steps = 0;      ///< Steps in contact.
  bool active = true;          ///< Still in contact at the last check.
  double duration_s() const { return last_t_s - first.t_s; }
};

/// One contact found at a step, before naming: `pair` identifies the (body, box) pair (the
/// same pair at consecutive steps continues an event), `body` indexes the caller's body names.
struct RawContact {
  std::int64_t pair = 0;
  int body = 0;
  int box = -1;
  double depth_m = 0.0;
};

/// The judge's bookkeeping over a run: contact events (a pair in contact over consecutive
/// steps is one event, with its maximum depth and duration), steps in contact, the maximum
/// depth and the first contact time.
class ContactEvents {
 public:
  struct Counts {
    std::int64_t events = 0;            ///< Contact events started.
    std::int64_t steps_in_contact = 0;  ///< Steps with at least one contact.
    std::int64_t steps = 0;             ///< Steps checked.
    double max_depth_m = 0.0;           ///< Deepest contact seen (0: none).
    double first_contact_t_s = std::numeric_limits<double>::quiet_NaN();  ///< NaN: none.
  };

  /// `body_names[b]` names body b of RawContact::body; at most max_recorded_events events
  /// are kept in events() (counting goes on beyond it).
  explicit ContactEvents(std::vector<std::string> body_names,
                         std::int64_t max_recorded_events = 100000);

  /// One step's contacts (any order; at most one per pair). Updates the counts and events and
  /// returns the contacts of the events that started at this step (sorted by pair).
  const std::vector<Contact>& Step(double t_s, std::vector<RawContact>* contacts);

  /// Every contact of the last step, sorted by pair.
  const std::vector<Contact>& active() const { return active_; }
  const Counts& counts() const { return counts_; }
  /// The recorded events in start order (the first max_recorded_events).
  const std::vector<ContactEvent>& events() const { return events_; }
  const std::string& body_name(int body) const { return body_names_[body]; }

  /// A few lines for a log: the counts, then the deepest recorded events (at most
  /// max_listed), one a line.
  std::string Report(int max_listed = 10) const;

 private:
  struct Open {
    std::int64_t pair;
    std::int64_t event;  // index in events_, or -1 if beyond the recording limit
    double max_depth_m;  // kept here too for unrecorded events
  };

  std::vector<std::string> body_names_;
  std::int64_t max_recorded_events_;
  Counts counts_;
  std::vector<ContactEvent> events_;
  std::vector<Open> open_;       // sorted by pair
  std::vector<Open> next_open_;  // scratch
  std::vector<Contact> started_;
  std::vector<Contact> active_;
};

}  // namespace topay::sim
