#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// How the arrays of a .vtp file are stored. AppendedRaw is compact, fast and keeps NaN and
// infinity; Ascii is readable text but VTK's text parser stops at "nan"/"inf", so it refuses
// fields with non-finite values.
enum class VtpEncoding { Ascii, AppendedRaw };

// CSV, one row per vertex: header `vertex,x,y,z,value`, then the vertex id, its position (mm)
// and its value, each number in the shortest text that reads back to the same double.
std::string fieldToCsv(const TriangleMesh& mesh, const std::vector<double>& values);
void writeFieldCsv(const std::filesystem::path& path, const TriangleMesh& mesh,
                   const std::vector<double>& values);

// VTK XML PolyData (.vtp), readable by ParaView without VTK on our side: Points (Float64),
// Polys (Int64 connectivity and offsets) and one Float64 PointData array named `fieldName`,
// marked as the active scalars.
// Throws InputError if `values` does not match the mesh, or for non-finite values in Ascii.
std::string fieldToVtp(const TriangleMesh& mesh, const std::vector<double>& values,
                       const std::string& fieldName, VtpEncoding encoding = VtpEncoding::AppendedRaw);
// Both writers go through writeFileAtomically: a reader never sees a half-written file.
void writeFieldVtp(const std::filesystem::path& path, const TriangleMesh& mesh,
                   const std::vector<double>& values, const std::string& fieldName,
                   VtpEncoding encoding = VtpEncoding::AppendedRaw);

}  // namespace spira
