#include "scenarios/run/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "scenarios/scene/scene_reader.hpp"

namespace carom {

OutputLock::OutputLock(const std::filesystem::path& dir, const std::string& what) {
  const std::string path = (dir / kLockFile).string();
  // O_CLOEXEC: a process started by the run (none today) must not inherit the lock.
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0)
    throw SceneError(dir.string() + ": cannot open its lock file " + kLockFile + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    char holder[32] = {0};
    const ssize_t got = ::pread(fd_, holder, sizeof holder - 1, 0);
    ::close(fd_);
    fd_ = -1;
    std::string pid = got > 0 ? std::string(holder, static_cast<std::size_t>(got)) : std::string("?");
    while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
    if (error == EWOULDBLOCK)
      throw SceneError(dir.string() + " is in use by another carom process (process id " + pid + ", lock file " +
                       kLockFile + "): " + what + " would write into the folder of a run still running; wait for it "
                       "to end, stop it, or choose another --out");
    throw SceneError(dir.string() + ": cannot lock " + kLockFile + ": " + std::strerror(error));
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) {
    const ssize_t written = ::pwrite(fd_, pid.data(), pid.size(), 0);
    (void)written;  // the process id is only for the message of a refused run
  }
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace carom
