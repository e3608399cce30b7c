#include "cad_importer.h"

#include "spira/base/error.h"

namespace spira::import_cad {
namespace {

std::vector<ParamDef> tessellationParams()
{
  return {
      numberParam(
          "linear_deflection", 0.1, 0.001, 10.0, "mm",
          {"Linear deflection",
           "Largest distance allowed between the CAD surface and its triangles. Smaller values follow "
           "curved walls more closely and give more triangles.",
           "Tessellation"}),
      numberParam(
          "angular_deflection", 10.0, 1.0, 45.0, "deg",
          {"Angular deflection",
           "Largest angle between neighbouring triangles on curved surfaces. Keeps small radii smooth "
           "where the linear deflection alone would allow coarse facets.",
           "Tessellation"}),
  };
}

ParamSchema makeSchema(bool withUnit)
{
  std::vector<ParamDef> defs = tessellationParams();
  if (withUnit)
    defs.push_back(
        choiceParam("unit", "mm", {"mm", "cm", "m", "in"},
                    {"File unit",
                     "The length unit the BREP file is written in. BREP does not record it: choose "
                     "the unit of the program that wrote it (Spira converts to millimetres).",
                     "Import"}));
  return ParamSchema(std::move(defs));
}

}  // namespace

CadImporter::CadImporter(CadFormat format) : format_(format) {}

std::string CadImporter::id() const
{
  switch (format_) {
    case CadFormat::Step:
      return "import.step";
    case CadFormat::Iges:
      return "import.iges";
    case CadFormat::Brep:
      return "import.brep";
  }
  return "import.cad";
}

std::string CadImporter::label() const
{
  switch (format_) {
    case CadFormat::Step:
      return "STEP model";
    case CadFormat::Iges:
      return "IGES model";
    case CadFormat::Brep:
      return "OpenCASCADE BREP model";
  }
  return "CAD model";
}

std::string CadImporter::description() const
{
  const std::string common = " Surfaces are tessellated with OpenCASCADE to the requested deflection.";
  switch (format_) {
    case CadFormat::Step:
      return "STEP (AP203, AP214, AP242) solids and surfaces, converted to millimetres." + common;
    case CadFormat::Iges:
      return "IGES surfaces and solids, converted to millimetres." + common;
    case CadFormat::Brep:
      return "OpenCASCADE native BREP shape; it stores no unit." + common;
  }
  return common;
}

const ParamSchema& CadImporter::schema() const
{
  static const ParamSchema withUnit = makeSchema(true);
  static const ParamSchema withoutUnit = makeSchema(false);
  return format_ == CadFormat::Brep ? withUnit : withoutUnit;
}

std::vector<std::string> CadImporter::extensions() const
{
  switch (format_) {
    case CadFormat::Step:
      return {"step", "stp"};
    case CadFormat::Iges:
      return {"iges", "igs"};
    case CadFormat::Brep:
      return {"brep"};
  }
  return {};
}

ImportedMesh CadImporter::read(const std::filesystem::path& file, const ParamSet& params,
                               Progress& progress) const
{
  const ParamSet values = params.withDefaults(schema());
  // STEP and IGES are transferred in millimetres; a BREP comes out in its own unit, so the
  // deflection is expressed in that unit and the import service scales the result.
  LengthUnit unit = LengthUnit::Millimetre;
  if (format_ == CadFormat::Brep) {
    const auto parsed = parseLengthUnit(values.getString("unit"));
    if (!parsed)
      throw InputError("unknown BREP unit '" + values.getString("unit") + "'", "use mm, cm, m or in");
    unit = *parsed;
  }
  TessellationSettings settings;
  settings.linearDeflection = values.internal(schema(), "linear_deflection") / millimetresPer(unit);
  settings.angularDeflection = values.internal(schema(), "angular_deflection");
  CadMesh cad = importCadFile(file, format_, settings, progress);
  ImportedMesh out;
  out.mesh = std::move(cad.mesh);
  out.unit = unit;
  out.fileUnit = cad.fileUnit;
  out.warnings = std::move(cad.warnings);
  return out;
}

}  // namespace spira::import_cad
