#pragma once

#include <filesystem>

#include <vtkDataObject.h>

namespace sedem::render {

// Writes VTK XML (.vtp for poly data, .vti for image data) the way every sedem series is
// written: appended raw binary, zlib-compressed, 64-bit headers; to a temporary file that is
// renamed into place, so a reader never sees half a file. Throws std::runtime_error.
void write_vtk_xml(vtkDataObject* data, const std::filesystem::path& file);

// Adds the TimeValue field data (one value) that ParaView reads as the data set's time.
void set_time_value(vtkDataObject* data, double time);

}  // namespace sedem::render
