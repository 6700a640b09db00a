#include "core/robot/kinematics.h"

#include <stdexcept>
#include <string>

namespace topay {
namespace {

// Motion of a child frame C relative to its joint frame J (URDF): a rotation by q about axis_J
// (revolute, Rodrigues' formula via AngleAxis) or a translation by q along axis_J (prismatic).
Eigen::Isometry3d JointMotion(const Link& link, double q) {
  Eigen::Isometry3d X_JC = Eigen::Isometry3d::Identity();
  if (link.joint_type == JointType::kRevolute) {
    X_JC.linear() = Eigen::AngleAxisd(q, link.axis_J).toRotationMatrix();
  } else if (link.joint_type == JointType::kPrismatic) {
    X_JC.translation() = link.axis_J * q;
  }
  return X_JC;
}

void CheckIndex(int index, int size, const char* what) {
  if (index < 0 || index >= size) {
    throw std::invalid_argument(std::string("Kinematics: ") + what + " index " +
                                std::to_string(index) + " out of range [0, " +
                                std::to_string(size) + ")");
  }
}

void CheckShape(const Eigen::Ref<Eigen::MatrixXd>& J, int rows, int cols, const char* what) {
  if (J.rows() != rows || J.cols() != cols) {
    throw std::invalid_argument(std::string("Kinematics: ") + what + " must be " +
                                std::to_string(rows) + " x " + std::to_string(cols) + ", got " +
                                std::to_string(J.rows()) + " x " + std::to_string(J.cols()));
  }
}

}  // namespace

Kinematics::Kinematics(const RobotModel& model) : model_(model) {
  const int num_links = static_cast<int>(model_.links.size());
  ancestor_links_with_joints_.resize(num_links);
  for (int i = 0; i < num_links; ++i) {
    const Link& link = model_.links[i];
    if (link.parent >= i) {
      throw std::invalid_argument("Kinematics: links are not in topological order at link '" +
                                  link.name + "'");
    }
    if (link.parent >= 0) ancestor_links_with_joints_[i] = ancestor_links_with_joints_[link.parent];
    if (link.q_index >= 0) ancestor_links_with_joints_[i].push_back(i);
  }
  rotation_sin_terms_.assign(num_links, Eigen::Matrix3d::Zero());
  rotation_cos_terms_.assign(num_links, Eigen::Matrix3d::Zero());
  for (int i = 0; i < num_links; ++i) {
    const Link& link = model_.links[i];
    if (link.joint_type != JointType::kRevolute) continue;
    const Eigen::Vector3d a = link.axis_J.normalized();
    Eigen::Matrix3d K;
    K << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    rotation_sin_terms_[i] = link.X_PJ.linear() * K;
    rotation_cos_terms_[i] = rotation_sin_terms_[i] * K;
  }
  for (const CollisionSphere& sphere : model_.spheres)
    CheckIndex(sphere.link, num_links, "sphere link");
  if (model_.end_effector_link >= 0)
    CheckIndex(model_.end_effector_link, num_links, "end-effector link");
}

KinematicsCache Kinematics::MakeCache() const {
  KinematicsCache cache;
  cache.X_WL.assign(model_.links.size(), Eigen::Isometry3d::Identity());
  cache.p_WS.assign(model_.spheres.size(), Eigen::Vector3d::Zero());
  return cache;
}

void Kinematics::Update(const WholeBodyState& state, KinematicsCache* cache) const {
  if (state.num_joints() != num_joints()) {
    throw std::invalid_argument("Kinematics::Update: state has " +
                                std::to_string(state.num_joints()) + " joints, the model " +
                                std::to_string(num_joints()));
  }
  if (!state.IsFinite()) throw std::invalid_argument("Kinematics::Update: state is not finite");
  if (cache->X_WL.size() != model_.links.size() || cache->p_WS.size() != model_.spheres.size()) {
    throw std::invalid_argument("Kinematics::Update: cache not made by this Kinematics");
  }
  cache->X_WB = state.BasePose();
  const int num_links = static_cast<int>(model_.links.size());
  for (int i = 0; i < num_links; ++i) {
    const Link& link = model_.links[i];
    const Eigen::Isometry3d& X_WP = link.parent < 0 ? cache->X_WB : cache->X_WL[link.parent];
    // X_WC = X_WP * X_PJ * X_JC(q)  (URDF joint convention, see Link), with X_PC = X_PJ X_JC.
    Eigen::Isometry3d& X_WC = cache->X_WL[i];
    switch (link.joint_type) {
      case JointType::kRevolute: {
        const double q = state.q_rad(link.q_index);
        const double s = std::sin(q), one_minus_c = 1.0 - std::cos(q);
        const Eigen::Matrix3d R_PC =
            link.X_PJ.linear() + s * rotation_sin_terms_[i] + one_minus_c * rotation_cos_terms_[i];
        X_WC.linear().noalias() = X_WP.linear() * R_PC;
        X_WC.translation().noalias() = X_WP.linear() * link.X_PJ.translation();
        X_WC.translation() += X_WP.translation();
        break;
      }
      case JointType::kPrismatic:
        X_WC = X_WP * link.X_PJ * JointMotion(link, state.q_rad(link.q_index));
        break;
      default:
        X_WC = X_WP * link.X_PJ;
    }
  }
  for (size_t s = 0; s < model_.spheres.size(); ++s) {
    const CollisionSphere& sphere = model_.spheres[s];
    cache->p_WS[s] = cache->X_WL[sphere.link] * sphere.p_LS_m;
  }
  if (model_.end_effector_link >= 0) {
    cache->X_WE = cache->X_WL[model_.end_effector_link] * model_.X_LE;
  }
}

void Kinematics::PointJacobian(const KinematicsCache& cache, int link, const Eigen::Vector3d& p_WP,
                               bool with_angular, Eigen::Ref<Eigen::MatrixXd> J) const {
  J.setZero();
  const int lin = with_angular ? 3 : 0;  // first row of the translational block
  // Base translation: d p / d x = e_x, d p / d y = e_y.
  J(lin + 0, 0) = 1.0;
  J(lin + 1, 1) = 1.0;
  // Base yaw about the world z axis through p_WB: d p / d yaw = e_z x (p - p_WB).
  const Eigen::Vector3d r_BP_W = p_WP - cache.X_WB.translation();
  J.block<3, 1>(lin, 2) = Eigen::Vector3d(-r_BP_W.y(), r_BP_W.x(), 0.0);
  if (with_angular) J(2, 2) = 1.0;
  for (int j : ancestor_links_with_joints_[link]) {
    const Link& joint_link = model_.links[j];
    const Eigen::Isometry3d& X_WJ = cache.X_WL[j];  // joint frame = child frame (URDF)
    const Eigen::Vector3d axis_W = X_WJ.linear() * joint_link.axis_J;
    const int col = 3 + joint_link.q_index;
    if (joint_link.joint_type == JointType::kRevolute) {
      // Revolute column of the geometric Jacobian (Siciliano et al., Robotics: Modelling,
      // Planning and Control, 2009, Sec. 3.1.3): [a; a x (p - o)].
      J.block<3, 1>(lin, col) = axis_W.cross(p_WP - X_WJ.translation());
      if (with_angular) J.block<3, 1>(0, col) = axis_W;
    } else {
      // Prismatic column (same section): [0; a].
      J.block<3, 1>(lin, col) = axis_W;
    }
  }
}

void Kinematics::SphereJacobian(const KinematicsCache& cache, int sphere,
                                Eigen::Ref<Eigen::MatrixXd> J_WS) const {
  CheckIndex(sphere, static_cast<int>(model_.spheres.size()), "sphere");
  CheckShape(J_WS, 3, num_states(), "SphereJacobian J_WS");
  PointJacobian(cache, model_.spheres[sphere].link, cache.p_WS[sphere], false, J_WS);
}

void Kinematics::EndEffectorJacobian(const KinematicsCache& cache,
                                     Eigen::Ref<Eigen::MatrixXd> J_WE) const {
  if (model_.end_effector_link < 0) {
    throw std::invalid_argument("Kinematics::EndEffectorJacobian: model has no end effector");
  }
  CheckShape(J_WE, 6, num_states(), "EndEffectorJacobian J_WE");
  PointJacobian(cache, model_.end_effector_link, cache.X_WE.translation(), true, J_WE);
}

void Kinematics::LinkJacobian(const KinematicsCache& cache, int link,
                              Eigen::Ref<Eigen::MatrixXd> J_WL) const {
  CheckIndex(link, static_cast<int>(model_.links.size()), "link");
  CheckShape(J_WL, 6, num_states(), "LinkJacobian J_WL");
  PointJacobian(cache, link, cache.X_WL[link].translation(), true, J_WL);
}

void Kinematics::AddPointJacobianTransposeTimes(const KinematicsCache& cache, int link,
                                                const Eigen::Vector3d& p_WP,
                                                const Eigen::Vector3d& f_W,
                                                Eigen::Ref<Eigen::VectorXd> gradient) const {
  CheckIndex(link, static_cast<int>(model_.links.size()), "link");
  if (gradient.size() != num_states()) {
    throw std::invalid_argument("Kinematics::AddPointJacobianTransposeTimes: gradient size " +
                                std::to_string(gradient.size()) +
                                " != " + std::to_string(num_states()));
  }
  // Column by column, f . J_col with the columns of PointJacobian.
  gradient(0) += f_W.x();
  gradient(1) += f_W.y();
  const Eigen::Vector3d r_BP_W = p_WP - cache.X_WB.translation();
  gradient(2) += f_W.dot(Eigen::Vector3d(-r_BP_W.y(), r_BP_W.x(), 0.0));
  for (int j : ancestor_links_with_joints_[link]) {
    const Link& joint_link = model_.links[j];
    const Eigen::Isometry3d& X_WJ = cache.X_WL[j];
    const Eigen::Vector3d axis_W = X_WJ.linear() * joint_link.axis_J;
    const Eigen::Vector3d column = joint_link.joint_type == JointType::kRevolute
                                       ? Eigen::Vector3d(axis_W.cross(p_WP - X_WJ.translation()))
                                       : axis_W;
    gradient(3 + joint_link.q_index) += f_W.dot(column);
  }
}

Eigen::Isometry3d Kinematics::EndEffectorPose(const WholeBodyState& state) const {
  KinematicsCache cache = MakeCache();
  Update(state, &cache);
  return cache.X_WE;
}

}  // namespace topay
