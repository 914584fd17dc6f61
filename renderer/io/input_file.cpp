#include "io/input_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pt {

std::string pathProblem(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) return "";
    const int error = errno;
    if (error == ELOOP) return "is a loop of symbolic links";
    if (error == ENOENT || error == ENOTDIR) {
        struct stat link {};
        if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) return "is a symbolic link to a missing file";
        return "not found";
    }
    return std::string("cannot be reached (") + std::strerror(error) + ")";
}

std::string readRegularFile(const std::string& path, uint64_t maxBytes, std::vector<unsigned char>& bytes) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
    int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return std::string("cannot open: ") + std::strerror(errno);
    struct stat st {};
    std::string error;
    if (fstat(fd, &st) != 0) error = std::string("cannot read: ") + std::strerror(errno);
    else if (!S_ISREG(st.st_mode)) error = "not a regular file (a folder, device or pipe)";
    else if (uint64_t(st.st_size) > maxBytes)
        error = std::to_string(st.st_size) + " bytes, more than the " + std::to_string(maxBytes) + " it may have";
    if (error.empty()) {
        try {
            bytes.resize(size_t(st.st_size));
        } catch (const std::bad_alloc&) {
            error = "out of memory for its " + std::to_string(st.st_size) + " bytes";
        }
    }
    for (size_t done = 0; error.empty() && done < bytes.size();) {
        ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) error = n == 0 ? "the file became shorter while it was read" : std::string("cannot read: ") + std::strerror(errno);
        else done += size_t(n);
    }
    ::close(fd);
    if (!error.empty()) bytes.clear();
    return error;
}

uint64_t contentHash(const void* data, size_t size) {
    uint64_t h = 0xcbf29ce484222325ULL;
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
    return h;
}

} // namespace pt
