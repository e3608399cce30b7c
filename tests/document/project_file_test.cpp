#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "document/document_test_data.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/version.h"
#include "spira/document/document.h"
#include "spira/document/project_file.h"
#include "spira/io/json_codec.h"
#include "spira/path/dwell.h"
#include "support/test_support.h"

namespace spira {
namespace {

std::string frame(std::uint32_t version, const std::string& payload, std::uint32_t crc)
{
  return test::projectFrame(version, payload, crc);
}

std::string framedJson(const nlohmann::json& j)
{
  return test::projectBytesOf(j);
}

nlohmann::json payloadOf(const std::string& file)
{
  return test::projectJsonOf(file);
}

std::string messageOf(std::string_view bytes)
{
  try {
    decodeProject(bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ProjectFile, Crc32MatchesTheStandardCheckValue)
{
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0u);
}

TEST(ProjectFile, FullStateRoundTripsBitForBit)
{
  const DocumentState s = test::fullState();
  const std::string bytes = encodeProject(s);
  const DocumentState back = decodeProject(bytes);
  EXPECT_EQ(back, s);
  EXPECT_EQ(*back.part, *s.part);
  EXPECT_EQ(*back.cell, *s.cell);
  EXPECT_EQ(*back.settings, *s.settings);
  EXPECT_EQ(*back.substrate, *s.substrate);
  EXPECT_EQ(back.results, s.results);
  // == calls -0.0 and 0.0 equal: check the bits of the awkward values too.
  EXPECT_TRUE(test::bitwiseEqual(back.part->mesh->vertices, s.part->mesh->vertices));
  EXPECT_TRUE(std::signbit(back.part->mesh->vertices[0].y()));
  EXPECT_EQ(back.part->mesh->vertices[1].y(), 1e-300);
  EXPECT_EQ(back.part->mesh->vertices[2].z(), std::numeric_limits<double>::denorm_min());
  EXPECT_TRUE(std::signbit(back.results.field->values[1]));
  EXPECT_TRUE(std::signbit(back.results.process->extra.at("dwell")[0]));
  EXPECT_TRUE(test::bitwiseEqual(back.results.generatrices->lines[3], s.results.generatrices->lines[3]));
  EXPECT_TRUE(test::bitwiseEqual(back.results.generatrices->normals[2], s.results.generatrices->normals[2]));
  // Every ParamValue keeps its type (2.0 stays a double, not the integer 2) and sign.
  const ParamSet process = back.settings->section("process");
  EXPECT_EQ(process.values().at("wire_feed").index(), 2u);
  EXPECT_EQ(process.values().at("layers"), ParamValue(std::int64_t{-3}));
  EXPECT_EQ(process.values().at("big"), ParamValue(std::int64_t{1} << 62));
  EXPECT_TRUE(std::signbit(process.getDouble("offset")));
  EXPECT_TRUE(sameBits(process.getDouble("layer_height"), 0.1));
  EXPECT_EQ(process.values().at("empty"), ParamValue(std::string()));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      EXPECT_TRUE(sameBits(back.part->T_world_part.matrix()(r, c), s.part->T_world_part.matrix()(r, c)));
  // Writing again gives the same bytes.
  EXPECT_EQ(encodeProject(back), bytes);
}

TEST(ProjectFile, EmptyAndPlaneStatesRoundTrip)
{
  const DocumentState empty;
  const DocumentState back = decodeProject(encodeProject(empty));
  EXPECT_EQ(back, empty);
  EXPECT_EQ(back.part, nullptr);
  EXPECT_EQ(back.cell, nullptr);
  EXPECT_EQ(back.results.presentStages(), 0u);
  DocumentState plane;
  plane.substrate = std::make_shared<const Substrate>(Substrate::plane(-12.5, Vec3(0, 0.6, 0.8)));
  EXPECT_EQ(decodeProject(encodeProject(plane)), plane);
}

TEST(ProjectFile, HeaderFollowsTheDocumentedLayout)
{
  const std::string bytes = encodeProject(test::fullState());
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(0, 8), "SPIRAPRJ");
  const std::string payload = bytes.substr(20, bytes.size() - 24);
  EXPECT_EQ(frame(1, payload, crc32(payload)), bytes);
  const nlohmann::json j = payloadOf(bytes);
  EXPECT_EQ(j.at("spira_version"), kVersion);
  for (const char* section : {"part", "substrate", "cell", "plan"}) EXPECT_EQ(j.at(section).at("schema"), 1);
  EXPECT_EQ(j.at("results").at("schema"), 2);  // 2: typed kinematics result
  EXPECT_TRUE(j.at("part").at("mesh").at("vertices").is_binary());
  EXPECT_EQ(j.at("part").at("mesh").at("vertices").get_binary().size(), 8u * 3 * 8);
  EXPECT_EQ(j.at("part").at("mesh").at("faces").get_binary().size(), 8u * 3 * 4);
}

TEST(ProjectFile, EverySingleByteFlipIsRejected)
{
  DocumentState s;
  s.cell = std::make_shared<const CellRecord>(test::sampleCell());
  const std::string good = encodeProject(s);
  for (size_t i = 0; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] = static_cast<char>(bad[i] ^ 0x5A);
    EXPECT_THROW(decodeProject(bad), InputError) << "byte " << i;
  }
  std::string bad = good;
  bad[good.size() / 2] ^= 1;
  EXPECT_NE(messageOf(bad).find("truncated or damaged"), std::string::npos) << messageOf(bad);
}

TEST(ProjectFile, EveryTruncationIsRejectedCleanly)
{
  DocumentState s;
  s.part = std::make_shared<const Part>(test::samplePart());
  s.results.setSpiral(std::make_shared<const Trajectory>(test::sampleTrajectory(2)));
  const std::string good = encodeProject(s);
  EXPECT_NE(messageOf(""), "no error");
  EXPECT_NE(messageOf("").find("not a Spira project"), std::string::npos);
  for (size_t n = 1; n < good.size(); ++n) {
    const std::string msg = messageOf(std::string_view(good).substr(0, n));
    EXPECT_NE(msg.find("truncated or damaged"), std::string::npos) << n << ": " << msg;
  }
  EXPECT_NE(messageOf(good + '\0').find("truncated or damaged"), std::string::npos);
}

TEST(ProjectFile, GarbageAndWrongMagicAreNotProjects)
{
  std::mt19937 rng(7);
  std::string garbage(4096, '\0');
  for (char& c : garbage) c = static_cast<char>(rng());
  EXPECT_NE(messageOf(garbage).find("not a Spira project"), std::string::npos);
  std::string wrong = encodeProject(DocumentState());
  wrong[7] = 'X';
  EXPECT_NE(messageOf(wrong).find("not a Spira project"), std::string::npos);
  EXPECT_NE(messageOf("solid cube\nendsolid\n").find("not a Spira project"), std::string::npos);
}

TEST(ProjectFile, NewerFormatVersionAsksForAnUpdate)
{
  std::string bytes = encodeProject(DocumentState());
  bytes[8] = 2;
  try {
    decodeProject(bytes);
    FAIL() << "accepted a newer format";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("version 2"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("update Spira"), std::string::npos);
  }
}

TEST(ProjectFile, NewerSectionSchemaAsksForAnUpdate)
{
  nlohmann::json j = payloadOf(encodeProject(test::fullState()));
  j["cell"]["schema"] = 7;
  try {
    decodeProject(framedJson(j));
    FAIL() << "accepted a newer schema";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("schema 7"), std::string::npos) << e.what();
    EXPECT_NE(e.hint().find("update Spira"), std::string::npos);
  }
}

