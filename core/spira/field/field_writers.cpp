#include "spira/field/field_writers.h"

#include "spira/base/number_text.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {
namespace {

void checkSizes(const TriangleMesh& mesh, const std::vector<double>& values)
{
  if (values.size() != mesh.vertices.size())
    throw InputError("the field has " + std::to_string(values.size()) + " values but the mesh has " +
                         std::to_string(mesh.vertices.size()) + " vertices",
                     "write the field with the mesh it was computed on");
}

std::string xmlEscaped(const std::string& s)
{
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

bool littleEndian()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// One data array: its XML element and, for the appended encoding, its block of raw bytes.
class VtpArrays {
 public:
  explicit VtpArrays(VtpEncoding encoding) : encoding_(encoding) {}

  template <typename T>
  void add(std::string& xml, const char* type, const std::string& name, int components,
           const std::vector<T>& data, const char* indent)
  {
    xml += indent;
    xml += "<DataArray type=\"";
    xml += type;
    xml += "\" Name=\"" + xmlEscaped(name) + "\" NumberOfComponents=\"" + std::to_string(components) + "\"";
    if (encoding_ == VtpEncoding::AppendedRaw) {
      xml += " format=\"appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
      const std::uint64_t bytes = data.size() * sizeof(T);
      appended_.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
      appended_.append(reinterpret_cast<const char*>(data.data()), bytes);
      return;
    }
    xml += " format=\"ascii\">\n";
    for (size_t i = 0; i < data.size(); ++i) {
      xml += (i % size_t(3 * components) == 0) ? (i ? "\n" : "") : " ";
      appendNumber(xml, data[i]);
    }
    xml += "\n";
    xml += indent;
    xml += "</DataArray>\n";
  }
  const std::string& appended() const { return appended_; }

 private:
  VtpEncoding encoding_;
  std::string appended_;
};

}  // namespace

std::string fieldToCsv(const TriangleMesh& mesh, const std::vector<double>& values)
{
  checkSizes(mesh, values);
  std::string out = "vertex,x,y,z,value\n";
  out.reserve(out.size() + values.size() * 64);
  for (size_t v = 0; v < values.size(); ++v) {
    appendNumber(out, static_cast<long long>(v));
    for (int k = 0; k < 3; ++k) {
      out += ',';
      appendNumber(out, mesh.vertices[v][k]);
    }
    out += ',';
    appendNumber(out, values[v]);
    out += '\n';
  }
  return out;
}

void writeFieldCsv(const std::filesystem::path& path, const TriangleMesh& mesh,
                   const std::vector<double>& values)
{
  writeFileAtomically(path, fieldToCsv(mesh, values));
}

std::string fieldToVtp(const TriangleMesh& mesh, const std::vector<double>& values,
                       const std::string& fieldName, VtpEncoding encoding)
{
  checkSizes(mesh, values);
  const std::string name = fieldName.empty() ? std::string("field") : fieldName;  // VTK needs a name
  if (encoding == VtpEncoding::Ascii)
    for (double x : values)
      if (!std::isfinite(x))
        throw InputError("the field '" + name + "' has non-finite values, which VTK cannot read as text",
                         "write it with the binary (appended raw) encoding");
  std::vector<double> points(3 * mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k) points[3 * v + k] = mesh.vertices[v][k];
  std::vector<long long> connectivity(3 * mesh.faces.size()), offsets(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) connectivity[3 * f + k] = mesh.faces[f][k];
    offsets[f] = static_cast<long long>(3 * (f + 1));
  }

  VtpArrays arrays(encoding);
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"";
  xml += littleEndian() ? "LittleEndian" : "BigEndian";
  xml += "\" header_type=\"UInt64\">\n  <PolyData>\n    <Piece NumberOfPoints=\"" +
         std::to_string(mesh.vertices.size()) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(mesh.faces.size()) + "\">\n";
  xml += "      <PointData Scalars=\"" + xmlEscaped(name) + "\">\n";
  arrays.add(xml, "Float64", name, 1, values, "        ");
  xml += "      </PointData>\n      <Points>\n";
  arrays.add(xml, "Float64", "Points", 3, points, "        ");
  xml += "      </Points>\n      <Polys>\n";
  arrays.add(xml, "Int64", "connectivity", 1, connectivity, "        ");
  arrays.add(xml, "Int64", "offsets", 1, offsets, "        ");
  xml += "      </Polys>\n    </Piece>\n  </PolyData>\n";
  if (encoding == VtpEncoding::AppendedRaw) {
    xml += "  <AppendedData encoding=\"raw\">\n   _";
    xml += arrays.appended();
    xml += "\n  </AppendedData>\n";
  }
  xml += "</VTKFile>\n";
  return xml;
}

void writeFieldVtp(const std::filesystem::path& path, const TriangleMesh& mesh,
                   const std::vector<double>& values, const std::string& fieldName, VtpEncoding encoding)
{
  writeFileAtomically(path, fieldToVtp(mesh, values, fieldName, encoding));
}

}  // namespace spira
