// An output file that appears whole or not at all. The temporary file beside the target is
// created first (so an unwritable folder or a name too long fails before any rendering), the
// bytes go in with every write, fsync and close checked, and one rename puts them in place. A
// failure at any step removes the temporary file and leaves an existing target as it was.
//
// Targets that exist keep their permission bits; new files get 0666 less the umask, as any
// program's output. A symbolic link is written through: the file it points to is replaced and
// the link stays. A link to a missing file is refused.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pt {

class OutputFile {
public:
    OutputFile() = default;
    ~OutputFile(); // removes the temporary file unless commit() succeeded
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    // Creates the temporary file for `path`. Returns "" or why the output cannot be written.
    std::string open(const std::string& path);
    // Writes `size` bytes, syncs them and renames the file over the target. Returns "" or the
    // error, in which case the temporary file is gone and the target unchanged.
    std::string commit(const void* data, size_t size);

    bool isOpen() const { return fd_ >= 0; }
    const std::string& path() const { return path_; }     // as the user gave it
    const std::string& target() const { return target_; } // after following a symbolic link
    const std::string& temporary() const { return temp_; }

private:
    void discard();

    std::string path_, target_, temp_;
    int fd_ = -1;
    bool existed_ = false; // the target existed when opened
    int slot_ = -1; // in the registry of temporary files a second signal removes
};

// open() and commit() in one step, for outputs that need no early check. Returns "" or the error.
std::string writeWholeFile(const std::string& path, const std::string& bytes);

// Checks that `path` could be an output without creating anything: its folder exists and is
// writable, it is not a folder, and its name fits the file system. Returns "" or the reason.
std::string checkOutputLocation(const std::string& path);

// True when `a` and `b` name the same file: the same inode if both exist, else the same
// absolute path once symbolic links are followed.
bool sameFile(const std::string& a, const std::string& b);

// "" when no output is the same file as an input (or as another output), else the message that
// refuses it: writing it would destroy what the command reads.
std::string outputIsInput(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

// The longest file name the file system of folder `dir` takes (NAME_MAX, 255 if it does not say).
long maxNameLength(const std::string& dir);

// For a signal handler: unlinks every temporary output file still open. Async-signal-safe.
void removeTemporaryOutputs();
// For a signal handler: how many outputs this process has put in place. Async-signal-safe.
int committedOutputs();

} // namespace pt
