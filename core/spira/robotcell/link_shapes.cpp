#include "spira/robotcell/link_shapes.h"

#include <urdf_parser/urdf_parser.h>

#include "spira/kinematics/urdf_parse.h"

#include <cmath>
#include <filesystem>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/urdf_parse.h"
#include "spira/robotcell/mesh_file.h"

namespace spira {
namespace {

constexpr double kMetre = 1000.0;  // URDF lengths are metres

void addQuad(TriangleMesh& m, int a, int b, int c, int d)
{
  m.faces.push_back({a, b, c});
  m.faces.push_back({a, c, d});
}

TriangleMesh boxMesh(const Vec3& size)
{
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(),
                            (i & 4 ? 0.5 : -0.5) * size.z());
  addQuad(m, 0, 2, 3, 1);
  addQuad(m, 4, 5, 7, 6);
  addQuad(m, 0, 1, 5, 4);
  addQuad(m, 2, 6, 7, 3);
  addQuad(m, 0, 4, 6, 2);
  addQuad(m, 1, 3, 7, 5);
  return m;
}

TriangleMesh cylinderMesh(double radius, double length, int segments = 24)
{
  TriangleMesh m;
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * kPi * i / segments;
    m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), -0.5 * length);
    m.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.5 * length);
  }
  const int bottom = static_cast<int>(m.vertices.size());
  m.vertices.emplace_back(0, 0, -0.5 * length);
  m.vertices.emplace_back(0, 0, 0.5 * length);
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    addQuad(m, 2 * i, 2 * j, 2 * j + 1, 2 * i + 1);
    m.faces.push_back({bottom, 2 * j, 2 * i});
    m.faces.push_back({bottom + 1, 2 * i + 1, 2 * j + 1});
  }
  return m;
}

void append(TriangleMesh& to, const TriangleMesh& from, const Transform& T)
{
  const int offset = static_cast<int>(to.vertices.size());
  for (const Vec3& v : from.vertices) to.vertices.push_back(T * v);
  for (const auto& f : from.faces) to.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
}

Transform poseOf(const urdf::Pose& p)
{
  double roll = 0, pitch = 0, yaw = 0;
  p.rotation.getRPY(roll, pitch, yaw);
  return transformFromXyzRpy(Vec3(p.position.x, p.position.y, p.position.z) * kMetre, Vec3(roll, pitch, yaw));
}

// The geometry of one <collision> or <visual> element in its link's frame, or nothing (with a
// warning naming `role` and the file).
bool geometryMesh(const urdf::Geometry& g, const std::filesystem::path& dir, const char* role,
                  const char* fallback, TriangleMesh& out, std::vector<std::string>& warnings)
{
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(g);
      out = boxMesh(Vec3(b.dim.x, b.dim.y, b.dim.z) * kMetre);
      return true;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      out = cylinderMesh(c.radius * kMetre, c.length * kMetre);
      return true;
    }
    case urdf::Geometry::SPHERE: {
      const auto& s = static_cast<const urdf::Sphere&>(g);
      out = boxMesh(Vec3::Constant(2.0 * s.radius * kMetre));
      return true;
    }
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(g);
      const std::filesystem::path file = dir / m.filename;
      try {
        out = readLinkMesh(file, Vec3(m.scale.x, m.scale.y, m.scale.z));
        return true;
      } catch (const Error& e) {
        warnings.push_back(std::string(role) + " geometry: " + e.what() + "; " + fallback);
        return false;
      }
    }
  }
  return false;
}

// The link's <visual> geometry with origins applied, or false (with a warning) when any piece of it
// cannot be read: a half-drawn link would mislead more than its collision shape does.
bool visualMesh(const urdf::Link& link, const std::filesystem::path& dir, TriangleMesh& out,
                std::vector<std::string>& warnings)
{
  for (const auto& v : link.visual_array) {
    if (!v || !v->geometry) continue;
    TriangleMesh piece;
    if (!geometryMesh(*v->geometry, dir, "visual", "its collision shape is shown instead", piece, warnings))
      return false;
    append(out, piece, poseOf(v->origin));
  }
  return !out.faces.empty();
}

}  // namespace

RobotShapes readRobotShapes(const std::string& urdfPath, const std::string& baseLink,
                            const std::string& tipLink)
{
  const urdf::ModelInterfaceSharedPtr model =
      parseUrdfModel(readFile(urdfPath), "the robot description " + urdfPath);
  const std::filesystem::path dir = std::filesystem::path(urdfPath).parent_path();
  const KinematicChain arm = KinematicChain::fromUrdfFile(urdfPath, baseLink, tipLink);
  RobotShapes shapes;
  std::vector<urdf::LinkSharedPtr> links;
  model->getLinks(links);
  for (const auto& link : links) {
    // Links off the chain (and off the fixed links around it) do not move with it: skip them.
    std::unique_ptr<KinematicChain> chain;
    try {
      chain = std::make_unique<KinematicChain>(KinematicChain::fromUrdfFile(urdfPath, baseLink, link->name));
    } catch (const InputError&) {
      continue;
    }
    bool onArm = chain->size() <= arm.size();
    for (size_t k = 0; onArm && k < chain->size(); ++k) onArm = chain->joint(k).name == arm.joint(k).name;
    if (!onArm || link->collision_array.empty()) continue;
    LinkShape s;
    s.link = link->name;
    s.joints = chain->size();
    for (const auto& c : link->collision_array) {
      if (!c || !c->geometry) continue;
      TriangleMesh piece;
      if (!geometryMesh(*c->geometry, dir, "collision", "a 100 mm cube stands in for it", piece,
                        shapes.warnings)) {
        piece = boxMesh(Vec3::Constant(100.0));
        s.standInCube = true;
      }
      append(s.mesh, piece, poseOf(c->origin));
    }
    if (s.mesh.faces.empty()) continue;
    s.displayIsVisual = visualMesh(*link, dir, s.display, shapes.warnings);
    if (!s.displayIsVisual) s.display = s.mesh;
    s.chain = std::move(chain);
    s.bvh = std::make_unique<TriangleBvh>(s.mesh);
    shapes.links.push_back(std::move(s));
  }
  return shapes;
}

}  // namespace spira
