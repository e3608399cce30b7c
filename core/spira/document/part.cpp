#include "spira/document/part.h"

#include <limits>

#include "spira/base/error.h"
#include "spira/document/document_state.h"
#include "spira/io/json_codec.h"

namespace spira {

namespace {
constexpr int kPartSchema = 1;
}

bool Part::operator==(const Part& o) const
{
  return name == o.name && sourcePath == o.sourcePath && sourceUnit == o.sourceUnit &&
         lowerBoundaryOverride == o.lowerBoundaryOverride &&
         codec::sameTransform(T_world_part, o.T_world_part) && sameValue(mesh, o.mesh);
}

nlohmann::json partToJson(const Part& part)
{
  nlohmann::json j;
  j["schema"] = kPartSchema;
  j["name"] = part.name;
  j["source_path"] = part.sourcePath;
  j["source_unit"] = std::string(lengthUnitSymbol(part.sourceUnit));
  j["T_world_part"] = codec::transformToJson(part.T_world_part);
  j["lower_boundary"] = part.lowerBoundaryOverride;
  j["mesh"] = part.mesh ? codec::meshToJson(*part.mesh) : nlohmann::json(nullptr);
  return j;
}

Part partFromJson(const nlohmann::json& j)
{
  const std::string what = "project part";
  codec::checkSchema(j, kPartSchema, what);
  Part p;
  p.name = codec::stringField(j, "name", what);
  p.sourcePath = codec::stringField(j, "source_path", what);
  const std::string unit = codec::stringField(j, "source_unit", what);
  const auto u = parseLengthUnit(unit);
  if (!u) throw InputError(what + ": unknown length unit '" + unit + "'", "the project file is damaged");
  p.sourceUnit = *u;
  p.T_world_part = codec::transformFromJson(codec::field(j, "T_world_part", what), what + " placement");
  const std::int64_t lower = codec::intField(j, "lower_boundary", what);
  if (lower < Part::kAutomaticLowerBoundary || lower > std::numeric_limits<int>::max())
    throw InputError(what + ": invalid lower boundary index " + std::to_string(lower),
                     "the project file is damaged");
  p.lowerBoundaryOverride = static_cast<int>(lower);
  const auto& m = codec::field(j, "mesh", what);
  if (!m.is_null()) p.mesh = std::make_shared<const TriangleMesh>(codec::meshFromJson(m, what + " mesh"));
  return p;
}

}  // namespace spira
