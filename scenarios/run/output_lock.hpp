#pragma once
/// One run per output folder: a run, a resume and a sweep hold an exclusive flock(2) on the file
/// .carom.lock in their folder for as long as they write there. The kernel releases it on any
/// exit (a crash and kill -9 included), so a lock left by a process that is gone is stale and
/// taken over at once; the file itself stays (it holds the last holder's process id, for the
/// message).
#include <filesystem>
#include <string>

namespace carom {

/// Name of the lock file in an output folder.
inline constexpr const char* kLockFile = ".carom.lock";

class OutputLock {
 public:
  /// Takes the lock of folder `dir` (which must exist). Throws SceneError (exit 2) naming the
  /// folder and the holder's process id when another process holds it, and `what` (e.g.
  /// "carom run") says who asked.
  OutputLock(const std::filesystem::path& dir, const std::string& what);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace carom
