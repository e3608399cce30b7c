#pragma once

#include <string>

#include <urdf_world/types.h>

namespace spira {

// Parses URDF text with urdfdom, after checking with the XML reader urdfdom itself uses (TinyXML)
// that the joints form a tree. urdfdom builds the links of a loop into a cycle of shared pointers
// before it rejects the file, and that cycle is never freed; the check refuses it first.
// Returns null when urdfdom rejects the text; throws InputError naming the joints for a link that
// is the child of two joints or a chain of joints that comes back to where it started.
urdf::ModelInterfaceSharedPtr parseUrdfTree(const std::string& xml);

}  // namespace spira
