// What pt checks of a library before dlopen (denoise/shared_library.h): a library whole passes
// and names what it needs; cut short, not ELF, a pipe or a loop of links is refused with why.
#include "denoise/shared_library.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

namespace pt {
namespace {

namespace fs = std::filesystem;

TEST(SharedLibrary, ADamagedLibraryIsRefusedBeforeItIsLoaded) {
    const fs::path dir = fs::path(::testing::TempDir()) / "pt_shared_library";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const SharedLibraryInfo whole = inspectSharedLibrary(PT_FAKE_OIDN);
    ASSERT_EQ(whole.error, "");
    ASSERT_FALSE(whole.needed.empty()) << "a C++ library needs at least the C++ runtime";
    for (const std::string& n : whole.needed) EXPECT_EQ(n.rfind("lib", 0), 0u) << n;

    const std::string bytes = [] {
        std::ifstream in(PT_FAKE_OIDN, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    for (size_t keep : {size_t(16), size_t(100), size_t(4096), bytes.size() / 2, bytes.size() - 1}) {
        const fs::path cut = dir / ("cut" + std::to_string(keep) + ".so");
        std::ofstream(cut, std::ios::binary).write(bytes.data(), std::streamsize(keep));
        const SharedLibraryInfo info = inspectSharedLibrary(cut.string());
        // The last byte of a library is often no loaded segment's (section headers follow them):
        // without it the loader does not fail, and neither does the check.
        if (keep == bytes.size() - 1) continue;
        EXPECT_NE(info.error, "") << "cut to " << keep << " of " << bytes.size() << " bytes";
        EXPECT_EQ(info.error.find(cut.string()), 0u) << info.error;
    }
    std::ofstream(dir / "text.so") << "not a library at all, but long enough to hold an ELF header's sixty-four bytes";
    EXPECT_NE(inspectSharedLibrary((dir / "text.so").string()).error.find("is not an ELF file"), std::string::npos);
    ASSERT_EQ(mkfifo((dir / "fifo.so").c_str(), 0600), 0);
    EXPECT_NE(inspectSharedLibrary((dir / "fifo.so").string()).error.find("is not a regular file"), std::string::npos);
    fs::create_symlink("b.so", dir / "a.so");
    fs::create_symlink("a.so", dir / "b.so");
    EXPECT_NE(inspectSharedLibrary((dir / "a.so").string()).error.find("is a loop of symbolic links"), std::string::npos);
    EXPECT_NE(inspectSharedLibrary((dir / "none.so").string()).error.find("does not exist"), std::string::npos);
    EXPECT_NE(inspectSharedLibrary(dir.string()).error.find("is a folder"), std::string::npos);
}

} // namespace
} // namespace pt
