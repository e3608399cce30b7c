#include "unit_parameter.h"

namespace spira::import_mesh {

const ParamSchema& unitlessMeshSchema()
{
  static const ParamSchema schema({ParamDef{
      "unit",
      ParamType::Choice,
      std::string("mm"),
      std::nullopt,
      std::nullopt,
      "",
      "File unit",
      "The length unit the file's coordinates are written in. STL, OBJ and PLY do not record it: choose "
      "the unit the exporting program used (Spira converts to millimetres).",
      "Import",
      {"mm", "cm", "m", "in"},
  }});
  return schema;
}

}  // namespace spira::import_mesh
