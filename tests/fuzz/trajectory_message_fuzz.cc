// The trajectory message to core trajectory conversion, as the tracker, the simulator's
// trajectory follower and the director run it: TRAJECTORY bytes -> poly_trajectory_t
// (CheckedDecode) -> msgs::PolyTrajectory (FromMessage) -> ArcYawTrajectory (ToArcYaw: the
// MINCO problem re-solved and compared). Checked for an accepted trajectory: a finite, positive
// duration; finite samples at the input's times in [0, duration]; and the same trajectory sent
// again (FromArcYaw, ToMessage) is accepted again.
// Input: [selector][u16 length][message bytes][u16 sample times...] (subscriber_fuzz.h record).
#include <cmath>
#include <cstdint>
#include <string>

#include "procs/msgs/convert_trajectory.h"
#include "procs/msgs/trajectory_from_message.h"
#include "tests/fuzz/subscriber_fuzz.h"

namespace {


void CheckSample(const topay::TrajectorySample& p) {
  const topay::WholeBodyState& s = p.state;
  FuzzCheck(std::isfinite(s.x_m) && std::isfinite(s.y_m) && std::isfinite(s.yaw_rad), "sampled pose finite");
  FuzzCheck(s.q_rad.allFinite(), "sampled joint positions finite");
  FuzzCheck(p.qd_radps.allFinite(), "sampled joint rates finite");
  FuzzCheck(p.qdd_radps2.allFinite(), "sampled joint accelerations finite");
  FuzzCheck(std::isfinite(p.v_mps) && std::isfinite(p.omega_radps) && std::isfinite(p.a_mps2) &&
                std::isfinite(p.beta_radps2),
            "sampled base rates finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  const std::uint8_t selector = in.Byte();
  const auto msg = DecodeFuzzed<poly_trajectory_t>(in.LengthPrefixed(), (selector & 0x80) != 0);
  if (!msg) return 0;
  std::string error;
  const std::optional<msgs::PolyTrajectory> poly = msgs::FromMessage(*msg, &error);
  if (!poly) return 0;
  const msgs::TrajectoryRebuildOptions options;
  const std::optional<ArcYawTrajectory> trajectory = msgs::ToArcYaw(*poly, options, &error);
  if (!trajectory) {
    FuzzCheck(!error.empty(), "a trajectory that cannot be rebuilt names why");
    return 0;
  }
  const double duration = trajectory->duration_s();
  FuzzCheck(std::isfinite(duration) && duration > 0, "duration finite and positive");
  TrajectorySample point = trajectory->MakePoint();
  for (int i = 0; i < 16 && !in.empty(); ++i) {
    trajectory->Evaluate(duration * in.U16() / 65535.0, &point);
    CheckSample(point);
  }
  const poly_trajectory_t again = msgs::ToMessage(msgs::FromArcYaw(*trajectory, poly->p0_W_m));
  const std::optional<msgs::PolyTrajectory> poly_again = msgs::FromMessage(again, &error);
  FuzzCheck(poly_again.has_value(), "an accepted trajectory sent again reads back");
  FuzzCheck(msgs::ToArcYaw(*poly_again, options, &error).has_value(), "an accepted trajectory sent again rebuilds");
  return 0;
}
