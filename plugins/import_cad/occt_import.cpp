// The only translation unit of Spira that includes OpenCASCADE headers (besides OCCT-only tests):
// their Handle macro breaks CGAL, so nothing here leaks into a header.
#include "occt_import.h"

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressRange.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <Standard_OutOfMemory.hxx>
#include <StepShape_Face.hxx>
#include <StepShape_OrientedFace.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <mutex>
#include <new>
#include <thread>

#include "spira/base/error.h"
#include "spira/io/mapped_file.h"
#include "spira/io/step_tokens.h"

namespace spira::import_cad {
namespace {

// Interface_Static and the unit factors of the XSTEP transfer are process-wide in OpenCASCADE
// 7.6, so concurrent reads would race on them. Reading is serialised; meshing is not.
std::mutex& transferMutex()
{
  static std::mutex m;
  return m;
}

// Lets a cancel request stop OpenCASCADE's long loops. Progress is forwarded only from the
// calling thread: BRepMesh calls Show() from its worker threads too.
class ProgressBridge final : public Message_ProgressIndicator {
 public:
  ProgressBridge(Progress& progress, const char* stage)
      : progress_(progress), stage_(stage), thread_(std::this_thread::get_id())
  {
  }
  Standard_Boolean UserBreak() override { return progress_.cancelled(); }
  void Show(const Message_ProgressScope&, const Standard_Boolean) override
  {
    if (std::this_thread::get_id() == thread_) progress_.report(GetPosition(), stage_);
  }

