#include "obj/obj_loader.h"
#include "load/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace pt {
namespace {

namespace fs = std::filesystem;

// A folder of its own per test for OBJ/MTL files.
class ObjFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(::testing::TempDir()) / ("pt_obj_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return (dir_ / name).string();
    }
    Scene load(const std::string& obj, const std::string& mtl = "") {
        if (!mtl.empty()) write("m.mtl", mtl);
        return loadObj(write("s.obj", obj), warnings_);
    }
    std::string errorOf(const std::string& obj, const std::string& mtl = "") {
        try {
            load(obj, mtl);
        } catch (const LoadError& e) {
            return e.what();
        }
        return "(no error)";
    }
    fs::path dir_;
    Warnings warnings_;
};

const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST_F(ObjFiles, VertexFormsAndFanTriangulation) {
    Scene s = load(std::string(kQuad) +
                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                   "f 1 2 3 4\n"          // v: quad -> 2 triangles
                   "f 1/1 2/2 3/3\n"      // v/vt
                   "f 1//1 2//1 3//1\n"   // v//vn
                   "f 1/1/1 2/2/1 3/3/1\n" // v/vt/vn
                   "f -4 -3 -2 -1\n");    // negative: relative to the end
    ASSERT_EQ(s.triangleCount(), 2u + 1 + 1 + 1 + 2);
    EXPECT_EQ(s.triPositions[0], glm::uvec3(0, 1, 2));
    EXPECT_EQ(s.triPositions[1], glm::uvec3(0, 2, 3)); // fan around the first corner
    EXPECT_EQ(s.triPositions[5], glm::uvec3(0, 1, 2));
    ASSERT_EQ(s.triNormals.size(), s.triangleCount());
    ASSERT_EQ(s.triUvs.size(), s.triangleCount());
    EXPECT_EQ(s.triNormals[0], glm::ivec3(-1)); // faces without normals use the geometric one
    EXPECT_EQ(s.triNormals[3], glm::ivec3(0));
    EXPECT_EQ(s.triUvs[2], glm::ivec3(0, 1, 2));
    EXPECT_EQ(s.triUvs[3], glm::ivec3(-1));
    EXPECT_EQ(s.triNormals[4], glm::ivec3(0));
    EXPECT_EQ(s.triUvs[4], glm::ivec3(0, 1, 2));
}

TEST_F(ObjFiles, FacesWithoutMaterialGetTheDefault) {
    Scene s = load(std::string(kQuad) + "f 1 2 3\n");
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].kd, Spectrum(0.7f));
    EXPECT_EQ(s.triMaterial[0], 0u);
}

TEST_F(ObjFiles, UsemtlPicksMaterialsFromMtllib) {
    Scene s = load(std::string("mtllib m.mtl\n") + kQuad + "usemtl B\nf 1 2 3\nusemtl A\nf 1 3 4\n",
                   "newmtl A\nKd 1 0 0\nnewmtl B\nKd 0 1 0\n");
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_EQ(s.materials[s.triMaterial[0]].name, "B");
    EXPECT_EQ(s.materials[s.triMaterial[1]].name, "A");
}

TEST_F(ObjFiles, WindowsLineEndingsLoad) {
    Scene s = load("mtllib m.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nusemtl A\r\nf 1 2 3\r\n",
                   "newmtl A\r\nKd 0.5 0.25 1\r\n");
    ASSERT_EQ(s.triangleCount(), 1u);
    EXPECT_EQ(s.materials[0].kd, Spectrum(0.5f, 0.25f, 1.0f));
}

