#include "program/safe_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <random>
#include <string>

#include "program/error.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void Fail(const fs::path& path, int error) {
  throw Error("cannot write " + Quoted(path) + ": " + std::strerror(error));
}

// The temporary being written, for the signal handler to remove: a fixed buffer and a
// flag, since a handler may only use what is async-signal-safe (unlink, raise).
constexpr std::size_t kMaxPendingPath = 4096;
char pending_path[kMaxPendingPath];
volatile std::sig_atomic_t has_pending = 0;

extern "C" void RemovePendingTemporaryAndStop(int signal_number) {
  if (has_pending) {
    ::unlink(pending_path);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// SIGINT and SIGTERM remove the pending temporary, then stop the program as they
// would have; installed once, and only where the program has no handler of its own.
void InstallSignalHandlersOnce() {
  static const bool installed = [] {
    for (const int signal_number : {SIGINT, SIGTERM}) {
      struct sigaction current {};
      if (sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_DFL) {
        struct sigaction action {};
        action.sa_handler = RemovePendingTemporaryAndStop;
        sigemptyset(&action.sa_mask);
        sigaction(signal_number, &action, nullptr);
      }
    }
    return true;
  }();
  (void)installed;
}

// While it lives, the temporary is the one the signal handler removes.
class PendingTemporary {
 public:
  explicit PendingTemporary(const fs::path& path) {
    const std::string text = path.string();
    if (text.size() < kMaxPendingPath) {
      Blocked blocked;
      std::memcpy(pending_path, text.c_str(), text.size() + 1);
      has_pending = 1;
    }
  }
  ~PendingTemporary() {
    Blocked blocked;
    has_pending = 0;
  }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

 private:
  // SIGINT and SIGTERM held back while the buffer changes.
  struct Blocked {
    Blocked() {
      sigset_t signals;
      sigemptyset(&signals);
      sigaddset(&signals, SIGINT);
      sigaddset(&signals, SIGTERM);
      pthread_sigmask(SIG_BLOCK, &signals, &saved);
    }
    ~Blocked() { pthread_sigmask(SIG_SETMASK, &saved, nullptr); }
    sigset_t saved;
  };
};

// Throws unless `path` is free or a regular file (not followed if a symbolic link).
void RefuseAnythingButARegularFile(const fs::path& path) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) {
    if (errno == ENOENT) {
      return;
    }
    Fail(path, errno);
  }
  if (S_ISREG(status.st_mode)) {
    return;
  }
  const char* what = S_ISDIR(status.st_mode)                              ? "a folder"
                     : S_ISLNK(status.st_mode)                            ? "a symbolic link"
                     : S_ISFIFO(status.st_mode)                           ? "a FIFO"
                     : S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode) ? "a device"
                                                                          : "not a regular file";
  throw Error("will not write " + Quoted(path) + ": it is " + what +
              ", not a regular file; nothing was written");
}

// A name for a temporary beside `path` that no other program is likely to pick.
fs::path TemporaryName(const fs::path& path) {
  static std::mt19937_64 random = [] {
    std::random_device device;
    return std::mt19937_64((static_cast<std::uint64_t>(device()) << 32) ^ device() ^
                           static_cast<std::uint64_t>(::getpid()));
  }();
  char suffix[17];
  std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(random()));
  std::string file(1, '.');  // appended, not "." + string: GCC 12's -Wrestrict (bug 105329)
  file += path.filename().string();
  file += '.';
  file += suffix;
  file += ".partial";
  return path.parent_path() / file;
}

// Writes every byte, flushes them to the disk and closes the file: 0, or the errno of
// the first step that failed.
int WriteSyncAndClose(int fd, std::string_view bytes) {
  int error = 0;
  while (!bytes.empty() && error == 0) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written >= 0) {
      bytes.remove_prefix(static_cast<std::size_t>(written));
    } else if (errno != EINTR) {
      error = errno;
    }
  }
  if (error == 0 && ::fsync(fd) != 0) {
    error = errno;
  }
  if (::close(fd) != 0 && error == 0) {
    error = errno;
  }
  return error;
}
// The folder's entry for the new file on the disk too (a failure here loses nothing).
void SyncFolder(const fs::path& path) {
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

int CreateExclusively(const fs::path& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
}

void WriteFileSafely(const fs::path& path, std::string_view bytes) {
  RefuseAnythingButARegularFile(path);
  InstallSignalHandlersOnce();
  fs::path temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary = TemporaryName(path);
    fd = CreateExclusively(temporary);
    if (fd < 0 && errno != EEXIST) {
      Fail(path, errno);
    }
  }
  if (fd < 0) {
    Fail(path, EEXIST);
  }
  PendingTemporary pending(temporary);
  int error = WriteSyncAndClose(fd, bytes);
  if (error == 0) {
    try {
      RefuseAnythingButARegularFile(path);  // nothing else took its place meanwhile
    } catch (...) {
      ::unlink(temporary.c_str());
      throw;
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
      error = errno;
    }
  }
  if (error != 0) {
    ::unlink(temporary.c_str());
    Fail(path, error);
  }
  SyncFolder(path);
}

}  // namespace cgfs
