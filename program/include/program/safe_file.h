// The one way every program of the project writes a file (figures, difference images,
// the report page), so that nothing the user had is lost, whatever goes wrong:
//
//   - a destination that exists and is not a regular file (a device node, a FIFO, a
//     folder, a symbolic link) is refused, and left as it is;
//   - the bytes go to a new temporary file beside the destination, with a name of its
//     own, created exclusively and never through a symbolic link;
//   - they are flushed to the disk (fsync), then the temporary is renamed over the
//     destination: the destination is the old file or the complete new one, never a
//     part of either;
//   - on any failure, and on SIGINT or SIGTERM while the file is being written, the
//     temporary is removed.
//
// Two programs writing the same destination at once each write a complete file of
// their own; the last rename wins.
#pragma once

#include <filesystem>
#include <string_view>

namespace cgfs {

// Writes `bytes` to `path` as above. Throws cgfs::Error: for a destination that is not
// a regular file, or with the system's reason for any other failure.
void WriteFileSafely(const std::filesystem::path& path, std::string_view bytes);

// Creates `path` for writing, exclusively: fails (EEXIST) if anything is there, a
// symbolic link or a FIFO included, without following or opening it. Returns the file
// descriptor, or -1 with errno set. The temporaries of WriteFileSafely are made so.
int CreateExclusively(const std::filesystem::path& path);

}  // namespace cgfs
