#include "io/output_file.h"

#include "io/input_file.h"

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <csignal>
#include <fcntl.h>
#include <pthread.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace pt {
namespace fs = std::filesystem;

namespace {

// Temporary files a signal handler may have to remove. Plain arrays with an atomic state per
// slot, since a handler can neither lock nor allocate: a slot is claimed, its name written, and
// only then marked ready, so a handler never unlinks a half-written or stale name.
constexpr int kSlots = 8;
enum SlotState : int { kFree, kClaimed, kReady };
char gTempNames[kSlots][PATH_MAX];
std::atomic<int> gTempState[kSlots];
std::atomic<int> gCommitted{0}; // outputs renamed into place

int registerTemp(const std::string& name) {
    if (name.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!gTempState[i].compare_exchange_strong(expected, kClaimed)) continue;
        std::memcpy(gTempNames[i], name.c_str(), name.size() + 1);
        gTempState[i].store(kReady);
        return i;
    }
    return -1;
}

void unregisterTemp(int slot) {
    if (slot >= 0) gTempState[slot].store(kFree);
}

std::string folderOf(const std::string& path) {
    fs::path dir = fs::path(path).parent_path();
    return dir.empty() ? "." : dir.string();
}

std::string errnoText() { return std::strerror(errno); }

} // namespace

int committedOutputs() { return gCommitted.load(); }

void removeTemporaryOutputs() {
    for (int i = 0; i < kSlots; ++i)
        if (gTempState[i].load() == kReady) unlink(gTempNames[i]);
}

std::string checkOutputLocation(const std::string& path) {
    std::string quoted = "output \"" + path + "\"";
    if (path.empty()) return "output: expected a file name";
    std::string dir = folderOf(path);
    struct stat st {};
    if (stat(dir.c_str(), &st) != 0) {
        std::string problem = pathProblem(dir);
        return quoted + ": folder \"" + dir + "\" " + (problem == "not found" ? "does not exist" : problem);
    }
    if (!S_ISDIR(st.st_mode)) return quoted + ": \"" + dir + "\" is not a folder";
    if (access(dir.c_str(), W_OK) != 0) return quoted + ": folder \"" + dir + "\" is not writable";
    std::string name = fs::path(path).filename().string();
    if (name.empty() || name == "." || name == "..") return quoted + ": expected a file name, not a folder";
    long longest = maxNameLength(dir);
    if (long(name.size()) > longest)
        return quoted + ": the name is longer than the file system allows (" + std::to_string(longest) + " bytes)";
    if (stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return quoted + " is a folder";
        if (!S_ISREG(st.st_mode)) return quoted + " exists and is not a regular file";
        return "";
    }
    // A dangling link, or a loop of links, is refused by name (a loop is no missing file).
    if (std::string problem = pathProblem(path); problem != "not found") return quoted + " " + problem;
    return "";
}

bool sameFile(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    if (stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    std::error_code ea, eb;
    fs::path pa = fs::weakly_canonical(fs::absolute(a, ea), ea), pb = fs::weakly_canonical(fs::absolute(b, eb), eb);
    return !ea && !eb && pa == pb;
}

long maxNameLength(const std::string& dir) {
    long n = pathconf(dir.c_str(), _PC_NAME_MAX);
    return n > 0 ? n : 255;
}

std::string outputIsInput(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
    for (size_t i = 0; i < outputs.size(); ++i) {
        for (const std::string& in : inputs)
            if (sameFile(outputs[i], in))
                return "output \"" + outputs[i] + "\" is also an input (\"" + in + "\"); choose another output name";
        for (size_t j = i + 1; j < outputs.size(); ++j)
            if (sameFile(outputs[i], outputs[j]))
                return "outputs \"" + outputs[i] + "\" and \"" + outputs[j] + "\" name the same file";
    }
    return "";
}

std::string OutputFile::open(const std::string& path) {
    discard();
    std::string problem = checkOutputLocation(path);
    if (!problem.empty()) return problem;
    path_ = path;
    target_ = path;
    struct stat lst {};
    if (lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
        std::error_code ec;
        fs::path resolved = fs::canonical(path, ec);
        if (ec) return "output \"" + path + "\": cannot follow the symbolic link: " + ec.message();
        target_ = resolved.string();
        problem = checkOutputLocation(target_);
        if (!problem.empty()) return problem + " (the target of \"" + path + "\")";
    }
    std::string dir = folderOf(target_);
    std::string name = fs::path(target_).filename().string();
    std::string pid = std::to_string(getpid());
    // ".out.exr.tmp-PID" names its target; a short name when that would be too long.
    std::string tempName = "." + name + ".tmp-" + pid;
    if (long(tempName.size()) > maxNameLength(dir)) tempName = ".pt-tmp-" + pid;
    temp_ = (fs::path(dir) / tempName).string();

    struct stat old {};
    existed_ = stat(target_.c_str(), &old) == 0;
    mode_t mode = existed_ ? (old.st_mode & 07777) : 0666;
    slot_ = registerTemp(temp_); // before the file exists, so a signal can never miss it
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0) {
        std::string why = errnoText();
        unregisterTemp(slot_);
        slot_ = -1;
        return "output \"" + path + "\": cannot create the temporary file \"" + temp_ + "\": " + why;
    }
    if (existed_ && fchmod(fd_, mode) != 0) {
        std::string why = errnoText();
        discard();
        return "output \"" + path + "\": cannot keep the file's mode: " + why;
    }
    return "";
}

std::string OutputFile::commit(const void* data, size_t size) {
    if (fd_ < 0) return "output \"" + path_ + "\" was not opened";
    auto failed = [&](const std::string& step) {
        std::string why = errnoText();
        discard();
        return "writing \"" + path_ + "\" failed (" + step + ": " + why + "); " +
               (existed_ ? "the existing file is unchanged" : "no file was left");
    };
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        ssize_t n = ::write(fd_, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = ENOSPC;
            return failed("write");
        }
        p += n;
        size -= size_t(n);
    }
    if (fsync(fd_) != 0) return failed("fsync");
    int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) return failed("close");
    // The rename and the count of committed outputs, with no signal between them: a handler
    // then says whether the output was written (committedOutputs) and never that it was not
    // after it was.
    sigset_t stop, before;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop, &before);
    const bool renamed = rename(temp_.c_str(), target_.c_str()) == 0;
    const int renameErrno = errno;
    if (renamed) {
        gCommitted.fetch_add(1);
        unregisterTemp(slot_);
        slot_ = -1;
        temp_.clear();
    }
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    errno = renameErrno;
    if (!renamed) return failed("rename");
    return "";
}

void OutputFile::discard() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temp_.empty()) unlink(temp_.c_str());
    temp_.clear();
    unregisterTemp(slot_);
    slot_ = -1;
}

OutputFile::~OutputFile() { discard(); }

std::string writeWholeFile(const std::string& path, const std::string& bytes) {
    OutputFile file;
    std::string error = file.open(path);
    return error.empty() ? file.commit(bytes.data(), bytes.size()) : error;
}

} // namespace pt
