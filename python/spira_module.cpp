// `import spira`: Spira's planning from Python (README.md, "Python").
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "builtin_plugins.h"
#include "py_errors.h"
#include "py_part.h"
#include "py_plan.h"
#include "spira/base/version.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/plugin/strategy_name.h"

namespace py = pybind11;

PYBIND11_MODULE(spira, m)
{
  using namespace spira;
  m.doc() = "Spira: one continuous spiral deposition path for wire-arc additive manufacturing.";
  m.attr("__version__") = kVersion;
  python::bindErrors(m);
  python::bindPart(m);
  python::bindPlan(m);
  m.def(
      "strategies",
      [] {
        std::vector<std::string> out;
        for (const Plugin* p : builtinRegistry().ofKind(PluginKind::Decomposer))
          out.push_back(strategyName(p->id()));
        return out;
      },
      "The decomposition strategies plan() takes as strategy=.");
  m.def(
      "formats",
      [] {
        std::vector<std::string> out;
        for (const Plugin* p : builtinRegistry().ofKind(PluginKind::Exporter)) out.push_back(p->id());
        return out;
      },
      "The exporter ids Plan.export() takes as format (or their name after 'export.').");
}
