// The import helper's result stream: what a Writer sends, a Reader rebuilds exactly, and a
// stream no Writer produced is refused before anything is believed.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>

#include "spira/base/error.h"
#include "spira/io/import_wire.h"

namespace spira::wire {
namespace {

// Everything a Writer wrote to a pipe, as bytes.
template <class F>
std::string written(F&& write)
{
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  Writer w(fds[1]);
  write(w);
  ::close(fds[1]);
  std::string bytes;
  char buf[4096];
  ssize_t n;
  while ((n = ::read(fds[0], buf, sizeof buf)) > 0) bytes.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  return bytes;
}

ImportedMesh sampleMesh()
{
  ImportedMesh m;
  m.mesh.vertices = {Vec3(0, 0, 0), Vec3(1.5, 0, 0), Vec3(0, 2.25, -1e-300), Vec3(3, 4, 5)};
  m.mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  m.unit = LengthUnit::Millimetre;
  m.fileUnit = LengthUnit::Inch;
  m.warnings = {"first", "second"};
  return m;
}

TEST(ImportWire, MeshWarningsAndProgressArriveIntactEvenByteByByte)
{
  const std::string bytes = written([](Writer& w) {
    w.header();
    w.progress(0.25, "Reading STEP");
    w.mesh(sampleMesh());
  });
  std::vector<std::pair<double, std::string>> reports;
  CallbackProgress progress([&](double f, std::string_view s) { reports.emplace_back(f, std::string(s)); });
  Reader r;
  for (char c : bytes) r.feed(&c, 1, progress);
  ASSERT_TRUE(r.complete());
  ASSERT_TRUE(r.mesh());
  const ImportedMesh expected = sampleMesh();
  EXPECT_EQ(r.mesh()->mesh.vertices, expected.mesh.vertices);
  EXPECT_EQ(r.mesh()->mesh.faces, expected.mesh.faces);
  EXPECT_EQ(r.mesh()->unit, LengthUnit::Millimetre);
  EXPECT_EQ(r.mesh()->fileUnit, LengthUnit::Inch);
  EXPECT_EQ(r.mesh()->warnings, expected.warnings);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].first, 0.25);
  EXPECT_EQ(reports[0].second, "Reading STEP");
}

TEST(ImportWire, ErrorsKeepTheirKindMessageAndHint)
{
  const std::string bytes = written([](Writer& w) {
    w.header();
    w.error(ErrorKind::Input, "cannot read 'a.step'", "re-export it");
  });
  NullProgress progress;
  Reader r;
  r.feed(bytes.data(), bytes.size(), progress);
  ASSERT_TRUE(r.complete());
  ASSERT_TRUE(r.error());
  EXPECT_EQ(r.error()->kind, ErrorKind::Input);
  EXPECT_EQ(r.error()->what, "cannot read 'a.step'");
  EXPECT_EQ(r.error()->hint, "re-export it");
}

TEST(ImportWire, TruncatedStreamIsNotComplete)
{
  const std::string bytes = written([](Writer& w) {
    w.header();
    w.mesh(sampleMesh());
  });
  NullProgress progress;
  Reader r;
  r.feed(bytes.data(), bytes.size() - 1, progress);
  EXPECT_FALSE(r.complete());
  EXPECT_FALSE(r.mesh());
}

TEST(ImportWire, ForeignOrInconsistentStreamsAreRefused)
{
  NullProgress progress;
  const std::string header = written([](Writer& w) { w.header(); });
  {
    Reader r;
    const std::string garbage = "*** ERR StepReaderData : Unresolved Reference";
    EXPECT_THROW(r.feed(garbage.data(), garbage.size(), progress), InternalError);
  }
  {
    // A mesh frame claiming a million vertices in a few bytes.
    std::string mesh = written([](Writer& w) { w.mesh(sampleMesh()); });
    mesh = mesh.substr(mesh.find('M'));  // skip the warning frames
    const uint64_t lie = 1000000;
    std::memcpy(mesh.data() + 9 + 2, &lie, sizeof lie);
    const std::string bytes = header + mesh;
    Reader r;
    EXPECT_THROW(r.feed(bytes.data(), bytes.size(), progress), InternalError);
  }
  {
    const std::string bytes = header + written([](Writer& w) { w.progress(0.5, "x"); });
    std::string bad = bytes;
    const double outside = 7.0;
    std::memcpy(bad.data() + header.size() + 9, &outside, sizeof outside);
    Reader r;
    EXPECT_THROW(r.feed(bad.data(), bad.size(), progress), InternalError);
  }
}

}  // namespace
}  // namespace spira::wire
