#pragma once

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace sedem::app {

// Writes `file` through a temporary file renamed into place: a reader never sees half a
// file, and a failed write leaves no temporary file and names the system's reason.
template <class Write>
void write_atomically(const std::filesystem::path& file, Write&& write) {
  auto tmp = file;
  tmp += ".tmp";
  {
    std::ofstream out(tmp);
    write(out);
    out.flush();
    if (!out) {
      const int e = errno;
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string() + ": " +
                               (e ? std::strerror(e) : "write error"));
    }
  }
  std::filesystem::rename(tmp, file);
}

}  // namespace sedem::app
