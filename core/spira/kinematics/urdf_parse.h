#pragma once

#include <string>

#include <urdf_world/types.h>

namespace spira {

// Parses URDF text with urdfdom, after checking with the XML reader urdfdom itself uses (TinyXML)
// that the joints form a tree. urdfdom builds the links of a loop into a cycle of shared pointers
// before it rejects the file, and that cycle is never freed; the check refuses it first. The text
// is padded so that TinyXML's reads past a final UTF-8 lead byte stay inside it. urdfdom's own
// messages are not printed: its first error ends the InputError, which names the file (`what`).
// Also refused: a link that is the child of two joints, a chain of joints that comes back to
// where it started, a model without a root link.
urdf::ModelInterfaceSharedPtr parseUrdfModel(const std::string& xml, const std::string& what);

}  // namespace spira
