#include "core/robot/self_collision.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

void CheckGradientShape(const Eigen::MatrixXd* gradients, int rows, int cols, const char* what) {
  if (gradients && (gradients->rows() != rows || gradients->cols() != cols)) {
    throw std::invalid_argument(std::string("SelfCollision: ") + what + " must be " +
                                std::to_string(rows) + " x " + std::to_string(cols));
  }
}

}  // namespace

std::vector<int> RigidBodiesOfLinks(const RobotModel& model) {
  std::vector<int> body(model.links.size());
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Link& link = model.links[i];
    const bool welded = link.parent >= 0 && link.joint_type == JointType::kFixed;
    body[i] = welded ? body[link.parent] : static_cast<int>(i);
  }
  return body;
}

std::vector<std::pair<int, int>> FindSelfCollisionPairs(const RobotModel& model) {
  const std::vector<int> body = RigidBodiesOfLinks(model);
  // The body a body hangs from through its movable joint (-1 for the root body).
  auto parent_body = [&](int b) {
    return model.links[b].parent < 0 ? -1 : body[model.links[b].parent];
  };
  const Kinematics kinematics(model);
  KinematicsCache cache = kinematics.MakeCache();
  WholeBodyState zero;
  zero.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  kinematics.Update(zero, &cache);

  std::vector<std::pair<int, int>> pairs;
  const int num_spheres = static_cast<int>(model.spheres.size());
  for (int i = 0; i < num_spheres; ++i) {
    for (int j = i + 1; j < num_spheres; ++j) {
      const int bi = body[model.spheres[i].link];
      const int bj = body[model.spheres[j].link];
      if (bi == bj || parent_body(bi) == bj || parent_body(bj) == bi) continue;
      const double gap = (cache.p_WS[i] - cache.p_WS[j]).norm() - model.spheres[i].radius_m -
                         model.spheres[j].radius_m;
      if (gap > 0.0) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

SelfCollision::SelfCollision(const Kinematics& kinematics) : kinematics_(kinematics) {
  for (const auto& [i, j] : pairs()) {
    if (i < 0 || j < 0 || i >= num_spheres() || j >= num_spheres()) {
      throw std::invalid_argument("SelfCollision: a self-collision pair names a missing sphere");
    }
  }
}

double SelfCollision::PairDistance(const KinematicsCache& cache, int k,
                                   Eigen::Vector3d* n_W) const {
  const auto [i, j] = pairs()[k];
  const Eigen::Vector3d r_W = cache.p_WS[i] - cache.p_WS[j];
  const double norm = r_W.norm();
  *n_W = norm > 0.0 ? Eigen::Vector3d(r_W / norm) : Eigen::Vector3d::Zero();
  // Signed distance between spheres: |p_i - p_j| - r_i - r_j.
  return norm - model().spheres[i].radius_m - model().spheres[j].radius_m;
}

// grad d = J_i^T n - J_j^T n  (d|r|/dr = r/|r| = n, r = p_i - p_j).
void SelfCollision::AddPairGradient(const KinematicsCache& cache, int k, const Eigen::Vector3d& n_W,
                                    Eigen::Ref<Eigen::VectorXd> gradient) const {
  const auto [i, j] = pairs()[k];
  kinematics_.AddPointJacobianTransposeTimes(cache, model().spheres[i].link, cache.p_WS[i], n_W,
                                             gradient);
  kinematics_.AddPointJacobianTransposeTimes(cache, model().spheres[j].link, cache.p_WS[j], -n_W,
                                             gradient);
}

void SelfCollision::Distances(const KinematicsCache& cache, Eigen::Ref<Eigen::VectorXd> distances_m,
                              Eigen::MatrixXd* gradients) const {
  if (distances_m.size() != num_pairs()) {
    throw std::invalid_argument(
        "SelfCollision::Distances: distances must have num_pairs() entries");
  }
  CheckGradientShape(gradients, kinematics_.num_states(), num_pairs(), "gradients");
  if (gradients) gradients->setZero();
  for (int k = 0; k < num_pairs(); ++k) {
    Eigen::Vector3d n_W;
    distances_m(k) = PairDistance(cache, k, &n_W);
    if (gradients) AddPairGradient(cache, k, n_W, gradients->col(k));
  }
}

double SelfCollision::MinDistance(const KinematicsCache& cache, Eigen::VectorXd* gradient) const {
  if (gradient && gradient->size() != kinematics_.num_states()) {
    throw std::invalid_argument("SelfCollision::MinDistance: gradient must have 3+N entries");
  }
  double min_distance = std::numeric_limits<double>::infinity();
  int min_pair = -1;
  Eigen::Vector3d min_n_W = Eigen::Vector3d::Zero();
  for (int k = 0; k < num_pairs(); ++k) {
    Eigen::Vector3d n_W;
    const double distance = PairDistance(cache, k, &n_W);
    if (distance < min_distance) {
      min_distance = distance;
      min_pair = k;
      min_n_W = n_W;
    }
  }
  if (gradient) {
    gradient->setZero();
    if (min_pair >= 0) AddPairGradient(cache, min_pair, min_n_W, *gradient);
  }
  return min_distance;
}

void SelfCollision::ChassisMargins(const KinematicsCache& cache,
                                   Eigen::Ref<Eigen::VectorXd> margins_m,
                                   Eigen::MatrixXd* gradients) const {
  if (margins_m.size() != num_spheres()) {
    throw std::invalid_argument("SelfCollision::ChassisMargins: margins must have one per sphere");
  }
  CheckGradientShape(gradients, kinematics_.num_states(), num_spheres(), "gradients");
  if (gradients) gradients->setZero();
  const double top_m = model().base_cylinder.height_m;
  for (int s = 0; s < num_spheres(); ++s) {
    const CollisionSphere& sphere = model().spheres[s];
    // Lowest point of the sphere above the chassis top: z_s - r_s - h.
    margins_m(s) = cache.p_WS[s].z() - sphere.radius_m - top_m;
    if (gradients) {
      kinematics_.AddPointJacobianTransposeTimes(cache, sphere.link, cache.p_WS[s],
                                                 Eigen::Vector3d::UnitZ(), gradients->col(s));
    }
  }
}

}  // namespace topay