TEST(ProjectFile, ValidFrameWithBadContentIsAnInputError)
{
  const std::string garbagePayload = "\xff\xff\x00 not cbor";
  EXPECT_THROW(decodeProject(frame(1, garbagePayload, crc32(garbagePayload))), InputError);
  EXPECT_THROW(decodeProject(framedJson(nlohmann::json::object())), InputError);
  EXPECT_THROW(decodeProject(framedJson(nlohmann::json::array({1, 2}))), InputError);
  const nlohmann::json good = payloadOf(encodeProject(test::fullState()));
  // Remove or break each top-level member and a few nested ones.
  for (const char* key : {"spira_version", "part", "substrate", "cell", "plan", "results"}) {
    nlohmann::json j = good;
    j.erase(key);
    EXPECT_THROW(decodeProject(framedJson(j)), InputError) << key;
    j[key] = 42;
    EXPECT_THROW(decodeProject(framedJson(j)), InputError) << key;
  }
  auto broken = [&](const std::function<void(nlohmann::json&)>& f) {
    nlohmann::json j = good;
    f(j);
    return framedJson(j);
  };
  EXPECT_THROW(decodeProject(broken([](auto& j) {
                 j["part"]["mesh"]["faces"] = nlohmann::json::binary({1, 2, 3});
               })),
               InputError);
  EXPECT_THROW(decodeProject(broken([](auto& j) {
                 j["part"]["mesh"]["faces"] = nlohmann::json::binary(std::vector<std::uint8_t>(12, 0x7F));
               })),
               InputError);  // face index far beyond the vertex count
  EXPECT_THROW(decodeProject(broken([](auto& j) { j["results"]["spiral"]["count"] = 21; })), InputError);
  EXPECT_THROW(decodeProject(broken([](auto& j) { j["part"]["T_world_part"][12] = 1.0; })), InputError);
  EXPECT_THROW(decodeProject(broken([](auto& j) { j["cell"]["controller"] = "staubli_cs9"; })), InputError);
  EXPECT_THROW(decodeProject(broken([](auto& j) { j["part"]["source_unit"] = "furlong"; })), InputError);
  EXPECT_THROW(decodeProject(broken([](auto& j) { j["plan"]["params"]["process"]["x"] = nullptr; })),
               InputError);
}

