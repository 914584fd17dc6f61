// Reading an input file whole, after checking what it is: a FIFO would block the open or the
// read, /dev/zero never ends, a folder has no bytes, and a sparse file can declare gigabytes of
// zeros. Only a regular file no larger than the caller's limit is read; the check comes first,
// on the open descriptor, so nothing is allocated for what is refused.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pt {

// Reads the regular file at `path` into `bytes`. Returns "" or why not, without the path:
// "cannot open: No such file or directory", "not a regular file (a folder, device or pipe)",
// "12884901888 bytes, more than the 4294967296 it may have".
std::string readRegularFile(const std::string& path, uint64_t maxBytes, std::vector<unsigned char>& bytes);

// Why `path` names no file one can open, in words that follow "texture \"x.png\" ": "" where it
// does (stat succeeds), else "not found", "is a symbolic link to a missing file", "is a loop of
// symbolic links", "cannot be reached (Permission denied)". A loop or a dangling link is not
// reported as a missing file, which would send the user looking for the wrong thing.
std::string pathProblem(const std::string& path);

// A 64-bit hash (FNV-1a, about 1 GB/s) of a file's bytes as pt read them: the part of a render
// job's identity (render/render_job.h) that says which content the file had.
uint64_t contentHash(const void* data, size_t size);

} // namespace pt
