#include "spira/kinematics/urdf_parse.h"

#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <map>

#include "spira/base/error.h"

namespace spira {
namespace {

constexpr const char* kTreeHint =
    "a URDF robot is a tree: give every link but the root exactly one parent joint";

const char* linkOf(const TiXmlElement& joint, const char* role)
{
  const TiXmlElement* e = joint.FirstChildElement(role);
  return e ? e->Attribute("link") : nullptr;
}

void checkJointTree(const std::string& xml)
{
  TiXmlDocument doc;
  doc.Parse(xml.c_str());
  const TiXmlElement* robot = doc.Error() ? nullptr : doc.FirstChildElement("robot");
  if (!robot) return;  // urdfdom refuses it without building anything
  struct Edge {
    std::string parent, joint;
  };
  std::map<std::string, Edge> up;  // child link -> its parent link and the joint between them
  for (const TiXmlElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    const char* parent = linkOf(*j, "parent");
    const char* child = linkOf(*j, "child");
    const char* name = j->Attribute("name");
    if (!parent || !child) continue;
    const std::string jointName = name ? name : "(unnamed)";
    const auto [it, added] = up.emplace(child, Edge{parent, jointName});
    if (!added)
      throw InputError("the robot description's link '" + std::string(child) +
                           "' is the child of two joints ('" + it->second.joint + "' and '" + jointName +
                           "')",
                       kTreeHint);
  }
  // Each link has at most one parent, so walking up from any link either ends at a root or loops.
  std::map<std::string, int> state;  // 1: on the current walk, 2: known to reach a root
  for (const auto& start : up) {
    std::string link = start.first;
    while (true) {
      int& s = state[link];
      if (s == 2) break;
      if (s == 1)
        throw InputError("the robot description's joints form a loop through link '" + link + "' (joint '" +
                             up.at(link).joint + "')",
                         kTreeHint);
      s = 1;
      const auto parent = up.find(link);
      if (parent == up.end()) break;
      link = parent->second.parent;
    }
    for (std::string l = start.first; state[l] == 1;) {
      state[l] = 2;
      const auto parent = up.find(l);
      if (parent == up.end()) break;
      l = parent->second.parent;
    }
  }
}

}  // namespace

urdf::ModelInterfaceSharedPtr parseUrdfTree(const std::string& xml)
{
  checkJointTree(xml);
  return urdf::parseURDF(xml);
}

}  // namespace spira