TEST(ProjectFile, DocumentSaveAsAndOpenRoundTrip)
{
  test::TempDir dir;
  Document doc(test::fullState());
  doc.setParam("process", "travel_speed", 7.0);
  EXPECT_THROW(doc.save(), InputError);  // no file yet
  const auto path = dir / "work.spira";
  doc.saveAs(path);
  EXPECT_FALSE(doc.isModified());
  EXPECT_EQ(doc.filePath(), path);
  const DocumentState saved = doc.snapshot();

  Document other;
  other.setCell(CellRecord());
  other.open(path);
  EXPECT_EQ(other.state(), saved);
  EXPECT_EQ(other.filePath(), path);
  EXPECT_FALSE(other.isModified());
  EXPECT_FALSE(other.canUndo());
  EXPECT_EQ(loadProject(path), saved);
}

// The thermal re-planning's dwells (path/dwell.h) ride in the process trajectory's extra channels.
TEST(ProjectFile, ADwellSurvivesSaveAndOpen)
{
  test::TempDir dir;
  DocumentState state = test::fullState();
  Trajectory process = *state.results.process;
  process.extra.clear();
  std::vector<double> dwell(process.size(), 0.0);
  dwell[4] = 17.25;
  process.extra[kDwellChannel] = dwell;
  state.results.process = std::make_shared<const Trajectory>(process);
  Document doc(state);
  const auto path = dir / "dwell.spira";
  doc.saveAs(path);

  Document other;
  other.open(path);
  const Trajectory& back = *other.state().results.process;
  EXPECT_TRUE(hasDwell(back));
  EXPECT_EQ(back.extra.at(kDwellChannel), dwell);
  EXPECT_EQ(dwellAt(back, 4), 17.25);
  EXPECT_EQ(dwellAt(back, 5), 0.0);
}

