#include "spira/thermal/thermal_vtk.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

#include "spira/base/base64.h"
#include "spira/base/number_text.h"

namespace spira {
namespace {

// A DataArray's inline "binary" content: base64 of a UInt32 byte count followed by the values, in
// one stream (VTK XML, uncompressed, header_type UInt32, little endian like the machines we run on).
template <class T>
std::string dataArray(const char* type, const char* name, int components, const std::vector<T>& values)
{
  std::string raw(sizeof(std::uint32_t) + values.size() * sizeof(T), '\0');
  const auto bytes = std::uint32_t(values.size() * sizeof(T));
  std::memcpy(raw.data(), &bytes, sizeof bytes);
  if (!values.empty()) std::memcpy(raw.data() + sizeof bytes, values.data(), values.size() * sizeof(T));
  std::string out = std::string("        <DataArray type=\"") + type + "\" Name=\"" + name +
                    "\" NumberOfComponents=\"" + std::to_string(components) +
                    "\" format=\"binary\">\n          ";
  out += base64Encode(raw);
  out += "\n        </DataArray>\n";
  return out;
}

// The shell's points and triangles, the same in every frame.
std::string geometry(const ThermalMesh& mesh)
{
  std::vector<float> points;
  for (const Vec3& p : mesh.nodes)
    for (int a = 0; a < 3; ++a) points.push_back(float(p[a]));
  std::vector<std::int32_t> connectivity, offsets;
  for (const auto& t : mesh.triangles) {
    connectivity.insert(connectivity.end(), {t[0], t[1], t[2]});
    offsets.push_back(std::int32_t(connectivity.size()));
  }
  const std::vector<std::uint8_t> types(mesh.elementCount(), 5);  // VTK_TRIANGLE
  return "      <Points>\n" + dataArray("Float32", "points", 3, points) + "      </Points>\n      <Cells>\n" +
         dataArray("Int32", "connectivity", 1, connectivity) + dataArray("Int32", "offsets", 1, offsets) +
         dataArray("UInt8", "types", 1, types) + "      </Cells>\n";
}

std::string frameFile(const ThermalMesh& mesh, const std::string& shape, const std::vector<float>& values,
                      double time)
{
  std::vector<std::uint8_t> deposited(mesh.elementCount());
  for (size_t e = 0; e < deposited.size(); ++e) deposited[e] = mesh.elementBirth[e] <= time + 1e-9 ? 1 : 0;
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n  <UnstructuredGrid>\n    <Piece "
         "NumberOfPoints=\"" +
         std::to_string(mesh.nodeCount()) + "\" NumberOfCells=\"" + std::to_string(mesh.elementCount()) +
         "\">\n      <PointData Scalars=\"temperature_C\">\n" +
         dataArray("Float32", "temperature_C", 1, values) + "      </PointData>\n      <CellData>\n" +
         dataArray("UInt8", "deposited", 1, deposited) + "      </CellData>\n" + shape +
         "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

std::vector<OutputFile> thermalTimeSeries(const ThermalStudy& study, const std::string& stem)
{
  std::vector<OutputFile> files;
  const std::string shape = geometry(study.mesh);
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (size_t f = 0; f < study.frames.times.size(); ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "%s_%04zu.vtu", stem.c_str(), f);
    files.push_back({name, frameFile(study.mesh, shape, study.frames.values[f], study.frames.times[f])});
    pvd += "    <DataSet timestep=\"";
    appendNumber(pvd, study.frames.times[f]);
    pvd += "\" part=\"0\" file=\"" + std::string(name) + "\"/>\n";
  }
  pvd += "  </Collection>\n</VTKFile>\n";
  files.insert(files.begin(), OutputFile{stem + ".pvd", pvd});
  return files;
}

}  // namespace spira
