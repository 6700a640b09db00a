#pragma once

namespace topay {

/// The C2 map between an unconstrained variable tau and a piece duration T > 0 (TopAY paper
/// eq. (21), tau = L_c2(T); its inverse as the authors' code states it):
///   T(tau) = tau^2 / 2 + tau + 1            tau > 0,
///   T(tau) = 1 / (tau^2 / 2 - tau + 1)      tau <= 0,
/// onto (0, inf), increasing, with T(0) = 1, T'(0) = 1 and T''(0) = 1 from both sides.

/// T(tau) (s); if dT_dtau is non-null, also dT/dtau:
///   tau + 1 (tau > 0),  (1 - tau) / (tau^2 / 2 - tau + 1)^2 (tau <= 0).
double DurationFromTau(double tau, double* dT_dtau = nullptr);

/// tau = L_c2(T), eq. (21): sqrt(2 T - 1) - 1 for T > 1, 1 - sqrt(2 / T - 1) for 0 < T <= 1.
/// Throws std::invalid_argument naming the value if T is not finite and > 0.
double TauFromDuration(double duration_s);

}  // namespace topay
