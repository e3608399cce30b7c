// spira-import: the helper process that runs a third-party importer (OpenCASCADE) for spira and
// spira-cli, so that a crash in it cannot take them down. See core/spira/io/isolated_import.h.
#include "builtin_plugins.h"
#include "spira/io/isolated_import.h"

int main(int argc, char** argv)
{
  return spira::importHelperMain(argc, argv, spira::builtinRegistry());
}
