#pragma once
// MotorSimOptions from YAML (config/sim/motorsim.yaml documents every key and its default;
// docs/motorsim.md has the table). Every key is optional; unknown keys and bad values are
// ConfigErrors naming the file and the key.

#include <string>

#include "sim/motors/motor_sim.h"

namespace topay::sim::motors {

/// Loads the YAML at `path`. Throws ConfigError naming the file and key.
MotorSimOptions LoadMotorSimOptions(const std::string& path);

/// The same from YAML text (`source` names it in errors), for tests.
MotorSimOptions ParseMotorSimOptions(const std::string& yaml_text, const std::string& source);

}  // namespace topay::sim::motors
