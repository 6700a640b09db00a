#include "core/io/urdf_joint_cycles.h"

#include <tinyxml.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "core/common/error.h"

namespace topay {
namespace {

struct Edge {
  std::string joint;
  std::string child_link;
};

const char* LinkAttribute(const TiXmlElement& joint, const char* end) {
  const TiXmlElement* element = joint.FirstChildElement(end);
  return element == nullptr ? nullptr : element->Attribute("link");
}

// parent link -> its joints (every one, a second parent of a link included), in document order.
std::map<std::string, std::vector<Edge>> JointsByParent(const TiXmlElement& robot) {
  std::map<std::string, std::vector<Edge>> children;
  for (const TiXmlElement* joint = robot.FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const char* name = joint->Attribute("name");
    const char* parent = LinkAttribute(*joint, "parent");
    const char* child = LinkAttribute(*joint, "child");
    if (name == nullptr || parent == nullptr || child == nullptr) continue;  // urdfdom's to reject
    children[parent].push_back(Edge{name, child});
  }
  return children;
}

}  // namespace

void CheckNoJointCycle(const std::string& urdf_text, const std::string& source) {
  TiXmlDocument document;
  document.Parse(urdf_text.c_str());
  const TiXmlElement* robot = document.Error() ? nullptr : document.FirstChildElement("robot");
  if (robot == nullptr) return;
  const std::map<std::string, std::vector<Edge>> children = JointsByParent(*robot);
  enum class Mark { kOnPath, kDone };
  std::map<std::string, Mark> marks;
  // Depth first from every link, iteratively: (link, next joint to follow), and the joints of
  // the path taken to it.
  for (const auto& [start, ignored] : children) {
    if (marks.count(start) > 0) continue;
    std::vector<std::pair<std::string, std::size_t>> stack{{start, 0}};
    std::vector<const Edge*> path;
    marks[start] = Mark::kOnPath;
    while (!stack.empty()) {
      auto& [link, next] = stack.back();
      const auto edges = children.find(link);
      if (edges == children.end() || next == edges->second.size()) {
        marks[link] = Mark::kDone;
        stack.pop_back();
        if (!path.empty()) path.pop_back();
        continue;
      }
      const Edge& edge = edges->second[next++];
      const auto mark = marks.find(edge.child_link);
      if (mark != marks.end() && mark->second == Mark::kOnPath) {
        // The cycle: the path's joints from where it left edge.child_link, then edge.
        std::string cycle;
        const auto from = std::find_if(stack.begin(), stack.end(), [&](const auto& s) { return s.first == edge.child_link; });
        for (auto k = path.begin() + (from - stack.begin()); k != path.end(); ++k) cycle += "'" + (*k)->joint + "' -> ";
        cycle += "'" + edge.joint + "'";
        throw ConfigError(source, "joint[" + edge.joint + "].child",
                          "the joints " + cycle + " make a cycle: a URDF must be a tree");
      }
      if (mark != marks.end()) continue;  // done: no cycle through it
      marks[edge.child_link] = Mark::kOnPath;
      path.push_back(&edge);
      stack.emplace_back(edge.child_link, 0);
    }
  }
}

}  // namespace topay
