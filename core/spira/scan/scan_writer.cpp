#include "spira/scan/scan_writer.h"

#include <cstring>

#include "spira/base/error.h"

namespace spira {
namespace {

void putFloat(std::string& out, double v)
{
  const float f = static_cast<float>(v);
  char bytes[4];
  std::memcpy(bytes, &f, 4);
  if constexpr (__BYTE_ORDER__ == __ORDER_BIG_ENDIAN__)
    std::swap(bytes[0], bytes[3]), std::swap(bytes[1], bytes[2]);
  out.append(bytes, 4);
}

}  // namespace

std::string pointCloudPly(const PointCloud& cloud, const std::vector<double>* scalar,
                          const std::string& scalarName)
{
  if (scalar && scalar->size() != cloud.size())
    throw InternalError("a per-point value for " + std::to_string(scalar->size()) + " of " +
                        std::to_string(cloud.size()) + " points");
  const bool normals = cloud.hasNormals();
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by Spira\nelement vertex " +
                    std::to_string(cloud.size()) + "\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) out += "property float nx\nproperty float ny\nproperty float nz\n";
  if (scalar) out += "property float " + scalarName + "\n";
  out += "end_header\n";
  out.reserve(out.size() + cloud.size() * 4 * (3 + (normals ? 3 : 0) + (scalar ? 1 : 0)));
  for (size_t i = 0; i < cloud.size(); ++i) {
    for (int k = 0; k < 3; ++k) putFloat(out, cloud.points[i][k]);
    if (normals)
      for (int k = 0; k < 3; ++k) putFloat(out, cloud.normals[i][k]);
    if (scalar) putFloat(out, (*scalar)[i]);
  }
  return out;
}

}  // namespace spira
