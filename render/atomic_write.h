#pragma once

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace sedem {

// An output that could not be written (disk full, a read-only folder, ...): the commands'
// exit status 4. Names the file and the system's reason.
struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What makes `file` unfit as an output, empty when nothing does: it must be a new path or a
// regular file. Renaming over a folder, a link, a pipe or a device (as root: /dev/full) would
// replace it or hang.
inline std::string unfit_output_file(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::symlink_status(file, ec);
  if (ec || !fs::exists(st) || fs::is_regular_file(st)) return "";
  const char* what = fs::is_directory(st)                                 ? "a folder"
                     : fs::is_symlink(st)                                 ? "a symbolic link"
                     : fs::is_fifo(st)                                    ? "a pipe"
                     : fs::is_socket(st)                                  ? "a socket"
                     : fs::is_block_file(st) || fs::is_character_file(st) ? "a device"
                                                                          : "not a file";
  return file.string() + " is " + what + "; an output must be a regular file or a new path";
}

// Writes `file` through a temporary file renamed into place: a reader never sees half a
// file, and a failed write or close leaves no temporary file and throws WriteError naming the
// system's reason.
template <class Write>
void write_atomically(const std::filesystem::path& file, Write&& write) {
  auto tmp = file;
  tmp += ".tmp";
  const auto fail = [&](int e) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw WriteError("cannot write " + file.string() + ": " +
                     (e ? std::strerror(e) : "write error"));
  };
  if (!unfit_output_file(tmp).empty()) fail(EEXIST);
  {
    errno = 0;
    std::ofstream out(tmp, std::ios::binary);
    if (!out) fail(errno);
    write(out);
    out.flush();
    const int written = out ? 0 : (errno ? errno : EIO);
    out.close();  // a failed close (a full disk on NFS, a quota) sets failbit too
    if (written || !out) fail(written ? written : (errno ? errno : EIO));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) fail(ec.value());
}

}  // namespace sedem
