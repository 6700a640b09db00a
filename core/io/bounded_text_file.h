#pragma once

#include <cstddef>
#include <string>

namespace topay {

/// Size limits of the files the loaders read (bytes). A file above its limit is an error, not
/// an allocation of all memory (e.g. `--scene-file /dev/zero`).
/// URDF, robot YAML and planner YAML: hand-written descriptions of a few kB (the shipped
/// topay_mm.urdf is 9 kB).
inline constexpr std::size_t kMaxConfigFileBytes = std::size_t{16} << 20;  // 16 MiB

/// Reads a whole text file of at most max_bytes. `what` names the kind of file in errors
/// ("robot URDF", "scene JSON"). Throws ConfigError(path, "", ...) if the path does not exist or
/// cannot be opened or read, is a directory (an empty read would pass for an empty file), holds
/// more than max_bytes (a regular file is rejected by its size before reading; a pipe or
/// device is read up to max_bytes + 1), or contains a NUL byte (not text: /dev/zero fails at
/// its first block). Regular files, pipes and character devices are read; other kinds (a
/// socket, a block device) are rejected.
std::string ReadBoundedTextFile(const std::string& path, std::size_t max_bytes,
                                const std::string& what);

}  // namespace topay
