#include "part_plan.h"

#include <chrono>
#include <filesystem>
#include <iostream>

#include "spira/plugin/strategy_name.h"
#include "substrate_flag.h"

namespace fs = std::filesystem;

namespace spira::cli {
namespace {

// The part as a document holds it: placed (the mesh moved or cut), standing on the plate.
std::shared_ptr<const Part> partOf(ImportedPart imported, const std::string& file, int lowerLoop)
{
  auto part = std::make_shared<Part>();
  part->name = fs::path(file).stem().string();
  part->sourcePath = file;
  part->sourceUnit = imported.sourceUnit;
  part->mesh = std::make_shared<const TriangleMesh>(std::move(imported.mesh));
  part->lowerBoundaryOverride = lowerLoop;
  return part;
}

}  // namespace

void PartPlanFlags::take(Args& args)
{
  strategy = args.takeOption("--strategy");
  placement = PartPlacement::take(args);
  noMidSurface = args.takeSwitch("--no-mid-surface");
  if (strategy.empty()) strategy = strategyName(kDefaultDecomposerId);
}

std::vector<FlagTarget> PartPlanFlags::targets() const
{
  std::vector<FlagTarget> all = planFlags.targets;
  all.insert(all.end(), importFlags.targets().begin(), importFlags.targets().end());
  return all;
}

PlannedPart planPartFile(const PluginRegistry& registry, const std::string& file, PartPlanFlags& flags,
                         std::shared_ptr<const CellRecord> cell, bool keepCollisions, Progress& progress)
{
  PlannedPart out;
  const auto t0 = std::chrono::steady_clock::now();
  ImportedPart imported = flags.importFlags.import(file, progress);
  for (const auto& w : imported.warnings) std::cerr << "warning: " << w << "\n";
  out.placed = flags.placement.apply(imported);
  std::cout << out.placed.text(flags.placement.substrateZ);
  const double importSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  DocumentState& snapshot = out.snapshot;
  snapshot.cell = std::move(cell);
  snapshot.part = partOf(std::move(imported), file, flags.placement.lowerLoop);
  Substrate plate;
  plate.planeZ = flags.placement.substrateZ;
  snapshot.substrate = std::make_shared<const Substrate>(
      flags.substrate.empty() ? std::move(plate)
                              : substrateFromFlag(flags.substrate, flags.importFlags, progress));
  snapshot.settings = std::make_shared<const PlanSettings>(PlanSettings{
      decomposerIdOf(flags.strategy), PlanSettings::kDefaultClosureFinder, flags.planFlags.values});

  PlanDocumentOptions options;
  options.midSurfaceOfSolid = !flags.noMidSurface;
  options.resolveCollisions = !keepCollisions;
  out.plan = planDocument(snapshot, registry, progress, options);
  if (out.plan.output.solid) std::cout << out.plan.output.solid->summary() << "\n";
  nlohmann::json& report = out.plan.report;
  report["dropped_mm"] = out.placed.dropped;
  if (out.placed.levelled)
    report["levelled_base"] = {{"cut_z_mm", out.placed.cutZ}, {"removed_mm", out.placed.removed}};
  report["timings_s"]["import"] = importSeconds;
  if (snapshot.substrate->kind == Substrate::Kind::Mesh)
    report["substrate"] = {{"kind", "mesh"},
                           {"name", snapshot.substrate->meshName},
                           {"triangles", snapshot.substrate->mesh->faces.size()}};
  return out;
}

}  // namespace spira::cli
