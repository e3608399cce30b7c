#include "unit_parameter.h"

namespace spira::import_mesh {

const ParamSchema& unitlessMeshSchema()
{
  static const ParamSchema schema({choiceParam(
      "unit", "mm", {"mm", "cm", "m", "in"},
      {"File unit",
       "The length unit the file's coordinates are written in. STL, OBJ and PLY do not record it: choose "
       "the unit the exporting program used (Spira converts to millimetres).",
       "Import"})});
  return schema;
}

}  // namespace spira::import_mesh