TEST(ProjectFile, FailedOpenLeavesTheDocumentUntouched)
{
  test::TempDir dir;
  const std::string good = encodeProject(test::fullState());
  test::writeBytes(dir / "corrupt.spira", good.substr(0, good.size() / 2));
  test::writeBytes(dir / "empty.spira", "");

  Document doc;
  doc.setPart(test::samplePart());
  doc.saveAs(dir / "mine.spira");
  doc.setCell(test::sampleCell());
  const DocumentState before = doc.snapshot();
  int notifications = 0;
  doc.subscribe([&](const ChangeSet&) { ++notifications; });
  for (const char* name : {"corrupt.spira", "empty.spira", "missing.spira"}) {
    SCOPED_TRACE(name);
    EXPECT_THROW(doc.open(dir / name), Error);
    EXPECT_EQ(doc.state(), before);
    EXPECT_EQ(doc.state().part, before.part);  // the very same objects
    EXPECT_EQ(doc.filePath(), dir / "mine.spira");
    EXPECT_TRUE(doc.isModified());
    EXPECT_EQ(doc.undoStack().count(), 2u);
  }
  EXPECT_THROW(doc.open(dir / "missing.spira"), IoError);
  EXPECT_EQ(notifications, 0);
}

TEST(ProjectFile, FailedSaveKeepsPreviousFileAndState)
{
  test::TempDir dir;
  Document doc;
  doc.setPart(test::samplePart());
  const auto path = dir / "p.spira";
  doc.saveAs(path);
  const std::string previous = readFile(path);
  doc.setCell(test::sampleCell());

  // Unwritable folder. Root ignores permissions, so the attempt runs in a child that drops to
  // an unprivileged user when needed; it reports through its exit code.
  std::filesystem::permissions(dir.path(),
                               std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
                                   std::filesystem::perms::group_read | std::filesystem::perms::group_exec |
                                   std::filesystem::perms::others_read | std::filesystem::perms::others_exec);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0)) _exit(3);
    try {
      doc.saveAs(path);
    } catch (const IoError&) {
      _exit(doc.isModified() && doc.filePath() == path ? 0 : 4);
    } catch (...) {
      _exit(5);
    }
    _exit(6);  // the save succeeded: the folder was writable after all
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_all);
  EXPECT_EQ(readFile(path), previous);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);  // no temporary left

  // A folder that does not exist and a target that is a folder: the same guarantees, in-process.
  EXPECT_THROW(doc.saveAs(dir / "no" / "such.spira"), IoError);
  EXPECT_EQ(doc.filePath(), path);
  EXPECT_TRUE(doc.isModified());
  std::filesystem::create_directory(dir / "folder.spira");
  test::writeBytes(dir / "folder.spira" / "keep", "x");
  EXPECT_THROW(doc.saveAs(dir / "folder.spira"), IoError);
  EXPECT_EQ(readFile(dir / "folder.spira" / "keep"), "x");
  EXPECT_EQ(doc.filePath(), path);
  EXPECT_EQ(readFile(path), previous);
}

TEST(ProjectFile, CellRecordJsonRoundTripsThroughText)
{
  const CellRecord c = test::sampleCell();
  const std::string text = cellRecordToJson(c).dump(2);
  EXPECT_EQ(cellRecordFromJson(nlohmann::json::parse(text)), c);
  nlohmann::json j = cellRecordToJson(c);
  j["robot_axes"][0].erase("max_deg");
  EXPECT_THROW(cellRecordFromJson(j), InputError);
  j = cellRecordToJson(c);
  j["mounting"] = "ceiling";
  EXPECT_THROW(cellRecordFromJson(j), InputError);
}

TEST(ProjectFile, PlanSettingsJsonKeepsTypes)
{
  const PlanSettings s = test::sampleSettings();
  const PlanSettings back = planSettingsFromJson(nlohmann::json::parse(planSettingsToJson(s).dump()));
  EXPECT_EQ(back, s);
  EXPECT_EQ(back.params.at("process").values().at("wire_feed"), ParamValue(2.0));
  EXPECT_EQ(PlanSettings().decomposerId, "decomposer.isovalue");
  EXPECT_EQ(PlanSettings().closureFinderId, "closure.max_min_geodesic");
}

