#include "py_arrays.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace spira::python {
namespace {

using Point = TrajectoryPoint;
constexpr double kMmPerSecondToMetresPerMinute = 60.0 / 1000.0;  // trajectory.csv's wire-feed unit

template <class T, class Get>
py::array_t<T> column(const std::vector<Point>& points, Get get)
{
  py::array_t<T> out(static_cast<py::ssize_t>(points.size()));
  auto a = out.template mutable_unchecked<1>();
  for (size_t i = 0; i < points.size(); ++i) a(static_cast<py::ssize_t>(i)) = get(points[i]);
  return out;
}

template <class Get>
py::array_t<double> vectors(const std::vector<Point>& points, Get get)
{
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t(3)});
  auto a = out.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3& v = get(points[i]);
    for (int k = 0; k < 3; ++k) a(static_cast<py::ssize_t>(i), k) = v[k];
  }
  return out;
}

template <class T>
py::array_t<T> array(const std::vector<T>& values)
{
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

const std::vector<Point>& pointsOf(const PlannedPart& p)
{
  return p.path->points;
}

}  // namespace

void bindTrajectoryArrays(py::class_<PlannedPart>& plan)
{
  plan.def("__len__", [](const PlannedPart& p) { return p.path->size(); })
      .def_property_readonly(
          "positions",
          [](const PlannedPart& p) {
            return vectors(pointsOf(p), [](const Point& q) { return q.position; });
          },
          "Torch (TCP) positions, N x 3, mm, part frame.")
      .def_property_readonly(
          "normals",
          [](const PlannedPart& p) { return vectors(pointsOf(p), [](const Point& q) { return q.normal; }); })
      .def_property_readonly(
          "tangents",
          [](const PlannedPart& p) { return vectors(pointsOf(p), [](const Point& q) { return q.tangent; }); })
      .def_property_readonly(
          "builds",
          [](const PlannedPart& p) { return vectors(pointsOf(p), [](const Point& q) { return q.build; }); },
          "Build directions b = n x t, along the torch axis, N x 3.")
      .def_property_readonly("revolution",
                             [](const PlannedPart& p) {
                               return column<int>(pointsOf(p), [](const Point& q) { return q.revolution; });
                             })
      .def_property_readonly("generatrix",
                             [](const PlannedPart& p) {
                               return column<int>(pointsOf(p), [](const Point& q) { return q.generatrix; });
                             })
      .def_property_readonly(
          "path_index",
          [](const PlannedPart& p) {
            return column<int>(pointsOf(p), [](const Point& q) { return q.path; });
          },
          "The sub-path of each point (multi-branch parts), 0 for a single spiral.")
      .def_property_readonly(
          "height",
          [](const PlannedPart& p) {
            return column<double>(pointsOf(p), [](const Point& q) { return q.height; });
          },
          "Deposit height, mm.")
      .def_property_readonly(
          "travel_speed",
          [](const PlannedPart& p) {
            return column<double>(pointsOf(p), [](const Point& q) { return q.travelSpeed; });
          },
          "Travel speed, mm/s.")
      .def_property_readonly(
          "wire_feed",
          [](const PlannedPart& p) {
            return column<double>(pointsOf(p),
                                  [](const Point& q) { return q.wireFeed * kMmPerSecondToMetresPerMinute; });
          },
          "Wire feed speed, m/min (as trajectory.csv writes it).")
      .def_property_readonly("arc",
                             [](const PlannedPart& p) {
                               return column<bool>(pointsOf(p), [](const Point& q) { return q.arcOn; });
                             })
      .def_property_readonly(
          "channels",
          [](const PlannedPart& p) {
            py::dict out;
            for (const auto& [name, values] : p.path->extra) out[py::str(name)] = array(values);
            return out;
          },
          "The extra per-point channels (dwell_s, ...) by name.");
}

void bindMotionArrays(py::class_<PlannedPart>& plan)
{
  plan.def_property_readonly(
          "joints",
          [](const PlannedPart& p) -> py::object {
            if (!p.plan->results.kinematics) return py::none();
            const auto& points = p.plan->results.kinematics->joints.points;
            py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t(6)});
            auto a = out.mutable_unchecked<2>();
            for (size_t i = 0; i < points.size(); ++i)
              for (int k = 0; k < 6; ++k)
                a(static_cast<py::ssize_t>(i), k) = points[i].robotDeg[static_cast<size_t>(k)];
            return std::move(out);
          },
          "Robot joints, N x 6, degrees in the controller's convention (joints.csv's q1..q6); None without a "
          "cell.")
      .def_property_readonly(
          "external_joints",
          [](const PlannedPart& p) -> py::object {
            if (!p.plan->results.kinematics || !p.plan->results.kinematics->joints.hasPositioner)
              return py::none();
            const auto& points = p.plan->results.kinematics->joints.points;
            py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t(2)});
            auto a = out.mutable_unchecked<2>();
            for (size_t i = 0; i < points.size(); ++i)
              for (int k = 0; k < 2; ++k)
                a(static_cast<py::ssize_t>(i), k) = points[i].externalDeg[static_cast<size_t>(k)];
            return std::move(out);
          },
          "Positioner axes E1, E2, N x 2, degrees; None without a positioner.")
      .def_property_readonly("reachable",
                             [](const PlannedPart& p) -> py::object {
                               if (!p.plan->results.kinematics) return py::none();
                               std::vector<bool> r;
                               for (const auto& q : p.plan->results.kinematics->joints.points)
                                 r.push_back(q.reachable);
                               return py::array(py::cast(r));
                             })
      .def_property_readonly(
          "thermal",
          [](const PlannedPart& p) -> py::object {
            const auto& t = p.plan->results.thermal;
            if (!t) return py::none();
            py::dict out;
            out["peak_c"] = array(t->peak);
            out["interpass_c"] = array(t->interpass);
            out["time_above_melt_s"] = array(t->timeAboveMelt);
            out["pool_length_mm"] = array(t->poolLength);
            out["bond"] = array(t->bond);
            out["risk"] = array(t->risk);
            return std::move(out);
          },
          "The thermal stage's per-point arrays (settings={'thermal': {'enabled': True}}); None when it did "
          "not run.");
}

}  // namespace spira::python
