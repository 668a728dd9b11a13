#include "app/lab_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "app/xlsx_reader.h"

namespace sedem::app {

namespace {

// The largest laboratory file read: a laboratory's CSV is a few kilobytes, a workbook tens.
constexpr std::uintmax_t kMaxLabFileBytes = 16u << 20;

}  // namespace

bool is_xlsx(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return ext == ".xlsx";
}

LabTable read_lab_file(const std::string& path, const std::string& sheet) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(status) &&
      (!std::filesystem::is_regular_file(status) ||
       std::filesystem::file_size(path, ec) > kMaxLabFileBytes))
    throw std::invalid_argument("not a readings file (a folder, a device or over 16 MB)");
  if (is_xlsx(path)) {
    if (!std::filesystem::exists(status))
      throw std::invalid_argument("cannot open the workbook: " +
                                  std::string(std::strerror(ENOENT)));
    return read_xlsx_table(path, sheet);
  }
  if (!sheet.empty())
    throw std::invalid_argument("--sheet names a sheet of an .xlsx workbook; this is a text file");
  std::ifstream in(path);
  if (!in)
    throw std::invalid_argument("cannot open the readings file: " +
                                std::string(std::strerror(errno)));
  return read_lab_text(in);
}

}  // namespace sedem::app
