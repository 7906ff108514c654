#include "scenarios/scene/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "scenarios/scene/scene_reader.hpp"

namespace carom {

namespace {

/// What a non-regular file is, in words.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string bytes_text(std::size_t bytes) { return std::to_string(bytes) + " bytes"; }

}  // namespace

void require_regular_file(const std::string& path, const std::string& context) {
  struct stat info {};
  // stat, not open: opening a FIFO without a writer would block.
  if (::stat(path.c_str(), &info) != 0)
    throw SceneError(context + ": " + path + ": " +
                     (errno == ENOENT ? std::string("no such file") : std::string(std::strerror(errno))));
  if (!S_ISREG(info.st_mode))
    throw SceneError(context + ": " + path + " is " + kind_of(info.st_mode) + ", not a regular file");
}

std::string read_regular_file(const std::string& path, const std::string& context, std::size_t max_bytes) {
  require_regular_file(path, context);
  // O_NONBLOCK: should the path have become a FIFO since the check, the open does not block.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw SceneError(context + ": " + path + ": cannot open: " + std::strerror(errno));
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    throw SceneError(context + ": " + path + " is " + kind_of(info.st_mode) + ", not a regular file");
  }
  const auto size = static_cast<std::size_t>(info.st_size);
  if (size > max_bytes) {
    ::close(fd);
    throw SceneError(context + ": " + path + " holds " + bytes_text(size) + ", more than the " + bytes_text(max_bytes) +
                     " such a file may have");
  }
  std::string bytes(size, '\0');
  std::size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(fd, bytes.data() + got, size - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  if (got != size) throw SceneError(context + ": " + path + ": could not be read whole (" + bytes_text(got) + " of " +
                                    bytes_text(size) + ")");
  return bytes;
}

std::string without_bom(std::string text) {
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
      static_cast<unsigned char>(text[2]) == 0xBF)
    text.erase(0, 3);
  return text;
}

std::string shorten_long_tokens(const std::string& message, std::size_t longest) {
  std::string out;
  std::size_t start = 0;
  while (start < message.size()) {
    std::size_t end = start;
    while (end < message.size() && message[end] != ' ' && message[end] != '\n') ++end;
    const std::size_t length = end - start;
    if (length > longest)
      out.append(message, start, 40).append("...(" + std::to_string(length) + " characters)");
    else
      out.append(message, start, length);
    if (end < message.size()) out += message[end];
    start = end + 1;
  }
  return out;
}

}  // namespace carom
