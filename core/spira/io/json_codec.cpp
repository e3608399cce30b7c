#include "spira/io/json_codec.h"

#include <cstring>

#include "spira/base/error.h"
#include "spira/io/json_read.h"

namespace spira::codec {

namespace {

// meshToJson/meshFromJson list every member of TriangleMesh; this fails to compile when one is
// added, as a reminder to store it too.
static_assert(sizeof(void*) != 8 || sizeof(TriangleMesh) == 48, "update meshToJson/meshFromJson");

const char* kDamagedHint = "the project file is damaged; open a backup or re-import the part";

[[noreturn]] void malformed(const std::string& what, const std::string& problem)
{
  throw InputError(what + ": " + problem, kDamagedHint);
}

const nlohmann::json::binary_t& blob(const nlohmann::json& j, const std::string& what, size_t elementSize)
{
  if (!j.is_binary()) malformed(what, "expected a binary array");
  const auto& b = j.get_binary();
  if (b.size() % elementSize != 0)
    malformed(what, "binary array size is not a multiple of " + std::to_string(elementSize));
  return b;
}

void putU64(std::vector<std::uint8_t>& out, std::uint64_t v)
{
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint64_t getU64(const std::uint8_t* p)
{
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= std::uint64_t{p[i]} << (8 * i);
  return v;
}

void putDouble(std::vector<std::uint8_t>& out, double d)
{
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  putU64(out, bits);
}

double getDouble(const std::uint8_t* p)
{
  const std::uint64_t bits = getU64(p);
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

}  // namespace

nlohmann::json::binary_t doublesToBlob(const std::vector<double>& v)
{
  std::vector<std::uint8_t> out;
  out.reserve(v.size() * 8);
  for (double d : v) putDouble(out, d);
  return nlohmann::json::binary_t(std::move(out));
}

std::vector<double> decodeDoubleBlob(const nlohmann::json& j, const std::string& what)
{
  const auto& b = blob(j, what, 8);
  std::vector<double> v(b.size() / 8);
  for (size_t i = 0; i < v.size(); ++i) v[i] = getDouble(b.data() + 8 * i);
  return v;
}

nlohmann::json::binary_t intsToBlob(const std::vector<std::int32_t>& v)
{
  std::vector<std::uint8_t> out;
  out.reserve(v.size() * 4);
  for (std::int32_t x : v) {
    const auto u = static_cast<std::uint32_t>(x);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
  }
  return nlohmann::json::binary_t(std::move(out));
}

std::vector<std::int32_t> blobToInts(const nlohmann::json& j, const std::string& what)
{
  const auto& b = blob(j, what, 4);
  std::vector<std::int32_t> v(b.size() / 4);
  for (size_t i = 0; i < v.size(); ++i) {
    std::uint32_t u = 0;
    for (int k = 0; k < 4; ++k) u |= std::uint32_t{b[4 * i + k]} << (8 * k);
    v[i] = static_cast<std::int32_t>(u);
  }
  return v;
}

nlohmann::json::binary_t vec3sToBlob(const std::vector<Vec3>& v)
{
  std::vector<std::uint8_t> out;
  out.reserve(v.size() * 24);
  for (const Vec3& p : v)
    for (int k = 0; k < 3; ++k) putDouble(out, p[k]);
  return nlohmann::json::binary_t(std::move(out));
}

std::vector<Vec3> blobToVec3s(const nlohmann::json& j, const std::string& what)
{
  const auto& b = blob(j, what, 24);
  std::vector<Vec3> v(b.size() / 24);
  for (size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) v[i][k] = getDouble(b.data() + 24 * i + 8 * k);
  return v;
}

nlohmann::json transformToJson(const Transform& T)
{
  nlohmann::json a = nlohmann::json::array();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a.push_back(T.matrix()(r, c));
  return a;
}

Transform transformFromJson(const nlohmann::json& j, const std::string& what)
{
  if (!j.is_array() || j.size() != 16) malformed(what, "expected 16 numbers (a row-major 4x4 matrix)");
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      const auto& x = j[static_cast<size_t>(4 * r + c)];
      if (!x.is_number()) malformed(what, "matrix entry is not a number");
      m(r, c) = x.get<double>();
    }
  if (!(m.row(3) == Eigen::RowVector4d(0, 0, 0, 1))) malformed(what, "last matrix row is not 0 0 0 1");
  Transform T;
  T.matrix() = m;
  return T;
}

bool sameTransform(const Transform& a, const Transform& b)
{
  return a.matrix() == b.matrix();
}

nlohmann::json vec3ToJson(const Vec3& v)
{
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

Vec3 vec3FromJson(const nlohmann::json& j, const std::string& what)
{
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    malformed(what, "expected 3 numbers");
  return Vec3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

nlohmann::json meshToJson(const TriangleMesh& mesh)
{
  std::vector<std::int32_t> idx;
  idx.reserve(mesh.faces.size() * 3);
  for (const Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) idx.push_back(static_cast<std::int32_t>(f[k]));
  return {{"vertices", vec3sToBlob(mesh.vertices)}, {"faces", intsToBlob(idx)}};
}

TriangleMesh meshFromJson(const nlohmann::json& j, const std::string& what)
{
  TriangleMesh mesh;
  mesh.vertices = blobToVec3s(field(j, "vertices", what), what + " vertices");
  const auto idx = blobToInts(field(j, "faces", what), what + " faces");
  if (idx.size() % 3 != 0) malformed(what, "face index count is not a multiple of 3");
  const auto nv = static_cast<std::int64_t>(mesh.vertices.size());
  mesh.faces.resize(idx.size() / 3);
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t i = idx[3 * f + k];
      if (i < 0 || i >= nv) malformed(what, "face " + std::to_string(f) + " refers to a missing vertex");
      mesh.faces[f][k] = i;
    }
  return mesh;
}

const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::string& what)
{
  return json_read::member(j, key, what, kDamagedHint);
}

std::string stringField(const nlohmann::json& j, const char* key, const std::string& what)
{
  return json_read::text(j, key, what, kDamagedHint);
}

double numberField(const nlohmann::json& j, const char* key, const std::string& what)
{
  return json_read::number(j, key, what, kDamagedHint);
}

std::int64_t intField(const nlohmann::json& j, const char* key, const std::string& what)
{
  return json_read::wholeNumber(j, key, what, kDamagedHint);
}

bool boolField(const nlohmann::json& j, const char* key, const std::string& what)
{
  return json_read::flag(j, key, what, kDamagedHint);
}

int checkSchema(const nlohmann::json& j, int supported, const std::string& what)
{
  const std::int64_t schema = intField(j, "schema", what);
  if (schema < 1) malformed(what, "invalid schema number " + std::to_string(schema));
  if (schema > supported)
    throw InputError(what + " uses schema " + std::to_string(schema) + ", this Spira reads up to schema " +
                         std::to_string(supported),
                     "update Spira to open this project");
  return static_cast<int>(schema);
}

}  // namespace spira::codec
