#include "spira/kinematics/urdf_parse.h"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <map>
#include <mutex>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {
namespace {

constexpr const char* kTreeHint =
    "a URDF robot is a tree: give every link but the root exactly one parent joint";

const char* linkOf(const TiXmlElement& joint, const char* role)
{
  const TiXmlElement* e = joint.FirstChildElement(role);
  return e ? e->Attribute("link") : nullptr;
}

void checkJointTree(const std::string& xml, const std::string& what)
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
      throw InputError(what + ": link '" + std::string(child) + "' is the child of two joints ('" +
                           it->second.joint + "' and '" + jointName + "')",
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
        throw InputError(
            what + ": the joints form a loop through link '" + link + "' (joint '" + up.at(link).joint + "')",
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

// Keeps urdfdom's messages (console_bridge, printed to the terminal by default) for the caller's
// message instead: the first error says what is wrong with the file.
class CapturedMessages final : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override
  {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && firstError.empty()) firstError = text;
  }
  std::string firstError;
};

std::mutex& handlerMutex()
{
  static std::mutex m;
  return m;
}

}  // namespace

urdf::ModelInterfaceSharedPtr parseUrdfModel(const std::string& xml, const std::string& what)
{
  // TinyXML steps over a UTF-8 lead byte's whole sequence: one at the very end of the text takes it
  // up to 3 bytes past the terminating NUL (AddressSanitizer, found by the URDF fuzz target). The
  // padding keeps those reads inside the buffer; the parsers stop at its first NUL.
  std::string padded = xml;
  padded.append(4, '\0');
  checkJointTree(padded, what);
  const std::lock_guard<std::mutex> lock(handlerMutex());
  CapturedMessages messages;
  console_bridge::useOutputHandler(&messages);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(padded);
  } catch (...) {
    console_bridge::restorePreviousOutputHandler();
    throw;
  }
  console_bridge::restorePreviousOutputHandler();
  if (!model || !model->getRoot())
    throw InputError(
        what + " is not valid URDF" +
            (messages.firstError.empty() ? std::string() : ": " + clippedText(messages.firstError)),
        "check the file with check_urdf; it must be plain URDF, not xacro");
  return model;
}

}  // namespace spira
