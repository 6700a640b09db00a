#pragma once
// A 64-bit digest (FNV-1a over the bytes) of everything the simulator outputs, for the
// determinism checks: two runs with the same inputs must give the same digests.

#include <cstdint>
#include <cstring>

#include "procs/sim/sim_core.h"

namespace topay::simproc {

class OutputDigest : public SimListener {
 public:
  void OnState(const StateSample& s) override;
  void OnScan(const ScanResult& scan) override;
  void OnContact(const ContactResult& contact, int box_id) override;
  void OnEvent(const sim::SimEvent& event, double t_s, const std::string& error) override;

  std::uint64_t states() const { return states_; }
  std::uint64_t scans() const { return scans_; }
  std::uint64_t contacts() const { return contacts_; }
  std::uint64_t events() const { return events_; }
  std::int64_t num_states = 0, num_scans = 0, num_contacts = 0, num_events = 0;

 private:
  std::uint64_t states_ = 0xcbf29ce484222325ULL, scans_ = 0xcbf29ce484222325ULL;
  std::uint64_t contacts_ = 0xcbf29ce484222325ULL, events_ = 0xcbf29ce484222325ULL;
};

/// FNV-1a of `size` bytes into *hash.
void MixBytes(std::uint64_t* hash, const void* data, std::size_t size);

}  // namespace topay::simproc
