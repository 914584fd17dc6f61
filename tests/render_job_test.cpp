// A render job's identity: the scene's content as pt read it. The hash comes from the bytes each
// loader read, so a file renamed over after loading (a user replacing an environment map while
// a Slurm array runs) cannot give a part the identity of content it did not use, and the same
// content gives the same identity wherever its files lie.
#include "render/render_job.h"
#include "load/scene_loader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace pt::test {
namespace {

namespace fs = std::filesystem;

// A scene in `dir` lit by an MTL environment map copied from `map`, with a texture.
void writeScene(const fs::path& dir, const std::string& map) {
    fs::create_directories(dir);
    fs::copy_file(PT_SOURCE_DIR "/scenes/" + map, dir / "env.exr", fs::copy_options::overwrite_existing);
    fs::copy_file(PT_SOURCE_DIR "/scenes/checker.png", dir / "checker.png", fs::copy_options::overwrite_existing);
    std::ofstream(dir / "scene.mtl") << "newmtl M\nmap_Kd checker.png\nnewenvironment E\nenvmap env.exr\n";
    std::ofstream(dir / "scene.obj") << "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                        "usemtl M\nf 1/1 2/2 3/3\n";
}

std::string loadedHash(const fs::path& dir, Scene* out = nullptr) {
    Warnings w;
    Scene s = loadScene((dir / "scene.obj").string(), w);
    std::string hash = jobHash(s.sources);
    if (out) *out = std::move(s);
    return hash;
}

TEST(JobIdentity, IsTheContentPtReadNotWhatThePathHoldsLater) {
    fs::path root = fs::temp_directory_path() / ("pt_job_" + std::to_string(::getpid()));
    writeScene(root / "a", "env_marker.exr");
    writeScene(root / "b", "env_sun.exr");
    Scene loaded;
    std::string marker = loadedHash(root / "a", &loaded);
    ASSERT_EQ(loaded.sources.size(), 4u) << "the OBJ, the MTL, the texture and the map";
    // Replace the map under the loaded scene, as `mv` would: the scene's identity is unchanged...
    fs::rename(root / "b" / "env.exr", root / "a" / "env.exr");
    EXPECT_EQ(jobHash(loaded.sources), marker);
    // ...while loading again sees the new content.
    EXPECT_NE(loadedHash(root / "a"), marker);
    // The same content elsewhere is the same job.
    writeScene(root / "c", "env_marker.exr");
    EXPECT_EQ(loadedHash(root / "c"), marker);
    fs::remove_all(root);
}

// Every identity field, differing alone between two parts, is the one a merge names; a field
// that only describes the job differs without splitting it.
TEST(JobIdentity, EachIdentityFieldDifferingIsNamed) {
    auto job = [](const char* changed) {
        Image image;
        JobMetadataWriter writer(image);
        for (size_t i = 0; i < kJobFieldCount; ++i)
            writer.text(kJobFields[i].name, std::strcmp(kJobFields[i].name, changed) == 0 ? "b" : "a");
        return image;
    };
    Image base = job("");
    size_t identities = 0;
    for (size_t i = 0; i < kJobFieldCount; ++i) {
        std::string field, a, b;
        bool differs = jobMismatch(base, job(kJobFields[i].name), field, a, b);
        if (kJobFields[i].role == JobFieldRole::Identity) {
            ++identities;
            EXPECT_TRUE(differs) << kJobFields[i].name;
            EXPECT_EQ(field, kJobFields[i].name);
            EXPECT_EQ(a + b, "ab");
        } else {
            EXPECT_FALSE(differs) << kJobFields[i].name << " only describes the job, yet " << field << " differed";
        }
    }
    EXPECT_EQ(identities, jobFields().size());
    EXPECT_GE(identities, 20u);
}

TEST(JobIdentity, AFieldNotInTheTableCannotBeWritten) {
    Image image;
    JobMetadataWriter writer(image);
    EXPECT_THROW(writer.real("pt:newSetting", 1.0), std::logic_error);
    EXPECT_TRUE(image.metadata.empty());
    writer.integer("pt:seed", 7);
    ASSERT_EQ(image.metadata.size(), 1u);
    EXPECT_EQ(attributeText(image, "pt:seed"), "7");
}

} // namespace
} // namespace pt::test
