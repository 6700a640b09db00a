#pragma once
// Options of the base pose estimator (core/estimation/se2_estimator.h), Ceres style: every
// field has a documented default; Check() throws std::invalid_argument naming the first bad
// field. config/estimator/estimator.yaml restates the defaults (section `filter`; the process
// loads it, core/ reads no files). Equations: docs/estimator.md.

namespace topay {

struct EstimatorOptions {
  // Odometry process noise. The noise of one odometry increment (distance d = v dt, turn
  // dpsi = omega dt) grows linearly with the motion, so the variance after a path does not
  // depend on the odometry rate (a random walk in distance and angle):
  //   var(d)    = translation_var_m2_per_m * |d|
  //   var(dpsi) = rotation_var_rad2_per_rad * |dpsi| + rotation_var_rad2_per_m * |d|
  // Correlated relative slip (std dev s, correlation time tau) at speed v gives
  // var(d) ~ 2 s^2 tau v per metre: 1e-3 m^2/m covers s = 5 %, tau = 0.5 s up to v = 0.4 m/s.
  double translation_var_m2_per_m = 1e-3;   ///< distance variance per metre travelled (m^2/m), >= 0
  double rotation_var_rad2_per_rad = 1e-3;  ///< yaw variance per radian turned (rad^2/rad), >= 0
  double rotation_var_rad2_per_m = 1e-4;    ///< yaw variance per metre travelled (rad^2/m), >= 0
  // Motion the wheels do not see (a push, lateral skid), also at rest: keeps the filter from
  // becoming over-confident while standing still. Per axis x, y and yaw, per second.
  double diffusion_xy_m2_per_s = 1e-5;      ///< x and y variance per second (m^2/s), >= 0
  double diffusion_yaw_rad2_per_s = 1e-5;   ///< yaw variance per second (rad^2/s), >= 0

  // The pose measurement (BASE_POSE carries no covariance): R = diag(sxy^2, sxy^2, syaw^2).
  double pose_xy_stddev_m = 0.03;           ///< std dev of x and y, m, > 0
  double pose_yaw_stddev_rad = 0.02;        ///< std dev of yaw, rad, > 0

  // Outlier gating: a pose whose squared Mahalanobis distance nu^T S^-1 nu exceeds gate_chi2
  // is rejected (chi-square, 3 degrees of freedom: 16.27 is the 99.9 % quantile). After
  // reinit_after_rejections consecutive rejections the filter re-initialises from the latest
  // pose (x = z, P = R): a wrong initial pose or a relocalisation jump is adopted after that many.
  double gate_chi2 = 16.27;                 ///< > 0
  int reinit_after_rejections = 10;         ///< >= 1

  // History for delayed poses: the last history_capacity events (odometry samples and poses)
  // with the state after each. An input stamped more than max_delay_s before the newest event, or
  // older than the oldest event kept, is rejected as too old.
  int history_capacity = 512;               ///< events kept, in [4, 100000] (2.5 s at 200 Hz)
  double max_delay_s = 0.5;                 ///< s, > 0

  /// Throws std::invalid_argument naming the first field out of range.
  void Check() const;
};

}  // namespace topay
