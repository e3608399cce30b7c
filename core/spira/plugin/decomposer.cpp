#include "spira/plugin/decomposer.h"

#include "spira/base/error.h"

namespace spira {

DecomposeResult DecomposerPlugin::decompose(const DecomposeInput& input, const ParamSet& params,
                                            Progress& progress) const
{
  std::string why;
  if (!accepts(input, &why))
    throw InputError(id() + " cannot plan this part: " + why, "choose another strategy with --strategy");
  const ParamSet values = params.withDefaults(schema());
  schema().validate(values);
  return decomposeChecked(input, values, progress);
}

}  // namespace spira
