#include "spira/field/field_writers.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "field/field_test_meshes.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "support/test_support.h"

namespace spira {
namespace {

TriangleMesh smallMesh()
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1.5, 0, 0), Vec3(0, 2.25, 0.1), Vec3(1.0 / 3.0, 1e-7, -4e5)};
  m.faces = {{0, 1, 2}, {1, 3, 2}};
  return m;
}

const std::vector<double> kValues = {0.0, 0.1, 1.0 / 3.0, 12345.678};

std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, sep)) out.push_back(item);
  return out;
}

TEST(FieldWriters, CsvRoundTripsEveryNumber)
{
  const TriangleMesh m = smallMesh();
  test::TempDir dir;
  writeFieldCsv(dir / "f.csv", m, kValues);
  const std::vector<std::string> lines = split(readFile(dir / "f.csv"), '\n');
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "vertex,x,y,z,value");
  for (size_t v = 0; v < 4; ++v) {
    const std::vector<std::string> cells = split(lines[v + 1], ',');
    ASSERT_EQ(cells.size(), 5u);
    EXPECT_EQ(std::stoul(cells[0]), v);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(std::stod(cells[1 + k]), m.vertices[v][k]);
    EXPECT_EQ(std::stod(cells[4]), kValues[v]);
  }
  EXPECT_THROW(writeFieldCsv(dir / "g.csv", m, {1.0}), InputError);
}

// Text between the first `open` after `from` and the next `close`.
std::string between(const std::string& s, const std::string& open, const std::string& close, size_t from = 0)
{
  const size_t a = s.find(open, from);
  if (a == std::string::npos) return {};
  const size_t b = s.find(close, a + open.size());
  return s.substr(a + open.size(), b - a - open.size());
}

std::vector<double> numbers(const std::string& text)
{
  std::vector<double> out;
  std::stringstream in(text);
  double x;
  while (in >> x) out.push_back(x);
  return out;
}

TEST(FieldWriters, AsciiVtpHoldsPointsPolysAndNamedScalars)
{
  const TriangleMesh m = smallMesh();
  test::TempDir dir;
  writeFieldVtp(dir / "f.vtp", m, kValues, "geodesic_distance", VtpEncoding::Ascii);
  const std::string xml = readFile(dir / "f.vtp");
  EXPECT_NE(xml.find("<VTKFile type=\"PolyData\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfPoints=\"4\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfPolys=\"2\""), std::string::npos);
  EXPECT_NE(xml.find("<PointData Scalars=\"geodesic_distance\">"), std::string::npos);

  const std::string field =
      between(xml, "Name=\"geodesic_distance\" NumberOfComponents=\"1\" format=\"ascii\">", "</");
  EXPECT_EQ(numbers(field), kValues);
  const std::vector<double> pts =
      numbers(between(xml, "Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">", "</"));
  ASSERT_EQ(pts.size(), 12u);
  for (size_t v = 0; v < 4; ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(pts[3 * v + k], m.vertices[v][k]);
  EXPECT_EQ(numbers(between(xml, "Name=\"connectivity\" NumberOfComponents=\"1\" format=\"ascii\">", "</")),
            (std::vector<double>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(numbers(between(xml, "Name=\"offsets\" NumberOfComponents=\"1\" format=\"ascii\">", "</")),
            (std::vector<double>{3, 6}));
}

TEST(FieldWriters, AsciiVtpRefusesNonFiniteValues)
{
  const TriangleMesh m = smallMesh();
  std::vector<double> values = kValues;
  values[2] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(fieldToVtp(m, values, "d", VtpEncoding::Ascii), InputError);
  EXPECT_NO_THROW(fieldToVtp(m, values, "d", VtpEncoding::AppendedRaw));
}

// Reads one appended block: a UInt64 byte count, then the bytes.
template <typename T>
std::vector<T> appendedBlock(const std::string& xml, const std::string& name)
{
  const size_t at = xml.find("Name=\"" + name + "\"");
  const size_t offset = std::stoul(between(xml, "offset=\"", "\"", at));
  const size_t data = xml.find("<AppendedData encoding=\"raw\">");
  const size_t start = xml.find('_', data) + 1 + offset;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, xml.data() + start, sizeof bytes);
  std::vector<T> out(bytes / sizeof(T));
  std::memcpy(out.data(), xml.data() + start + sizeof bytes, bytes);
  return out;
}

TEST(FieldWriters, AppendedRawVtpKeepsExactBitsAndNonFiniteValues)
{
  const TriangleMesh m = smallMesh();
  std::vector<double> values = kValues;
  values[3] = std::numeric_limits<double>::infinity();
  const std::string xml = fieldToVtp(m, values, "a<b&\"c\"", VtpEncoding::AppendedRaw);
  EXPECT_NE(xml.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(xml.find("Scalars=\"a&lt;b&amp;&quot;c&quot;\""), std::string::npos);
  EXPECT_EQ(appendedBlock<double>(xml, "a&lt;b&amp;&quot;c&quot;"), values);
  const std::vector<double> pts = appendedBlock<double>(xml, "Points");
  ASSERT_EQ(pts.size(), 12u);
  EXPECT_EQ(pts[9], m.vertices[3].x());
  EXPECT_EQ(pts[11], m.vertices[3].z());
  EXPECT_EQ(appendedBlock<std::int64_t>(xml, "connectivity"), (std::vector<std::int64_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(appendedBlock<std::int64_t>(xml, "offsets"), (std::vector<std::int64_t>{3, 6}));
  EXPECT_EQ(xml.substr(xml.size() - 11), "</VTKFile>\n");
}

TEST(FieldWriters, WritesLargeMeshFile)
{
  const test::RingMesh dome = test::domeMesh(10.0, 0.5);
  std::vector<double> values(dome.mesh.vertices.size());
  for (size_t v = 0; v < values.size(); ++v) values[v] = dome.mesh.vertices[v].z();
  test::TempDir dir;
  writeFieldVtp(dir / "dome.vtp", dome.mesh, values, "z");
  const std::string xml = readFile(dir / "dome.vtp");
  EXPECT_EQ(appendedBlock<double>(xml, "z"), values);
  EXPECT_EQ(appendedBlock<std::int64_t>(xml, "offsets").back(), std::int64_t(3 * dome.mesh.faces.size()));
}

}  // namespace
}  // namespace spira
