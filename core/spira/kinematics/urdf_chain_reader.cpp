// KinematicChain::fromUrdf*: the URDF side of the chain, kept apart from the numerics.
#include <algorithm>
#include <sstream>

#include <urdf_parser/urdf_parser.h>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/kinematics/kinematic_chain.h"
#include "spira/kinematics/urdf_parse.h"

namespace spira {

namespace {

constexpr double kMmPerMetre = 1000.0;

Transform toTransform(const urdf::Pose& pose)
{
  Transform t = Transform::Identity();
  t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  t.translation() = Vec3(pose.position.x, pose.position.y, pose.position.z) * kMmPerMetre;
  return t;
}

std::string jointTypeName(int type)
{
  switch (type) {
    case urdf::Joint::PRISMATIC:
      return "prismatic";
    case urdf::Joint::FLOATING:
      return "floating";
    case urdf::Joint::PLANAR:
      return "planar";
    default:
      return "unknown";
  }
}

// Joints from `link` up to the root, nearest first.
std::vector<urdf::JointConstSharedPtr> jointsToRoot(const urdf::ModelInterface& model,
                                                    const std::string& link)
{
  std::vector<urdf::JointConstSharedPtr> out;
  urdf::LinkConstSharedPtr l = model.getLink(link);
  while (l && l->parent_joint) {
    out.push_back(l->parent_joint);
    l = model.getLink(l->parent_joint->parent_link_name);
  }
  return out;
}

std::string listLinks(const urdf::ModelInterface& model)
{
  std::string names;
  for (const auto& [name, link] : model.links_) names += (names.empty() ? "" : ", ") + name;
  return names;
}

KinematicChain chainFromModel(const urdf::ModelInterface& model, const std::string& baseLink,
                              const std::string& tipLink)
{
  for (const std::string& name : {baseLink, tipLink})
    if (!model.getLink(name))
      throw InputError("the robot description '" + model.getName() + "' has no link named '" + name + "'",
                       "choose one of its links: " + listLinks(model));

  const auto fromTip = jointsToRoot(model, tipLink);
  const auto fromBase = jointsToRoot(model, baseLink);
  // Drop the common part above the common ancestor.
  size_t common = 0;
  while (common < fromTip.size() && common < fromBase.size() &&
         fromTip[fromTip.size() - 1 - common] == fromBase[fromBase.size() - 1 - common])
    ++common;
  const size_t tipCount = fromTip.size() - common;
  const size_t baseCount = fromBase.size() - common;

  // T_ancestor_base from the fixed joints between the ancestor and the base link.
  Transform ancestorBase = Transform::Identity();
  for (size_t i = baseCount; i-- > 0;) {
    const auto& j = fromBase[i];
    if (j->type != urdf::Joint::FIXED)
      throw InputError(
          "joint '" + j->name + "' lies between the chain base '" + baseLink +
              "' and the tip's ancestors and is not fixed",
          "choose a base link that is an ancestor of '" + tipLink + "' or joined to one by fixed joints");
    ancestorBase = ancestorBase * toTransform(j->parent_to_joint_origin_transform);
  }

  std::vector<ChainJoint> joints;
  Transform pending = ancestorBase.inverse();  // fixed transforms not yet folded into a joint
  for (size_t i = tipCount; i-- > 0;) {
    const auto& j = fromTip[i];
    const Transform origin = toTransform(j->parent_to_joint_origin_transform);
    if (j->type == urdf::Joint::FIXED) {
      pending = pending * origin;
      continue;
    }
    if (j->type != urdf::Joint::REVOLUTE && j->type != urdf::Joint::CONTINUOUS)
      throw InputError("joint '" + j->name + "' in the chain " + baseLink + " -> " + tipLink + " is " +
                           jointTypeName(j->type) + "; only revolute joints are supported",
                       "use a robot description whose arm joints are revolute");
    if (j->mimic)
      throw InputError("joint '" + j->name + "' mimics joint '" + j->mimic->joint_name +
                           "'; coupled joints are not supported in a serial chain",
                       "describe the arm with independent revolute joints");
    ChainJoint cj;
    cj.name = j->name;
    cj.origin = pending * origin;
    cj.axis = Vec3(j->axis.x, j->axis.y, j->axis.z);
    if (j->limits) {
      if (j->type == urdf::Joint::REVOLUTE) {
        cj.lower = j->limits->lower;
        cj.upper = j->limits->upper;
      }
      if (j->limits->velocity > 0.0) cj.maxVelocity = j->limits->velocity;
    }
    joints.push_back(std::move(cj));
    pending = Transform::Identity();
  }
  return KinematicChain(baseLink, tipLink, std::move(joints), pending);
}

}  // namespace

KinematicChain KinematicChain::fromUrdfString(const std::string& xml, const std::string& baseLink,
                                              const std::string& tipLink)
{
  return chainFromModel(*parseUrdfModel(xml, "the robot description"), baseLink, tipLink);
}

KinematicChain KinematicChain::fromUrdfFile(const std::string& path, const std::string& baseLink,
                                            const std::string& tipLink)
{
  const std::string text = readFile(path);
  try {
    return fromUrdfString(text, baseLink, tipLink);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what(), e.hint());
  }
}

}  // namespace spira
