#include "spira/document/substrate.h"

#include "spira/base/error.h"
#include "spira/document/document_state.h"
#include "spira/io/json_codec.h"

namespace spira {

namespace {
constexpr int kSubstrateSchema = 1;
}

Substrate Substrate::plane(double z, const Vec3& normal)
{
  Substrate s;
  s.kind = Kind::Plane;
  s.planeZ = z;
  s.planeNormal = normal;
  return s;
}

Substrate Substrate::fromMesh(std::shared_ptr<const TriangleMesh> mesh, std::string name,
                              std::string sourcePath)
{
  Substrate s;
  s.kind = Kind::Mesh;
  s.mesh = std::move(mesh);
  s.meshName = std::move(name);
  s.sourcePath = std::move(sourcePath);
  return s;
}

bool Substrate::operator==(const Substrate& o) const
{
  return kind == o.kind && planeZ == o.planeZ && planeNormal == o.planeNormal && meshName == o.meshName &&
         sourcePath == o.sourcePath && sameValue(mesh, o.mesh);
}

const char* substrateKindName(Substrate::Kind k)
{
  return k == Substrate::Kind::Plane ? "plane" : "mesh";
}

nlohmann::json substrateToJson(const Substrate& s)
{
  nlohmann::json j;
  j["schema"] = kSubstrateSchema;
  j["kind"] = substrateKindName(s.kind);
  j["plane_z"] = s.planeZ;
  j["plane_normal"] = codec::vec3ToJson(s.planeNormal);
  j["mesh_name"] = s.meshName;
  j["source_path"] = s.sourcePath;
  j["mesh"] = s.mesh ? codec::meshToJson(*s.mesh) : nlohmann::json(nullptr);
  return j;
}

Substrate substrateFromJson(const nlohmann::json& j)
{
  const std::string what = "project substrate";
  codec::checkSchema(j, kSubstrateSchema, what);
  Substrate s;
  const std::string kind = codec::stringField(j, "kind", what);
  if (kind == "plane")
    s.kind = Substrate::Kind::Plane;
  else if (kind == "mesh")
    s.kind = Substrate::Kind::Mesh;
  else
    throw InputError(what + ": unknown kind '" + kind + "'", "the project file is damaged");
  s.planeZ = codec::numberField(j, "plane_z", what);
  s.planeNormal = codec::vec3FromJson(codec::field(j, "plane_normal", what), what + " normal");
  s.meshName = codec::stringField(j, "mesh_name", what);
  s.sourcePath = codec::stringField(j, "source_path", what);
  const auto& m = codec::field(j, "mesh", what);
  if (!m.is_null()) s.mesh = std::make_shared<const TriangleMesh>(codec::meshFromJson(m, what + " mesh"));
  if (s.kind == Substrate::Kind::Mesh && !s.mesh)
    throw InputError(what + ": mesh substrate without a mesh", "the project file is damaged");
  return s;
}

}  // namespace spira