 private:
  Progress& progress_;
  const char* stage_;
  std::thread::id thread_;
};

const char* formatName(CadFormat f)
{
  switch (f) {
    case CadFormat::Step:
      return "STEP";
    case CadFormat::Iges:
      return "IGES";
    case CadFormat::Brep:
      return "BREP";
  }
  return "CAD";
}

InputError unreadable(const std::filesystem::path& file, CadFormat format, const std::string& why)
{
  return InputError("cannot read '" + file.filename().string() + "' as " + formatName(format) + ": " + why,
                    std::string("the file is damaged or not ") + (format == CadFormat::Iges ? "an " : "a ") +
                        formatName(format) + " file; export it again from the CAD program");
}

std::optional<LengthUnit> unitFromStepName(std::string name)
{
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (name == "MILLIMETRE" || name == "MM") return LengthUnit::Millimetre;
  if (name == "CENTIMETRE" || name == "CM") return LengthUnit::Centimetre;
  if (name == "METRE" || name == "M") return LengthUnit::Metre;
  if (name == "MICROMETRE" || name == "UM") return LengthUnit::Micrometre;
  if (name == "INCH" || name == "IN") return LengthUnit::Inch;
  if (name == "FOOT" || name == "FT") return LengthUnit::Foot;
  return std::nullopt;
}

std::optional<LengthUnit> unitFromIgesFlag(int flag)
{
  switch (flag) {
    case 1:
      return LengthUnit::Inch;
    case 2:
      return LengthUnit::Millimetre;
    case 4:
      return LengthUnit::Foot;
    case 6:
      return LengthUnit::Metre;
    case 9:
      return LengthUnit::Micrometre;
    case 10:
      return LengthUnit::Centimetre;
    default:
      return std::nullopt;
  }
}

std::string fileHead(const std::filesystem::path& file, size_t bytes)
{
  std::ifstream in(file, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(static_cast<size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head;
}

// OpenCASCADE's parsers print noise and, for IGES, leak their buffers on files that are not
// STEP or IGES at all: such files are refused here from their first bytes.
void checkSignature(const std::filesystem::path& file, CadFormat format)
{
  std::string head = fileHead(file, 512);
  if (head.compare(0, 3, "\xEF\xBB\xBF") == 0) head.erase(0, 3);
  if (format == CadFormat::Step) {
    const size_t start = head.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || head.compare(start, 13, "ISO-10303-21;") != 0)
      throw unreadable(file, format, "it does not start with 'ISO-10303-21;'");
  } else if (format == CadFormat::Iges) {
    // Fixed-format IGES: 80-column records with the section letter in column 73 (S or G first;
    // C for compressed files).
    const std::string line = head.substr(0, head.find('\n'));
    if (line.size() < 73 || std::string("SGC").find(line[72]) == std::string::npos)
      throw unreadable(file, format, "its first line has no IGES section letter in column 73");
  }
}

// Makes the transfer produce millimetres whatever the file says.
void requestMillimetres()
{
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
}

// A face the file declares but whose references do not resolve is silently left out of the
// transfer; counting the declared ones is how the loss is noticed. An oriented face only points
// at another face.
size_t declaredFaces(const STEPControl_Reader& reader)
{
  const Handle(Interface_InterfaceModel) model = reader.Model();
  size_t n = 0;
  for (Standard_Integer i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Standard_Transient)& e = model->Value(i);
    if (e->IsKind(STANDARD_TYPE(StepShape_Face)) && !e->IsKind(STANDARD_TYPE(StepShape_OrientedFace))) ++n;
  }
  return n;
}

TopoDS_Shape readStep(const std::filesystem::path& file, Progress& progress, CadMesh& out, size_t& declared)
{
  checkStepTokens(MappedFile(file).bytes(), file.filename().string());
  std::lock_guard<std::mutex> lock(transferMutex());
  STEPControl_Reader reader;
  requestMillimetres();
  if (reader.ReadFile(file.c_str()) != IFSelect_RetDone)
    throw unreadable(file, CadFormat::Step, "syntax error");
  reader.SetSystemLengthUnit(1.0);
  TColStd_SequenceOfAsciiString lengths, angles, solidAngles;
  reader.FileUnits(lengths, angles, solidAngles);
  if (lengths.Length() > 0) {
    out.fileUnit = unitFromStepName(lengths.First().ToCString());
    if (!out.fileUnit)
      out.warnings.push_back(std::string("the STEP length unit '") + lengths.First().ToCString() +
                             "' has no Spira name; the part was converted to millimetres");
  }
  if (reader.NbRootsForTransfer() == 0) throw unreadable(file, CadFormat::Step, "it contains no shape");
  declared = declaredFaces(reader);
  Handle(ProgressBridge) bridge = new ProgressBridge(progress, "Reading STEP");
  reader.TransferRoots(bridge->Start());
  progress.checkCancel();
  return reader.OneShape();
}

TopoDS_Shape readIges(const std::filesystem::path& file, Progress& progress, CadMesh& out)
{
  std::lock_guard<std::mutex> lock(transferMutex());
  IGESControl_Reader reader;
  requestMillimetres();
  if (reader.ReadFile(file.c_str()) != IFSelect_RetDone)
    throw unreadable(file, CadFormat::Iges, "syntax error");
  const IGESData_GlobalSection& global = reader.IGESModel()->GlobalSection();
  out.fileUnit = unitFromIgesFlag(global.UnitFlag());
  if (!out.fileUnit) {
    const auto name = global.UnitName();
    out.warnings.push_back(std::string("the IGES length unit '") + (name.IsNull() ? "?" : name->ToCString()) +
                           "' has no Spira name; the part was converted to millimetres");
  }
  if (reader.NbRootsForTransfer() == 0) throw unreadable(file, CadFormat::Iges, "it contains no shape");
  Handle(ProgressBridge) bridge = new ProgressBridge(progress, "Reading IGES");
  reader.TransferRoots(bridge->Start());
  progress.checkCancel();
  return reader.OneShape();
}

TopoDS_Shape readBrep(const std::filesystem::path& file, Progress& progress)
{
  TopoDS_Shape shape;
  BRep_Builder builder;
  Handle(ProgressBridge) bridge = new ProgressBridge(progress, "Reading BREP");
  if (!BRepTools::Read(shape, file.c_str(), builder, bridge->Start()))
    throw unreadable(file, CadFormat::Brep, "not an OpenCASCADE shape file");
  progress.checkCancel();
  // A stored triangulation may be coarser or finer than asked: always tessellate afresh.
  BRepTools::Clean(shape);
  return shape;
}

void tessellate(const TopoDS_Shape& shape, const TessellationSettings& settings, Progress& progress)
{
  IMeshTools_Parameters params;
  params.Deflection = settings.linearDeflection;
  params.Angle = settings.angularDeflection;
  params.Relative = Standard_False;
  params.InParallel = Standard_True;
  Handle(ProgressBridge) bridge = new ProgressBridge(progress, "Tessellating");
  BRepMesh_IncrementalMesh mesher(shape, params, bridge->Start());
  progress.checkCancel();
  if (!mesher.IsDone())
    throw AlgorithmError("OpenCASCADE could not tessellate the part", "try a larger deflection");
}

// Returns how many distinct faces were meshed: an instance placed twice counts once, as the file
// declares it once.
size_t collectTriangles(const TopoDS_Shape& shape, Progress& progress, CadMesh& out)
{
  size_t missing = 0;
  TopTools_MapOfShape meshed;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    progress.checkCancel();
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, location);
    if (tri.IsNull() || tri->NbTriangles() == 0) {
      ++missing;
      continue;
    }
    meshed.Add(face.Located(TopLoc_Location()));
    const gp_Trsf T = location.Transformation();
    // Triangles run counter-clockwise around the surface normal; a reversed face (or a mirroring
    // placement) points the other way in the solid, so its corners are swapped.
    const bool flip = (face.Orientation() == TopAbs_REVERSED) != T.IsNegative();
    const int base = static_cast<int>(out.mesh.vertices.size()) - 1;  // OCCT indices start at 1
    for (Standard_Integer i = 1; i <= tri->NbNodes(); ++i) {
      const gp_Pnt p = tri->Node(i).Transformed(T);
      out.mesh.vertices.emplace_back(p.X(), p.Y(), p.Z());
    }
    for (Standard_Integer t = 1; t <= tri->NbTriangles(); ++t) {
      Standard_Integer a = 0, b = 0, c = 0;
      tri->Triangle(t).Get(a, b, c);
      if (flip) std::swap(b, c);
      out.mesh.faces.push_back({base + a, base + b, base + c});
    }
  }
  if (missing > 0)
    out.warnings.push_back(std::to_string(missing) +
                           " CAD faces could not be tessellated and are missing from the mesh; check the "
                           "model for broken faces");
  return static_cast<size_t>(meshed.Extent());
}

