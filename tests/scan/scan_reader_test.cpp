// Scan files as scanners and point-cloud tools write them: text columns with or without a header and
// normals, PCD ascii and binary, PLY points; and the line or byte of what is wrong in a bad one.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "builtin_plugins.h"
#include "spira/base/error.h"
#include "spira/scan/scan_reader.h"
#include "spira/scan/scan_writer.h"
#include "support/test_support.h"

namespace spira {
namespace {

std::string errorOf(const std::function<void()>& f)
{
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ScanText, ColumnsWithAndWithoutNamesAndNormals)
{
  const PointCloud plain = parseXyzText("# a profiler's export\n1 2 3\n4,5,6\n7;8;9 # last\n\n", "a.xyz");
  ASSERT_EQ(plain.size(), 3u);
  EXPECT_EQ(plain.points[1], Vec3(4, 5, 6));
  EXPECT_FALSE(plain.hasNormals());

  // Named columns in any order; intensity and the rest skipped.
  const PointCloud named = parseXyzText("intensity,Z,X,Y,NX,NY,NZ\n7,3,1,2,0,0,2\n8,6,4,5,0,3,0\n", "b.csv");
  ASSERT_EQ(named.size(), 2u);
  EXPECT_EQ(named.points[0], Vec3(1, 2, 3));
  ASSERT_TRUE(named.hasNormals());
  EXPECT_EQ(named.normals[0], Vec3(0, 0, 1));  // normalised
  EXPECT_EQ(named.normals[1], Vec3(0, 1, 0));

  // Six unnamed columns are x y z nx ny nz when the last three are unit vectors, else not normals.
  EXPECT_TRUE(parseXyzText("0 0 0 1 0 0\n1 0 0 0 1 0\n", "c.xyz").hasNormals());
  EXPECT_FALSE(parseXyzText("0 0 0 10 20 30\n1 0 0 0 1 0\n", "d.xyz").hasNormals());
  // CloudCompare's commented header.
  const PointCloud cc = parseXyzText("//X,Y,Z,R,G,B\n1,2,3,255,0,0\n", "e.txt");
  EXPECT_EQ(cc.points[0], Vec3(1, 2, 3));
}

TEST(ScanText, BadLinesAreNamed)
{
  EXPECT_NE(errorOf([] {
              parseXyzText("1 2 3\n4 five 6\n", "s.xyz");
            }).find("'s.xyz' line 2: 'five' is not a number"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              parseXyzText("1 2 3\n4 5\n", "s.xyz");
            }).find("line 2: 2 values where the file's lines hold 3"),
            std::string::npos);
  EXPECT_NE(errorOf([] { parseXyzText("1 2\n", "s.xyz"); }).find("line 1: 2 value(s), a point needs x y z"),
            std::string::npos);
  EXPECT_NE(errorOf([] { parseXyzText("# nothing\n", "s.xyz"); }).find("holds no point"), std::string::npos);
  EXPECT_NE(errorOf([] { parseXyzText("1 2 inf\n", "s.xyz"); }).find("line 1"), std::string::npos);
}

TEST(ScanPcd, AsciiAndBinaryWithNormalsAndMissingReturns)
{
  const std::string ascii =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z normal_x normal_y normal_z curvature\nSIZE 4 4 4 4 4 4 4\n"
      "TYPE F F F F F F F\nCOUNT 1 1 1 1 1 1 1\nWIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA "
      "ascii\n"
      "1 2 3 0 0 1 0\nnan nan nan 0 0 1 0\n4 5 6 1 0 0 0.5\n";
  const PointCloud a = parsePcd(ascii, "a.pcd");
  ASSERT_EQ(a.size(), 2u);  // the NaN return is no point
  EXPECT_EQ(a.points[1], Vec3(4, 5, 6));
  EXPECT_EQ(a.normals[1], Vec3(1, 0, 0));

  std::string binary =
      "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 8 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 2\nHEIGHT 1\n"
      "POINTS 2\nDATA binary\n";
  for (int i = 0; i < 2; ++i) {
    const float x = 1.5f + i, y = -2.0f;
    const double z = 10.25 * (i + 1);
    const std::uint32_t rgb = 0xff0000;
    binary.append(reinterpret_cast<const char*>(&x), 4).append(reinterpret_cast<const char*>(&y), 4);
    binary.append(reinterpret_cast<const char*>(&z), 8).append(reinterpret_cast<const char*>(&rgb), 4);
  }
  const PointCloud b = parsePcd(binary, "b.pcd");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b.points[1], Vec3(2.5, -2.0, 20.5));
  EXPECT_FALSE(b.hasNormals());

  EXPECT_NE(errorOf([&] {
              parsePcd(binary.substr(0, binary.size() - 3), "c.pcd");
            }).find("more than its bytes hold"),
            std::string::npos);
  std::string compressed = binary;
  compressed.replace(compressed.find("DATA binary"), 11, "DATA binary_compressed");
  EXPECT_NE(errorOf([&] { parsePcd(compressed, "d.pcd"); }).find("compressed PCD"), std::string::npos);
  EXPECT_NE(errorOf([] {
              parsePcd("VERSION 0.7\nFIELDS a b\nSIZE 4 4\nTYPE F F\nPOINTS 0\nDATA ascii\n", "e.pcd");
            }).find("has no field 'x'"),
            std::string::npos);
}

TEST(ScanPly, WhatSpiraWritesReadsBack)
{
  test::TempDir dir;
  PointCloud cloud;
  for (int i = 0; i < 50; ++i) {
    cloud.points.push_back(Vec3(0.5 * i, -i, 100.0 + 0.25 * i));
    cloud.normals.push_back(Vec3(0, i % 2, 1 - i % 2));
  }
  const std::vector<double> deviation(50, 0.125);
  {
    std::ofstream out(dir / "s.ply", std::ios::binary);
    out << pointCloudPly(cloud, &deviation);
  }
  NullProgress progress;
  const PointCloud back = readScan(builtinRegistry(), dir / "s.ply", progress);
  ASSERT_EQ(back.size(), 50u);
  ASSERT_TRUE(back.hasNormals());
  for (size_t i = 0; i < 50; ++i) {
    EXPECT_EQ(back.points[i], cloud.points[i]);  // exact in float
    EXPECT_EQ(back.normals[i], cloud.normals[i]);
  }
  // A mesh PLY reads as its vertices.
  {
    std::ofstream out(dir / "m.ply");
    out << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 "
           "2\n";
  }
  EXPECT_EQ(readScan(builtinRegistry(), dir / "m.ply", progress).size(), 3u);
  {
    std::ofstream out(dir / "empty.ply");
    out << "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
           "end_header\n";
  }
  EXPECT_NE(errorOf([&] { readScan(builtinRegistry(), dir / "empty.ply", progress); }).find("holds no point"),
            std::string::npos);
}

}  // namespace
}  // namespace spira
