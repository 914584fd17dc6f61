#include "obj/obj_loader.h"

#include "io/input_file.h"

#include "obj/mtl_loader.h"
#include "obj/text_parser.h"

#include <charconv>
#include <filesystem>
#include <unordered_map>

namespace pt {
namespace {

struct Corner {
    int position = -1, uv = -1, normal = -1;
};

struct ObjParser {
    ObjParser(const std::string& p, Warnings& w) : path(p), warnings(w) {}

    const std::string& path;
    Warnings& warnings;
    Scene scene;
    std::unordered_map<std::string, uint32_t> materialIndex;
    bool mtlMissing = false; // a mtllib could not be read: unknown names are then warnings
    int defaultMaterial = -1;
    uint32_t currentMaterial = 0;
    bool haveMaterial = false;
    bool anyNormals = false, anyUvs = false;
    std::vector<Corner> corners; // reused for every face

    void parseLine(std::string_view keyword, Tokens& t, const LineReader& lines);
    void parseFace(Tokens& t, const LineReader& lines);
    Corner parseCorner(std::string_view token, const Tokens& t) const;
    void useMaterial(std::string_view name, const Tokens& t);
    uint32_t fallbackMaterial();
};

// Resolves a 1-based (or negative, relative) OBJ index against `count` defined elements.
int resolveIndex(std::string_view digits, size_t count, const char* what, const Tokens& t) {
    long long value = 0;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || ptr != digits.data() + digits.size())
        t.fail(std::string("f: expected a ") + what + " index, found \"" + std::string(digits.substr(0, 40)) + "\"");
    long long resolved = value > 0 ? value - 1 : (long long)count + value;
    if (value == 0 || resolved < 0 || resolved >= (long long)count)
        t.fail(std::string("f: ") + what + " index " + std::to_string(value) + " is out of range (" +
               std::to_string(count) + " defined so far; indices start at 1)");
    return int(resolved);
}

Corner ObjParser::parseCorner(std::string_view token, const Tokens& t) const {
    // Forms: v, v/vt, v//vn, v/vt/vn. Check the shape before resolving any index.
    size_t s1 = token.find('/');
    size_t s2 = s1 == std::string_view::npos ? s1 : token.find('/', s1 + 1);
    if (s2 != std::string_view::npos && (token.find('/', s2 + 1) != std::string_view::npos || s2 + 1 == token.size()))
        t.fail("f: malformed vertex \"" + std::string(token.substr(0, 40)) + "\"; expected v, v/vt, v//vn or v/vt/vn");
    Corner c;
    c.position = resolveIndex(token.substr(0, s1), scene.positions.size(), "vertex", t);
    if (s1 == std::string_view::npos) return c;
    std::string_view vt = token.substr(s1 + 1, s2 == std::string_view::npos ? std::string_view::npos : s2 - s1 - 1);
    if (!vt.empty()) c.uv = resolveIndex(vt, scene.uvs.size(), "texture coordinate", t);
    if (s2 != std::string_view::npos) c.normal = resolveIndex(token.substr(s2 + 1), scene.normals.size(), "normal", t);
    return c;
}

uint32_t ObjParser::fallbackMaterial() {
    if (defaultMaterial < 0) {
        Material m;
        m.name = "(default)";
        defaultMaterial = int(scene.materials.size());
        scene.materials.push_back(m);
    }
    return uint32_t(defaultMaterial);
}

void ObjParser::useMaterial(std::string_view name, const Tokens& t) {
    if (name.empty()) t.fail("usemtl: expected a material name");
    auto it = materialIndex.find(std::string(name));
    if (it != materialIndex.end()) {
        currentMaterial = it->second;
    } else if (mtlMissing) {
        warnings.once("usemtl:" + std::string(name),
                      t.location() + "usemtl: material \"" + std::string(name) +
                          "\" not found (its mtllib is missing); using the default material");
        currentMaterial = fallbackMaterial();
    } else {
        t.fail("usemtl: no material named \"" + std::string(name) + "\" in the mtllib files");
    }
    haveMaterial = true;
}

void ObjParser::parseFace(Tokens& t, const LineReader& lines) {
    corners.clear();
    while (!t.empty()) corners.push_back(parseCorner(t.word(), t));
    if (corners.size() < 3) t.fail("f: expected at least 3 vertices, found " + std::to_string(corners.size()));
    if (!haveMaterial) {
        currentMaterial = fallbackMaterial();
        haveMaterial = true;
    }
    // A face uses normals (or uvs) only if every corner has one; otherwise the renderer falls
    // back to the geometric normal (or uv 0) for the whole face.
    bool hasNormals = true, hasUvs = true;
    for (const Corner& c : corners) {
        hasNormals &= c.normal >= 0;
        hasUvs &= c.uv >= 0;
    }
    if (hasNormals && !anyNormals) {
        anyNormals = true;
        scene.triNormals.assign(scene.triPositions.size(), glm::ivec3(-1));
    }
    if (hasUvs && !anyUvs) {
        anyUvs = true;
        scene.triUvs.assign(scene.triPositions.size(), glm::ivec3(-1));
    }
    (void)lines;
    // Fan triangulation, as the lab does.
    for (size_t i = 1; i + 1 < corners.size(); ++i) {
        const Corner &a = corners[0], &b = corners[i], &c = corners[i + 1];
        scene.triPositions.emplace_back(a.position, b.position, c.position);
        scene.triMaterial.push_back(currentMaterial);
        if (anyNormals)
            scene.triNormals.push_back(hasNormals ? glm::ivec3(a.normal, b.normal, c.normal) : glm::ivec3(-1));
        if (anyUvs) scene.triUvs.push_back(hasUvs ? glm::ivec3(a.uv, b.uv, c.uv) : glm::ivec3(-1));
    }
}

void ObjParser::parseLine(std::string_view keyword, Tokens& t, const LineReader& lines) {
    if (keyword == "v") {
        scene.positions.push_back(t.point("v"));
        return; // an optional w or vertex colour may follow; neither is used
    }
    if (keyword == "vn") {
        Vec3 n = t.vec3("vn");
        scene.normals.push_back(n);
        return;
    }
    if (keyword == "vt") {
        float u = t.number("vt");
        float v = t.empty() ? 0.0f : t.number("vt");
        scene.uvs.emplace_back(u, v);
        return;
    }
    if (keyword == "f") return parseFace(t, lines);
    if (keyword == "usemtl") return useMaterial(t.restOfLine(), t);
    if (keyword == "mtllib") {
        std::string_view rest = t.restOfLine();
        if (rest.empty()) t.fail("mtllib: expected a file name");
        std::filesystem::path dir = std::filesystem::path(path).parent_path();
        // One name per line is the common case and may contain spaces; otherwise split on spaces.
        std::vector<std::string> names;
        std::error_code ec; // the non-throwing forms: a name can be too long for the file system
        if (std::filesystem::exists(dir / std::string(rest), ec)) {
            names.emplace_back(rest);
        } else {
            Tokens words(rest, lines);
            for (std::string_view w = words.word(); !w.empty(); w = words.word()) names.emplace_back(w);
        }
        for (const std::string& name : names) {
            std::string file = (dir / name).string();
            try {
                loadMtl(file, scene, materialIndex, warnings);
            } catch (const LoadError& e) {
                // A material library that does not exist is recoverable; a malformed one is not.
                std::string problem = pathProblem(file);
                if (problem.empty()) throw;
                warnings.add(t.location() + "mtllib \"" + name + "\" " + problem +
                             "; faces using its materials get the default material");
                mtlMissing = true;
            }
        }
        return;
    }
    if (keyword == "o" || keyword == "g" || keyword == "s") return; // grouping and smoothing: not needed
    warnings.once("obj:" + std::string(keyword), t.location() + "unsupported keyword \"" + std::string(keyword.substr(0, 40)) +
                                                     "\" ignored (reported once)");
}

} // namespace

Scene parseObj(std::string_view text, const std::string& path, Warnings& warnings) {
    ObjParser parser(path, warnings);
    parser.scene.path = path;
    parser.scene.sources.push_back({path, contentHash(text.data(), text.size())});
    parseLines(text, path, parser);
    return std::move(parser.scene);
}

Scene loadObj(const std::string& path, Warnings& warnings) {
    std::string text = readTextFile(path);
    if (text.empty()) throw LoadError(path + ": the file is empty; expected a Wavefront OBJ scene");
    return parseObj(text, path, warnings);
}

} // namespace pt