TEST_F(ObjFiles, MalformedLinesReportFileAndLine) {
    struct Case {
        std::string obj, expected;
    };
    std::vector<Case> cases = {
        {"v 1 2\n", ":1: v: expected a number, found end of line"},
        {"v 1 2 x\n", ":1: v: expected a number, found \"x\""},
        {"v 0 0 0\nv nan 0 0\n", ":2: v: \"nan\" is not a finite number"},
        {std::string(kQuad) + "f 1 2\n", ":5: f: expected at least 3 vertices"},
        {std::string(kQuad) + "f 1 2 5\n", ":5: f: vertex index 5 is out of range (4 defined so far"},
        {std::string(kQuad) + "f 0 1 2\n", ":5: f: vertex index 0 is out of range"},
        {std::string(kQuad) + "f -5 1 2\n", ":5: f: vertex index -5 is out of range"},
        {std::string(kQuad) + "f 1//1 2//1 3//1\n", ":5: f: normal index 1 is out of range (0 defined"},
        {std::string(kQuad) + "f 1/a 2 3\n", ":5: f: expected a texture coordinate index"},
        {std::string(kQuad) + "f 1/1/1/1 2 3\n", ":5: f: malformed vertex"},
        {std::string(kQuad) + "usemtl nothing\n", ":5: usemtl: no material named \"nothing\""},
    };
    for (const Case& c : cases) {
        std::string e = errorOf(c.obj);
        EXPECT_NE(e.find("s.obj" + c.expected), std::string::npos) << "got: " << e << "\nfor: " << c.obj;
    }
}

TEST_F(ObjFiles, UnknownKeywordsWarnOnce) {
    Scene s = load(std::string(kQuad) + "l 1 2\nl 2 3\no thing\ng group\ns 1\nf 1 2 3\n");
    EXPECT_EQ(s.triangleCount(), 1u);
    ASSERT_EQ(warnings_.messages().size(), 1u);
    EXPECT_NE(warnings_.messages()[0].find("s.obj:5: unsupported keyword \"l\""), std::string::npos);
}

TEST_F(ObjFiles, MissingMtllibIsAWarningAndFallsBack) {
    Scene s = load(std::string("mtllib absent.mtl\n") + kQuad + "usemtl A\nf 1 2 3\n");
    EXPECT_EQ(s.triangleCount(), 1u);
    EXPECT_EQ(s.materials[s.triMaterial[0]].kd, Spectrum(0.7f));
    ASSERT_GE(warnings_.messages().size(), 1u);
    EXPECT_NE(warnings_.messages()[0].find("mtllib \"absent.mtl\" not found"), std::string::npos);
}

TEST_F(ObjFiles, MalformedMtllibIsAnError) {
    std::string e = errorOf(std::string("mtllib m.mtl\n") + kQuad, "newmtl A\nKd red\n");
    EXPECT_NE(e.find("m.mtl:2: Kd: expected a number, found \"red\""), std::string::npos) << e;
}

TEST_F(ObjFiles, SceneWithoutCameraIsFramedAutomatically) {
    Warnings w;
    Scene s = loadScene(write("nocam.obj", std::string(kQuad) + "f 1 2 3 4\n"), w);
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_EQ(s.cameras[0].name, "auto");
    EXPECT_NEAR(s.cameras[0].target.x, 0.5f, 1e-6f);
    EXPECT_GT(s.cameras[0].position.z, 1.0f);
    ASSERT_FALSE(w.messages().empty());
    EXPECT_NE(w.messages().back().find("no camera"), std::string::npos);
}

TEST_F(ObjFiles, MissingAndUnsupportedFilesAreErrors) {
    Warnings w;
    EXPECT_THROW(loadScene((dir_ / "none.obj").string(), w), LoadError);
    EXPECT_THROW(loadScene(write("x.ply", "ply\n"), w), LoadError);
    EXPECT_THROW(loadScene(dir_.string(), w), LoadError);
}

TEST(LabScenes, LoadWithExpectedContents) {
    const std::string lab = PT_LAB_SCENES;
    if (!fs::exists(lab + "/cornell.obj")) GTEST_SKIP() << "lab scenes not found at " << lab;
    Warnings w;
    Scene cornell = loadScene(lab + "/cornell.obj", w);
    EXPECT_EQ(cornell.triangleCount(), 34u);
    EXPECT_EQ(cornell.cameras.size(), 2u);
    EXPECT_EQ(cornell.lights.size(), 1u);
    EXPECT_TRUE(w.messages().empty()) << w.messages()[0];
    Scene bottle = loadScene(lab + "/cornellbottle2.obj", w);
    EXPECT_EQ(bottle.triangleCount(), 43066u);
    Scene textured = loadScene(lab + "/cornell_textured.obj", w);
    ASSERT_EQ(textured.textures->size(), 1u);
    EXPECT_GT((*textured.textures)[0].width, 0);
    EXPECT_TRUE(w.messages().empty()) << w.messages()[0];
}

} // namespace
} // namespace pt
