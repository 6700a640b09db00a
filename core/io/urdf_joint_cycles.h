#pragma once
// A URDF's joints read from the XML before urdfdom builds its tree: urdfdom links every joint's
// child into its parent's list of shared pointers, so a cycle of joints (a link its own parent,
// or a ring of links) is a cycle of shared pointers that urdfdom never frees when it then
// rejects the model (no root, two roots). Found by the robot_model fuzz target (LeakSanitizer);
// docs/reliability.md.

#include <string>

namespace topay {

/// Throws ConfigError (source, "joint[<name>].child") if the <joint> elements of the document's
/// <robot> make a cycle, naming its joints ("'j2' -> 'j3'"). Text that is not XML, or has no
/// <robot>, passes: urdfdom rejects it without building a tree.
void CheckNoJointCycle(const std::string& urdf_text, const std::string& source);

}  // namespace topay
