#include "shadowproof/core/io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "shadowproof/core/error.h"

namespace shadowproof {

std::string read_file(const std::filesystem::path& path, std::size_t max_bytes) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw error(errc::io_cannot_read, "cannot read " + path.string() + ": it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error(errc::io_cannot_read, "cannot read " + path.string() + ": " + std::strerror(errno));
  std::string content;
  // One allocation for a regular file (its size, up to the limit): appending to a growing
  // string copied a 50 MB mesh several times over.
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) content.reserve(static_cast<std::size_t>(std::min<std::uintmax_t>(size, max_bytes)) + 1);
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    content.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (content.size() > max_bytes)
      throw error(errc::io_too_large, path.string() + " is larger than the limit of " + std::to_string(max_bytes) +
                                      " bytes (raise it with --max-file-bytes)");
  }
  if (in.bad()) throw error(errc::io_cannot_read, "cannot read " + path.string() + ": read error");
  return content;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  auto fail = [&](const std::string& why) {
    throw error(errc::io_cannot_write, "cannot write " + path.string() + ": " + why);
  };
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::string temp = (dir / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) fail(std::strerror(errno));
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      ::close(fd);
      std::remove(temp.c_str());
      fail(why);
    }
    written += static_cast<std::size_t>(n);
  }
  // Make the new file readable like one created normally (mkstemp uses 0600).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temp.c_str());
    fail(why);
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temp.c_str());
    fail(why);
  }
}

}  // namespace shadowproof
