#include "examples/plugin_sdk/xyz_exporter.h"

#include <sstream>

#include "spira/base/atomic_file.h"
#include "spira/base/progress.h"

namespace spira::example {

const ParamSchema& XyzExporter::schema() const
{
  static const ParamSchema s({ParamDef{"name",
                                       ParamType::String,
                                       std::string("path"),
                                       {},
                                       {},
                                       "",
                                       "File name",
                                       "Name of the .xyz file, without extension.",
                                       "Output",
                                       {}}});
  return s;
}

ExportResult XyzExporter::write(const ExportInput& input, const ParamSet& params,
                                const std::filesystem::path& outDir, Progress& progress) const
{
  std::ostringstream text;
  for (const auto& [key, value] : input.header) text << "# " << key << ": " << value << "\n";
  text.precision(10);
  for (const TrajectoryPoint& p : input.trajectory.points)
    text << p.position.x() << ' ' << p.position.y() << ' ' << p.position.z() << ' ' << p.travelSpeed << '\n';
  progress.checkCancel();
  const std::filesystem::path file = outDir / (params.getString("name") + ".xyz");
  writeFileAtomically(file, text.str());  // all or nothing, as every exporter must
  return ExportResult{{file}, {}};
}

}  // namespace spira::example
