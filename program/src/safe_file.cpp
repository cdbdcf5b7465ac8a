#include "program/safe_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <optional>
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

// The signals that stop a program while it writes: interrupted (Ctrl-C), terminated, or
// its terminal closed.
constexpr int kStoppingSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Those signals remove the pending temporary, then stop the program as they would have;
// installed once, and only where the program has no handler of its own.
void InstallSignalHandlersOnce() {
  static const bool installed = [] {
    for (const int signal_number : kStoppingSignals) {
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

// The temporary the signal handler removes while this lives. Made with the signals held
// back, so that no signal can come between the file's creation and its registration.
class PendingTemporary {
 public:
  // Creates `path` exclusively (CreateExclusively); fd() is -1 with errno set if it could
  // not be created.
  explicit PendingTemporary(const fs::path& path) {
    Blocked blocked;
    fd_ = CreateExclusively(path);
    const std::string text = path.string();
    if (fd_ >= 0 && text.size() < kMaxPendingPath) {
      std::memcpy(pending_path, text.c_str(), text.size() + 1);
      has_pending = 1;
    }
  }
  int fd() const { return fd_; }
  ~PendingTemporary() {
    Blocked blocked;
    has_pending = 0;
  }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

 private:
  // The stopping signals held back while the file and the buffer change.
  struct Blocked {
    Blocked() {
      sigset_t signals;
      sigemptyset(&signals);
      for (const int signal_number : kStoppingSignals) {
        sigaddset(&signals, signal_number);
      }
      pthread_sigmask(SIG_BLOCK, &signals, &saved);
    }
    ~Blocked() { pthread_sigmask(SIG_SETMASK, &saved, nullptr); }
    sigset_t saved;
  };
  int fd_ = -1;
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

// A name for a temporary beside `path` that no other program is likely to pick:
// `.<name>.<16 hex digits>.partial`, the name cut to 200 bytes so that the whole fits
// the 255 bytes a file name may have.
fs::path TemporaryName(const fs::path& path) {
  static std::mt19937_64 random = [] {
    std::random_device device;
    return std::mt19937_64((static_cast<std::uint64_t>(device()) << 32) ^ device() ^
                           static_cast<std::uint64_t>(::getpid()));
  }();
  char suffix[17];
  std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(random()));
  std::string file(1, '.');  // appended, not "." + string: GCC 12's -Wrestrict (bug 105329)
  file += path.filename().string().substr(0, 200);
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
  std::optional<PendingTemporary> pending;
  for (int attempt = 0; attempt < 100 && (!pending || pending->fd() < 0); ++attempt) {
    temporary = TemporaryName(path);
    pending.emplace(temporary);
    if (pending->fd() < 0 && errno != EEXIST) {
      Fail(path, errno);
    }
  }
  if (pending->fd() < 0) {
    Fail(path, EEXIST);
  }
  int error = WriteSyncAndClose(pending->fd(), bytes);
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
