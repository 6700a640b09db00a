#include "procs/sim/output_digest.h"

namespace topay::simproc {

void MixBytes(std::uint64_t* hash, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    *hash ^= bytes[i];
    *hash *= 0x100000001b3ULL;
  }
}

namespace {

void MixDouble(std::uint64_t* hash, double value) { MixBytes(hash, &value, sizeof value); }

}  // namespace

void OutputDigest::OnState(const StateSample& s) {
  ++num_states;
  MixDouble(&states_, s.t_s);
  MixDouble(&states_, s.truth.state.x_m);
  MixDouble(&states_, s.truth.state.y_m);
  MixDouble(&states_, s.truth.state.yaw_rad);
  MixBytes(&states_, s.truth.state.q_rad.data(), sizeof(double) * s.truth.state.q_rad.size());
  MixBytes(&states_, s.truth.qdot_radps.data(), sizeof(double) * s.truth.qdot_radps.size());
  MixDouble(&states_, s.truth.v_mps);
  MixDouble(&states_, s.truth.omega_radps);
  MixDouble(&states_, s.truth.gripper);
  MixDouble(&states_, s.pose.x_m);
  MixDouble(&states_, s.pose.y_m);
  MixDouble(&states_, s.pose.yaw_rad);
  MixDouble(&states_, s.measured.v_mps);
  MixDouble(&states_, s.measured.omega_radps);
}

void OutputDigest::OnScan(const ScanResult& scan) {
  ++num_scans;
  MixDouble(&scans_, scan.t_s);
  MixBytes(&scans_, scan.X_WS.matrix().data(), sizeof(double) * 16);
  for (const Eigen::Vector3f& p : scan.p_SP) MixBytes(&scans_, p.data(), sizeof(float) * 3);
  MixBytes(&scans_, &scan.self_hits, sizeof scan.self_hits);
}

void OutputDigest::OnContact(const ContactResult& contact, int box_id) {
  ++num_contacts;
  MixDouble(&contacts_, contact.t_s);
  MixBytes(&contacts_, contact.body.data(), contact.body.size());
  MixBytes(&contacts_, &box_id, sizeof box_id);
  MixDouble(&contacts_, contact.depth_m);
}

void OutputDigest::OnEvent(const sim::SimEvent& event, double t_s, const std::string& error) {
  ++num_events;
  MixDouble(&events_, t_s);
  MixBytes(&events_, &event.box_id, sizeof event.box_id);
  MixBytes(&events_, error.data(), error.size());
}

}  // namespace topay::simproc
