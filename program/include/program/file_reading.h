// Reading a whole input file, whatever the user points at.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace cgfs {

// The bytes of a regular file (after symbolic links) of at most `max_bytes`: never a
// FIFO that blocks, a device without end such as /dev/zero, a folder or a
// symbolic-link loop. The size the file system states is only a hint (files in /proc
// state 0): the file is read to its end, and refused once past the limit. Throws
// cgfs::Error with one line.
std::string ReadWholeFile(const std::filesystem::path& path, std::uintmax_t max_bytes);

}  // namespace cgfs
