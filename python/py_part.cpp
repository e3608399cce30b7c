#include "py_part.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "py_json.h"
#include "py_progress.h"
#include "spira/io/import_service.h"
#include "spira/plugin/plugin_registry.h"

namespace py = pybind11;

namespace spira::python {
namespace {

// --lower-loop's range and wording, with the argument's name.
int lowerLoopOf(long long loop)
{
  constexpr long long kMaxLoop = 999999;
  if (loop < 1 || loop > kMaxLoop)
    throw UsageError(
        "lower_loop: '" + std::to_string(loop) + "' is out of range (1 to " + std::to_string(kMaxLoop) + ")",
        "a loop number from 1, as 'spira-cli info' lists the loops, or leave it out to stand the part "
        "on its lowest loop");
  return static_cast<int>(loop - 1);
}

double substrateZOf(double z)
{
  constexpr double kMaxZ = 1e6;
  if (!std::isfinite(z) || std::abs(z) > kMaxZ)
    throw UsageError("substrate_z: '" + std::to_string(z) + "' is out of range (-1e6 to 1e6 mm)",
                     "a height in mm, e.g. substrate_z=0");
  return z;
}

py::array_t<double> vertexArray(const TriangleMesh& mesh)
{
  py::array_t<double> out({static_cast<py::ssize_t>(mesh.vertices.size()), py::ssize_t(3)});
  auto a = out.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) a(static_cast<py::ssize_t>(i), k) = mesh.vertices[i][k];
  return out;
}

py::array_t<std::int64_t> faceArray(const TriangleMesh& mesh)
{
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(mesh.faces.size()), py::ssize_t(3)});
  auto a = out.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.faces.size(); ++i)
    for (int k = 0; k < 3; ++k) a(static_cast<py::ssize_t>(i), k) = mesh.faces[i][k];
  return out;
}

}  // namespace

ImportChoices::ImportChoices()
{
  const auto importers = builtinRegistry().ofKind(PluginKind::Importer);
  for (const Plugin* p : importers) values[p->id()];
  for (const Plugin* p : importers) targets.push_back(FlagTarget{p->id(), &p->schema(), &values[p->id()]});
}

void ImportChoices::takePlacement(Options& options)
{
  if (const auto loop = options.takeInteger("lower_loop")) placement.lowerLoop = lowerLoopOf(*loop);
  if (const auto z = options.takeNumber("substrate_z")) placement.substrateZ = substrateZOf(*z);
  placement.drop = options.takeBool("drop").value_or(false);
  placement.levelBase = options.takeBool("level_base").value_or(false);
}

LoadedPart loadPart(const std::string& path, const ImportChoices& choices, PythonProgress& progress)
{
  const PluginRegistry& registry = builtinRegistry();
  LoadedPart out;
  out.placement = choices.placement;
  ImportedPart imported = progress.run([&] {
    const auto t0 = std::chrono::steady_clock::now();
    const ParamSet& values = choices.values.at(registry.importerForFile(path).id());
    ImportedPart read = importPart(registry, path, &values, progress);
    out.placed = placePart(read.mesh, read.report, out.placement);
    out.importSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return read;
  });
  auto part = std::make_shared<Part>();
  part->name = std::filesystem::path(path).stem().string();
  part->sourcePath = path;
  part->sourceUnit = imported.sourceUnit;
  part->mesh = std::make_shared<const TriangleMesh>(std::move(imported.mesh));
  part->lowerBoundaryOverride = out.placement.lowerLoop;
  out.part = std::move(part);
  out.report = std::move(imported.report);
  out.importerId = std::move(imported.importerId);
  out.warnings = std::move(imported.warnings);
  return out;
}

void bindPart(py::module_& m)
{
  py::class_<LoadedPart>(m, "Part", "A part file imported (welded, in mm) and placed on the substrate.")
      .def_property_readonly("name", [](const LoadedPart& p) { return p.part->name; })
      .def_property_readonly("path", [](const LoadedPart& p) { return p.part->sourcePath; })
      .def_property_readonly(
          "vertices", [](const LoadedPart& p) { return vertexArray(*p.part->mesh); },
          "Vertex positions, N x 3, mm, as planned (after drop or level_base).")
      .def_property_readonly(
          "faces", [](const LoadedPart& p) { return faceArray(*p.part->mesh); },
          "Triangles as vertex indices, M x 3.")
      .def_property_readonly(
          "report", [](const LoadedPart& p) { return toPython(p.report.toJson()); },
          "The mesh's validation report, as 'spira-cli info --json' gives it.")
      .def_property_readonly("part_class",
                             [](const LoadedPart& p) { return std::string(p.report.className()); })
      .def_property_readonly("importer", [](const LoadedPart& p) { return p.importerId; })
      .def_property_readonly("warnings", [](const LoadedPart& p) { return p.warnings; })
      .def_property_readonly("dropped_mm", [](const LoadedPart& p) { return p.placed.dropped; })
      .def_property_readonly("substrate_z", [](const LoadedPart& p) { return p.placement.substrateZ; })
      .def("__repr__", [](const LoadedPart& p) {
        return "<spira.Part '" + p.part->name + "': " + std::to_string(p.report.vertexCount) + " vertices, " +
               std::to_string(p.report.faceCount) + " faces, " + p.report.className() + ">";
      });

  m.def(
      "load_part",
      [](py::object path, py::kwargs kwargs) {
        const std::string file = pathArgument("load_part", "path", path);
        Options options("load_part", kwargs);
        ImportChoices choices;
        choices.takePlacement(options);
        options.takeSettings(choices.targets);
        PythonProgress progress("load_part", options.take("progress"));
        options.finish();
        return loadPart(file, choices, progress);
      },
      py::arg("path"),
      "load_part(path, *, lower_loop=None, substrate_z=0.0, drop=False, level_base=False, progress=None, "
      "**importer_settings) -> Part\n\n"
      "Imports a part file with the importer of its extension (importer settings such as unit='m' by key),\n"
      "places it as 'spira-cli plan' does (lower_loop numbered from 1 as 'spira-cli info' lists the loops)\n"
      "and validates it.");
}

}  // namespace spira::python
