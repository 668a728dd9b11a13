#include "render/series_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

namespace sedem::render {

namespace {

// Collects the errors a VTK reader or parser reports (VTK's own printing is off).
class ErrorCatcher : public vtkCommand {
 public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override {
    if (message.empty() && data) message = static_cast<const char*>(data);
    failed = true;
  }
  bool failed = false;
  std::string message;
};

[[noreturn]] void damaged(const std::filesystem::path& file, const std::string& why) {
  throw SeriesError(file.string() + ": damaged or not a sedem file: " + why);
}

// Whether the file's last non-blank bytes close its VTKFile element.
bool ends_whole(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff tail = std::min<std::streamoff>(size, 64);
  std::string end(static_cast<std::size_t>(tail), '\0');
  in.seekg(size - tail);
  in.read(end.data(), tail);
  if (!in) return false;
  while (!end.empty() && std::isspace(static_cast<unsigned char>(end.back()))) end.pop_back();
  const std::string close = "</VTKFile>";
  return end.size() >= close.size() &&
         end.compare(end.size() - close.size(), close.size(), close) == 0;
}

// Whether the file's XML head names a DataArray `name`: VTK drops an array whose compressed
// data does not inflate, with no error, so a missing array that the head declares is damage.
bool declares_array(const std::filesystem::path& file, const char* name) {
  std::ifstream in(file, std::ios::binary);
  std::string head(1 << 16, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  const auto appended = head.find("<AppendedData");
  if (appended != std::string::npos) head.resize(appended);
  return head.find(std::string("Name=\"") + name + "\"") != std::string::npos;
}

}  // namespace

std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(pvd, ec)) throw SeriesError("cannot read " + pvd.string());
  // VTK's XML parser (expat): a file cut short or otherwise not well-formed is refused, not
  // read as far as it goes.
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  auto errors = vtkSmartPointer<ErrorCatcher>::New();
  parser->AddObserver(vtkCommand::ErrorEvent, errors);
  parser->SetFileName(pvd.c_str());
  if (!parser->Parse() || errors->failed) damaged(pvd, "not well-formed XML");
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!root || std::string(root->GetName()) != "VTKFile" || !root->GetAttribute("type") ||
      std::string(root->GetAttribute("type")) != "Collection")
    damaged(pvd, "not a ParaView collection (VTKFile type=\"Collection\")");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (!collection) damaged(pvd, "no Collection element");
  std::vector<std::pair<double, std::string>> entries;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    if (std::string(e->GetName()) != "DataSet") continue;
    double time = 0;
    const char* file = e->GetAttribute("file");
    if (!e->GetScalarAttribute("timestep", time) || !std::isfinite(time))
      damaged(pvd, "entry " + std::to_string(i + 1) + " has no valid timestep");
    if (!file || !*file) damaged(pvd, "entry " + std::to_string(i + 1) + " names no file");
    const std::filesystem::path relative(file);
    if (relative.is_absolute() || std::any_of(relative.begin(), relative.end(),
                                              [](const auto& part) { return part == ".."; }))
      damaged(pvd, "entry " + std::to_string(i + 1) + " names a file outside its folder");
    if (!entries.empty() && time < entries.back().first)
      damaged(pvd, "its times go backwards at entry " + std::to_string(i + 1));
    entries.emplace_back(time, file);
  }
  return entries;
}

Snapshot read_particles_vtp(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) throw SeriesError("no such file: " + file.string());
  // A file cut short: VTK reads what it can of it and says nothing (its arrays are then simply
  // missing), so its end is looked at first.
  if (!ends_whole(file)) damaged(file, "cut short (it does not end with </VTKFile>)");
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  auto errors = vtkSmartPointer<ErrorCatcher>::New();
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  // The XML parser's and the decompressor's complaints go to these, not to the reader.
  reader->SetReaderErrorObserver(errors);
  reader->SetParserErrorObserver(errors);
  if (!reader->CanReadFile(file.c_str())) damaged(file, "not a VTK XML PolyData file");
  reader->SetFileName(file.c_str());
  // A damaged header can make VTK size an array from garbage: it then throws (bad_alloc,
  // length_error) from inside the reader, which is damage too, not a failure to write.
  try {
    reader->Update();
  } catch (const std::exception& e) {
    damaged(file, std::string("its data does not read back (") + e.what() + ")");
  }
  if (errors->failed) damaged(file, errors->message.empty() ? "unreadable" : errors->message);
  vtkPolyData* poly = reader->GetOutput();
  auto* pd = poly->GetPointData();
  const vtkIdType points = poly->GetNumberOfPoints();
  auto array = [&](const char* name) {
    vtkDataArray* a = pd->GetArray(name);
    if (!a && declares_array(file, name))
      damaged(file, std::string("point array '") + name +
                        "' is declared but its data does not read back (corrupted)");
    if (!a) damaged(file, std::string("no point array '") + name + "'");
    if (a->GetNumberOfTuples() != points)
      damaged(file, std::string("point array '") + name + "' is cut short");
    return a;
  };
  vtkDataArray* diameter = array("diameter");
  vtkDataArray* velocity = array("velocity");
  vtkDataArray* weight = array("weight");
  vtkDataArray* size_class = array("size_class");
  vtkDataArray* id = array("id");
  vtkDataArray* time = poly->GetFieldData()->GetArray("TimeValue");
  if (!time || time->GetNumberOfTuples() < 1) damaged(file, "no field data 'TimeValue'");

  Snapshot s;
  s.time = time->GetTuple1(0);
  const auto n = std::size_t(poly->GetNumberOfPoints());
  auto& p = s.particles;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = vtkIdType(i);
    double xyz[3];
    poly->GetPoint(k, xyz);
    p.x[i] = xyz[0];
    p.y[i] = xyz[1];
    p.vx[i] = velocity->GetComponent(k, 0);
    p.vy[i] = velocity->GetComponent(k, 1);
    p.diameter[i] = diameter->GetTuple1(k);
    p.weight[i] = weight->GetTuple1(k);
    p.size_class[i] = std::int32_t(size_class->GetTuple1(k));
    p.id[i] = std::uint32_t(id->GetTuple1(k));
  }
  return s;
}

}  // namespace sedem::render
