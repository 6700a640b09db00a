#pragma once
// Whole turns of revolute joints. The kinematics are 2 pi periodic in a revolute joint's
// angle, so q_i and q_i + 2 pi k are the same pose of the robot; a joint whose limits span
// more than a turn (the wrist's joint 7 of the TopAY arm: [-6.28, 6.28] rad) can reach a pose
// on two branches. A goal on the far branch costs up to a full extra turn of travel (finding
// 29: an IK goal with q7 = 5.87 rad for a start at q7 = -5.52 rad asked the arm's RRT* for
// 11.4 rad of wrist travel within a 10 s base path, near the joint's speed limit all the way;
// the trees never met in 100,000 iterations, while the same goal at q7 = -0.41 rad is 5.1 rad
// away).

#include <Eigen/Core>

#include "core/robot/robot_model.h"

namespace topay {

/// q_rad with each revolute joint turned by the whole turns (2 pi k, k integer) that bring it
/// nearest q_reference_rad while staying within the joint's limits [q_min, q_max]: the same
/// pose (every link frame and collision sphere unchanged), the least joint travel from the
/// reference. A joint already nearest, a prismatic joint, or one whose limits leave no other
/// turn is unchanged. Sizes must be the model's joint count (std::invalid_argument otherwise);
/// a non-finite value is left as it is.
Eigen::VectorXd NearestJointTurns(const RobotModel& model, const Eigen::VectorXd& q_rad,
                                  const Eigen::VectorXd& q_reference_rad);

}  // namespace topay
