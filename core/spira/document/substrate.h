#pragma once

#include <memory>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/base/transform.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// What the part is built on: a plane (the usual plate) or a mesh (a pipe, a previous part).
// Coordinates are in the world frame.
struct Substrate {
  enum class Kind { Plane, Mesh };

  Kind kind = Kind::Plane;
  double planeZ = 0.0;                       // Plane: height of the plane along its normal, mm
  Vec3 planeNormal = Vec3::UnitZ();          // Plane: unit normal pointing into the build side
  std::shared_ptr<const TriangleMesh> mesh;  // Mesh: the substrate surface, mm
  std::string meshName;                      // Mesh: shown name
  std::string sourcePath;                    // Mesh: file it was imported from (may be empty)

  static Substrate plane(double z = 0.0, const Vec3& normal = Vec3::UnitZ());
  static Substrate fromMesh(std::shared_ptr<const TriangleMesh> mesh, std::string name,
                            std::string sourcePath = {});

  bool operator==(const Substrate& o) const;
  bool operator!=(const Substrate& o) const { return !(*this == o); }
};

const char* substrateKindName(Substrate::Kind k);  // "plane", "mesh"

nlohmann::json substrateToJson(const Substrate& s);
Substrate substrateFromJson(const nlohmann::json& j);  // throws InputError

}  // namespace spira
