#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/io/import_service.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/plugin/plugin_registry.h"

namespace spira::test {

// A registry holding every built-in plugin (the importers under test among them).
const PluginRegistry& ioRegistry();

// importPart with the importer's defaults, or with one parameter set.
ImportedPart importFile(const std::filesystem::path& file);
ImportedPart importFile(const std::filesystem::path& file, const std::string& key, const ParamValue& value);

// Largest distance between corresponding face corners of two meshes whose faces come in the
// same order; infinity when the face counts differ.
double maxCornerDistance(const TriangleMesh& a, const TriangleMesh& b);
// True when both meshes share one vertex wherever the other does (same connectivity up to
// vertex renumbering, faces in the same order).
bool sameConnectivity(const TriangleMesh& a, const TriangleMesh& b);

// Signed enclosed volume (positive for a closed mesh with outward faces).
double signedVolume(const TriangleMesh& m);

// Largest |r - R| over the vertices (vertexOnly) or over a dense sample of every triangle, for a
// surface of revolution about Z whose profile is the line r(z) = r0 + (r1 - r0) * z / height:
// the distance to that cone or cylinder, measured perpendicular to the profile line.
double maxDistanceToRevolvedLine(const TriangleMesh& m, double r0, double r1, double height, bool vertexOnly);

// Exercises an error path: runs `f`, expects exception type E with a one-line message and a hint.
template <class E, class F>
::testing::AssertionResult throwsOneLine(F&& f, const std::string& mustContain = {})
{
  try {
    f();
  } catch (const E& e) {
    const std::string what = e.what();
    if (what.find('\n') != std::string::npos) return ::testing::AssertionFailure() << "multi-line: " << what;
    if (e.hint().empty()) return ::testing::AssertionFailure() << "no hint: " << what;
    if (!mustContain.empty() && what.find(mustContain) == std::string::npos)
      return ::testing::AssertionFailure() << "'" << what << "' does not mention '" << mustContain << "'";
    return ::testing::AssertionSuccess() << what << " (" << e.hint() << ")";
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "wrong exception type: " << e.what();
  }
  return ::testing::AssertionFailure() << "no exception";
}

// An import refused as InputError on one line with a hint, naming the file and `mustContain`, with
// none of Assimp's own words.
::testing::AssertionResult refusedImport(const std::filesystem::path& file, const std::string& mustContain);

// Whether one of the import's warnings contains `text` (the failure lists them all).
::testing::AssertionResult hasImportWarning(const ImportedPart& part, const std::string& text);

}  // namespace spira::test
