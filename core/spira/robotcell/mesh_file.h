#pragma once

#include <filesystem>

#include "spira/base/transform.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Reads one robot link mesh file named by a URDF <mesh> into mm, multiplied by the URDF `scale`.
// STL goes through Spira's own fast reader (metres, as ROS packages write them); every other format
// (COLLADA .dae, OBJ, PLY, ...) through Assimp in the spira-import helper (isolated_import.h), with
// the node transforms flattened in. COLLADA is read the way ROS rviz reads it: the file's <unit> is
// honoured, its <up_axis> is ignored (the URDF already places the link). Throws IoError when the
// file is missing or does not parse as a mesh, InputError when the reader crashes or exceeds the
// import limits, so the caller can substitute a stand-in and warn.
TriangleMesh readLinkMesh(const std::filesystem::path& file, const Vec3& scale);

}  // namespace spira
