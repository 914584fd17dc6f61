#include "denoise/shared_library.h"

#include <elf.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace pt {
namespace {

#if defined(__x86_64__)
constexpr uint16_t kMachine = EM_X86_64;
constexpr const char* kMachineName = "x86-64";
#elif defined(__aarch64__)
constexpr uint16_t kMachine = EM_AARCH64;
constexpr const char* kMachineName = "AArch64";
#else
#error "shared_library.cpp: name this machine's ELF e_machine"
#endif

// An open file descriptor, closed on every path out.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) close(fd);
    }
};

// Whether [offset, offset + size) lies inside a file of `fileSize` bytes, without overflow.
bool inside(uint64_t offset, uint64_t size, uint64_t fileSize) { return offset <= fileSize && size <= fileSize - offset; }

bool readAt(int fd, void* out, size_t size, uint64_t offset) {
    auto* p = static_cast<char*>(out);
    while (size > 0) {
        const ssize_t got = pread(fd, p, size, off_t(offset));
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        p += got, size -= size_t(got), offset += uint64_t(got);
    }
    return true;
}

} // namespace

SharedLibraryInfo inspectSharedLibrary(const std::string& path) {
    SharedLibraryInfo info;
    auto fail = [&](const std::string& why) {
        info.error = path + " " + why;
        info.needed.clear();
        return info;
    };
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) {
        if (errno == ELOOP) return fail("is a loop of symbolic links");
        if (errno == ENOENT) return fail("does not exist");
        return fail(std::string("cannot be read: ") + std::strerror(errno));
    }
    if (!S_ISREG(st.st_mode)) return fail(S_ISDIR(st.st_mode) ? "is a folder, not a library" : "is not a regular file (a pipe or device?)");
    Fd file{open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
    if (file.fd < 0) return fail(std::string("cannot be opened: ") + std::strerror(errno));
    if (fstat(file.fd, &st) != 0 || !S_ISREG(st.st_mode)) return fail("is not a regular file");
    const uint64_t size = uint64_t(st.st_size);

    Elf64_Ehdr eh{};
    if (size < sizeof eh || !readAt(file.fd, &eh, sizeof eh, 0))
        return fail("is too short (" + std::to_string(size) + " bytes) to be a shared library");
    if (std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0) return fail("is not an ELF file");
    if (eh.e_ident[EI_CLASS] != ELFCLASS64 || eh.e_ident[EI_DATA] != ELFDATA2LSB || eh.e_machine != kMachine)
        return fail(std::string("is not a 64-bit ") + kMachineName + " library");
    if (eh.e_type != ET_DYN) return fail("is an ELF file but not a shared library");
    if (eh.e_phentsize != sizeof(Elf64_Phdr) || eh.e_phnum == 0 ||
        !inside(eh.e_phoff, uint64_t(eh.e_phnum) * sizeof(Elf64_Phdr), size))
        return fail("is damaged: its program headers lie outside its " + std::to_string(size) + " bytes");
    std::vector<Elf64_Phdr> ph(eh.e_phnum);
    if (!readAt(file.fd, ph.data(), ph.size() * sizeof(Elf64_Phdr), eh.e_phoff)) return fail("cannot be read");

    const Elf64_Phdr* dynamic = nullptr;
    for (const Elf64_Phdr& p : ph) {
        if (p.p_type != PT_LOAD && p.p_type != PT_DYNAMIC) continue;
        if (!inside(p.p_offset, p.p_filesz, size))
            return fail("is damaged (cut short?): a segment it loads ends at byte " + std::to_string(p.p_offset + p.p_filesz) +
                        " of a file of " + std::to_string(size) + " bytes");
        if (p.p_type == PT_DYNAMIC) dynamic = &p;
    }
    if (!dynamic) return info; // nothing it needs

    // The names of the libraries it needs: DT_NEEDED offsets into the string table DT_STRTAB,
    // which is given as a virtual address, found in the file through the loaded segments.
    std::vector<Elf64_Dyn> dyn(dynamic->p_filesz / sizeof(Elf64_Dyn));
    if (!readAt(file.fd, dyn.data(), dyn.size() * sizeof(Elf64_Dyn), dynamic->p_offset)) return fail("cannot be read");
    uint64_t strtab = 0, strsz = 0;
    std::vector<uint64_t> neededAt;
    for (const Elf64_Dyn& d : dyn) {
        if (d.d_tag == DT_NULL) break;
        if (d.d_tag == DT_STRTAB) strtab = d.d_un.d_ptr;
        if (d.d_tag == DT_STRSZ) strsz = d.d_un.d_val;
        if (d.d_tag == DT_NEEDED) neededAt.push_back(d.d_un.d_val);
    }
    if (neededAt.empty()) return info;
    uint64_t strOffset = 0;
    bool found = false;
    for (const Elf64_Phdr& p : ph)
        if (p.p_type == PT_LOAD && strtab >= p.p_vaddr && strtab - p.p_vaddr < p.p_filesz) {
            strOffset = strtab - p.p_vaddr + p.p_offset;
            found = strsz <= p.p_filesz - (strtab - p.p_vaddr);
            break;
        }
    if (!found || strsz > (uint64_t(1) << 24)) return fail("is damaged: its table of needed libraries lies outside it");
    std::string strings(strsz, '\0');
    if (!readAt(file.fd, strings.data(), strsz, strOffset)) return fail("cannot be read");
    for (uint64_t at : neededAt) {
        if (at >= strsz) return fail("is damaged: a needed library's name lies outside its string table");
        info.needed.emplace_back(strings.c_str() + at, strnlen(strings.c_str() + at, strsz - at));
    }
    return info;
}

} // namespace pt
