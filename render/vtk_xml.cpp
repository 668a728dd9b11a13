#include "render/vtk_xml.h"

#include <stdexcept>
#include <string>

#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

namespace sedem::render {

void write_vtk_xml(vtkDataObject* data, const std::filesystem::path& file) {
  vtkSmartPointer<vtkXMLWriter> writer;
  if (vtkPolyData::SafeDownCast(data)) {
    writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  } else if (vtkImageData::SafeDownCast(data)) {
    writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
  } else {
    throw std::invalid_argument("write_vtk_xml: only poly data and image data are written");
  }
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  auto tmp = file;
  tmp += ".tmp";
  writer->SetFileName(tmp.c_str());
  writer->SetInputDataObject(data);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes, not base64
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();
  // A full disk shows in the error code, not always in Write()'s return value.
  if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError) {
    const std::string why = vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
    std::filesystem::remove(tmp);
    throw std::runtime_error("cannot write " + file.string() + " (" + why + ")");
  }
  std::filesystem::rename(tmp, file);
}

void set_time_value(vtkDataObject* data, double time) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName("TimeValue");
  array->SetNumberOfTuples(1);
  array->SetValue(0, time);
  data->GetFieldData()->AddArray(array);
}

}  // namespace sedem::render