// Refuses a part that lost more than this fraction of its faces: what is left has holes the
// planner would take for the part's own boundary.
constexpr double kMaxLostFaceFraction = 0.05;

void checkLostFaces(const std::filesystem::path& file, size_t declared, size_t meshed, CadMesh& out)
{
  if (meshed >= declared) return;
  const std::string what = "'" + file.filename().string() + "' declares " + std::to_string(declared) +
                           " faces but only " + std::to_string(meshed) +
                           " could be read (unresolved or wrong-typed references)";
  if (static_cast<double>(declared - meshed) > kMaxLostFaceFraction * static_cast<double>(declared))
    throw InputError(what + "; the part would have holes where they were",
                     "re-export the part from the CAD program as STEP AP214 or AP242");
  out.warnings.push_back(what + "; the part has holes where they were");
}

}  // namespace

CadMesh importCadFile(const std::filesystem::path& file, CadFormat format,
                      const TessellationSettings& settings, Progress& progress)
{
  CadMesh out;
  try {
    TopoDS_Shape shape;
    size_t declared = 0;
    checkSignature(file, format);
    switch (format) {
      case CadFormat::Step:
        shape = readStep(file, progress, out, declared);
        break;
      case CadFormat::Iges:
        shape = readIges(file, progress, out);
        break;
      case CadFormat::Brep:
        shape = readBrep(file, progress);
        break;
    }
    if (shape.IsNull()) throw unreadable(file, format, "no shape could be transferred");
    tessellate(shape, settings, progress);
    const size_t meshed = collectTriangles(shape, progress, out);
    checkLostFaces(file, declared, meshed, out);
  } catch (const Standard_OutOfMemory&) {
    throw std::bad_alloc();
  } catch (const Standard_Failure& e) {
    throw unreadable(file, format, std::string("OpenCASCADE: ") + e.GetMessageString());
  }
  return out;
}

}  // namespace spira::import_cad
