#pragma once

#include <memory>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/base/transform.h"
#include "spira/base/units.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The part the user builds: an imported, welded mesh and where it sits in the cell.
// A value: edits replace the whole Part (the mesh is shared, never copied).
struct Part {
  // `lowerBoundaryOverride` value meaning "the loop with the lowest z" (validateMesh order).
  static constexpr int kAutomaticLowerBoundary = -1;

  std::string name;
  std::string sourcePath;                          // file it was imported from, as the user chose it
  LengthUnit sourceUnit = LengthUnit::Millimetre;  // unit of the source file; the mesh is in mm
  std::shared_ptr<const TriangleMesh> mesh;        // welded, in mm, in the part frame
  // Part frame -> world frame (p_world = T_world_part * p_part). The planned path lives in the
  // part frame, so moving the part only changes kinematics and later stages.
  Transform T_world_part = Transform::Identity();
  // Index into MeshReport::boundaryLoops of the loop on the substrate, or kAutomaticLowerBoundary.
  int lowerBoundaryOverride = kAutomaticLowerBoundary;

  // Deep equality (meshes compared by value when the pointers differ).
  bool operator==(const Part& o) const;
  bool operator!=(const Part& o) const { return !(*this == o); }
};

// Project-file codec. The mesh is stored as binary blobs (little-endian doubles and int32), so
// the round trip is bit-for-bit. fromJson throws InputError on missing or malformed fields.
nlohmann::json partToJson(const Part& part);
Part partFromJson(const nlohmann::json& j);

}  // namespace spira
