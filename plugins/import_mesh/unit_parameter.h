#pragma once

#include "spira/plugin/parameter.h"

namespace spira::import_mesh {

// The schema every mesh importer of this plugin shares: formats that do not store a length unit
// ask for it through one `unit` parameter, declared here once.
const ParamSchema& unitlessMeshSchema();

}  // namespace spira::import_mesh