// The cell's URDFs are stored relative to the project too: a job folder moved or copied whole finds
// its own robot files, a project copied alone still finds them where they were.
TEST(ProjectFile, CellFilesAreFoundRelativeToTheProjectThenWhereTheyWere)
{
  namespace fs = std::filesystem;
  test::TempDir dir;
  fs::create_directories(dir / "job" / "robots");
  fs::create_directories(dir / "shared");
  test::writeBytes(dir / "job" / "robots" / "arm.urdf", "<robot/>");
  test::writeBytes(dir / "shared" / "turntable.urdf", "<robot/>");
  CellRecord cell;
  cell.name = "job cell";
  cell.robotUrdf = (dir / "job" / "robots" / "arm.urdf").string();
  cell.positionerUrdf = (dir / "shared" / "turntable.urdf").string();
  Document doc;
  doc.setCell(cell);
  doc.saveAs(dir / "job" / "job.spira");
  EXPECT_EQ(
      payloadOf(test::readBytes(dir / "job" / "job.spira"))["relative_paths"],
      nlohmann::json({{"robot_urdf", "robots/arm.urdf"}, {"positioner_urdf", "../shared/turntable.urdf"}}));

  fs::rename(dir / "job", dir / "moved");
  const DocumentState moved = loadProject(dir / "moved" / "job.spira");
  ASSERT_TRUE(moved.cell);
  EXPECT_EQ(moved.cell->robotUrdf, (dir / "moved" / "robots" / "arm.urdf").string());
  EXPECT_EQ(moved.cell->positionerUrdf, (dir / "shared" / "turntable.urdf").string());

  fs::create_directories(dir / "elsewhere" / "deeper");
  fs::copy_file(dir / "moved" / "job.spira", dir / "elsewhere" / "deeper" / "job.spira");
  const DocumentState alone = loadProject(dir / "elsewhere" / "deeper" / "job.spira");
  ASSERT_TRUE(alone.cell);
  EXPECT_EQ(alone.cell->robotUrdf, (dir / "job" / "robots" / "arm.urdf").string())
      << "the absolute path, as saved";
  EXPECT_EQ(alone.cell->positionerUrdf, (dir / "shared" / "turntable.urdf").string());

  // Bytes alone (no folder) keep the absolute paths.
  EXPECT_EQ(decodeProject(test::readBytes(dir / "moved" / "job.spira")).cell->robotUrdf,
            (dir / "job" / "robots" / "arm.urdf").string());
}

// A compared scan is kept as its file and alignment, not its points; like the cell's files, the file
// is found beside the project when both moved together.
TEST(ProjectFile, AScanIsKeptAsItsFileAndAlignment)
{
  namespace fs = std::filesystem;
  test::TempDir dir;
  fs::create_directories(dir / "job" / "scans");
  test::writeBytes(dir / "job" / "scans" / "wall.ply", "ply");
  ScanRecord scan;
  scan.file = (dir / "job" / "scans" / "wall.ply").string();
  scan.T_part_scan = Transform(Eigen::AngleAxisd(0.3, Vec3(0, 0.6, 0.8)));
  scan.T_part_scan.translation() = Vec3(1.25, -3.5, 0.125);
  scan.rmsMm = 0.031;
  scan.depositedTo = 8100;
  Document doc;
  doc.setScan(scan);
  EXPECT_EQ(doc.undoStack().undoText(), "Compare scan");
  doc.saveAs(dir / "job" / "job.spira");
  EXPECT_EQ(payloadOf(test::readBytes(dir / "job" / "job.spira"))["scan"]["relative_file"], "scans/wall.ply");

  fs::rename(dir / "job", dir / "moved");
  const DocumentState moved = loadProject(dir / "moved" / "job.spira");
  ASSERT_TRUE(moved.scan);
  EXPECT_EQ(moved.scan->file, (dir / "moved" / "scans" / "wall.ply").string());
  EXPECT_TRUE(codec::sameTransform(moved.scan->T_part_scan, scan.T_part_scan));
  EXPECT_EQ(moved.scan->rmsMm, 0.031);
  EXPECT_EQ(moved.scan->depositedTo, 8100u);

  // A project without one (older ones too) has none.
  Document empty;
  empty.saveAs(dir / "empty.spira");
  EXPECT_FALSE(loadProject(dir / "empty.spira").scan);
  EXPECT_FALSE(payloadOf(test::readBytes(dir / "empty.spira")).contains("scan"));
}

}  // namespace
}  // namespace spira
