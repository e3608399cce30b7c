#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "spira/base/transform.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira::codec {

// Helpers shared by the project-file codecs. Binary blobs are little-endian whatever the host,
// so files move between machines; reading checks sizes and throws InputError naming `what`.

nlohmann::json::binary_t doublesToBlob(const std::vector<double>& v);
std::vector<double> decodeDoubleBlob(const nlohmann::json& j, const std::string& what);
nlohmann::json::binary_t intsToBlob(const std::vector<std::int32_t>& v);
std::vector<std::int32_t> blobToInts(const nlohmann::json& j, const std::string& what);

nlohmann::json::binary_t vec3sToBlob(const std::vector<Vec3>& v);
std::vector<Vec3> blobToVec3s(const nlohmann::json& j, const std::string& what);

// 16 numbers, row-major; the last row must be 0 0 0 1.
nlohmann::json transformToJson(const Transform& T);
Transform transformFromJson(const nlohmann::json& j, const std::string& what);
bool sameTransform(const Transform& a, const Transform& b);

nlohmann::json vec3ToJson(const Vec3& v);
Vec3 vec3FromJson(const nlohmann::json& j, const std::string& what);

nlohmann::json meshToJson(const TriangleMesh& mesh);
// Checks face indices against the vertex count.
TriangleMesh meshFromJson(const nlohmann::json& j, const std::string& what);

// The member `key` of object `j`; throws InputError "<what>: missing '<key>'" when absent.
const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::string& what);
std::string stringField(const nlohmann::json& j, const char* key, const std::string& what);
double numberField(const nlohmann::json& j, const char* key, const std::string& what);
std::int64_t intField(const nlohmann::json& j, const char* key, const std::string& what);
bool boolField(const nlohmann::json& j, const char* key, const std::string& what);
// Throws InputError when `j["schema"]` is newer than `supported` (or missing).
int checkSchema(const nlohmann::json& j, int supported, const std::string& what);

}  // namespace spira::codec
