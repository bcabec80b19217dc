// Writing generated files: atomically, and only when the bytes change.
#pragma once

#include <string>

namespace offsetgen {

// Writes `content` to `path` through a temporary file in the same directory and a rename, so a
// reader never sees half a file. Leaves the file (and its timestamp) alone when it already holds
// exactly `content`, so build systems do not rebuild dependants for nothing.
// Returns true when the file was written. Throws std::runtime_error naming the path on failure.
bool write_file_if_changed(const std::string& path, const std::string& content);

// The same without the comparison (for large outputs such as meshes, where reading the old file back
// would cost as much as writing): always replaces the file, atomically.
void write_file_atomically(const std::string& path, const std::string& content);

// Throws std::runtime_error if `path` could not be written (missing or read-only directory), without
// creating anything. Lets a multi-file run fail before it writes its first file.
void require_writable(const std::string& path);

}  // namespace offsetgen
