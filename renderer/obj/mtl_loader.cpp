#include "obj/mtl_loader.h"

#include "io/input_file.h"

#include "environment/environment_map.h"
#include "environment/sky_environment.h"
#include "texture/texture_io.h"
#include "obj/text_parser.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <optional>

namespace pt {
namespace {

enum class Block { None, Material, Light, Camera, Environment };

// What a map line's texture holds: colour (sRGB-decoded) or data (linear), and which options it takes.
enum class MapKind { Colour, Scalar, Normal, Bump, Alpha };

// A material as written; the metallic (Pm) rule is applied when it is evaluated at a hit.
struct PendingMaterial {
    Material m;
    std::optional<float> metallic;
    std::optional<float> d, tr; // d is coverage with map_d, else transparency 1 - d
    size_t line = 0;
};

struct PendingLight {
    LocalLight light;
    Spectrum color{1.0f};
    float intensity = 1.0f;
};

// An environment block, read when the block ends: a map file and how to turn and scale it, or
// the Preetham sky (envsky) with its sun and haze.
struct PendingEnvironment {
    std::string file;         // resolved against the MTL's folder
    size_t fileLine = 0;
    float rotate = 0.0f, scale = 1.0f;
    size_t rotateLine = 0, scaleLine = 0, skyScaleLine = 0;
    size_t skyLine = 0;       // of envsky
    size_t firstSkyKeywordLine = 0;
    std::string firstSkyKeyword;
    SkyParameters sky;
    float sunElevation = 45.0f, sunAzimuth = 135.0f;
    size_t sunAnglesLine = 0, sunDirLine = 0;
};

// Lines of a camera block's keywords, so an error points at the value that is wrong.
struct CameraLines {
    size_t position = 0, target = 0, up = 0, fov = 0;
};

struct MtlParser {
    MtlParser(const std::string& p, Scene& s, std::unordered_map<std::string, uint32_t>& index, Warnings& w)
        : path(p), scene(s), materialIndex(index), warnings(w) {}

    const std::string& path;
    Scene& scene;
    std::unordered_map<std::string, uint32_t>& materialIndex;
    Warnings& warnings;

    Block block = Block::None;
    PendingMaterial material;
    PendingLight light;
    Camera camera;
    CameraLines cameraLines;
    PendingEnvironment environment;
    size_t environmentLine = 0; // of the scene's newenvironment, once one was seen
    size_t blockLine = 0;

    void finishBlock();
    void finishMaterial();
    void finishCamera();
    void parseLine(std::string_view keyword, Tokens& t, const LineReader& lines);
    void requireBlock(Block wanted, std::string_view keyword, const Tokens& t) const;
    float nonNegative(Tokens& t, std::string_view keyword);
    Spectrum nonNegativeColor(Tokens& t, std::string_view keyword);
    Spectrum reflectance(Tokens& t, std::string_view keyword);
    float unitInterval(Tokens& t, std::string_view keyword);
    TextureMap loadTexture(std::string_view spec, std::string_view keyword, const LineReader& lines, MapKind kind);
};

void MtlParser::requireBlock(Block wanted, std::string_view keyword, const Tokens& t) const {
    if (block == wanted) return;
    const char* name = wanted == Block::Material      ? "newmtl"
                       : wanted == Block::Light       ? "newlight"
                       : wanted == Block::Environment ? "newenvironment"
                                                      : "newcamera";
    t.fail(std::string(keyword) + " outside a " + name + " block");
}

float MtlParser::nonNegative(Tokens& t, std::string_view keyword) {
    float v = t.number(keyword);
    if (v < 0.0f) t.fail(std::string(keyword) + ": expected a value >= 0, found " + shortNumber(v));
    return v;
}

Spectrum MtlParser::nonNegativeColor(Tokens& t, std::string_view keyword) {
    Spectrum c = t.color(keyword);
    if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
        t.fail(std::string(keyword) + ": expected values >= 0");
    return c;
}

// Kd and Ks above 1 reflect more light than arrives: allowed (artists do it), but said once;
// beyond kMaxReflectance refused.
Spectrum MtlParser::reflectance(Tokens& t, std::string_view keyword) {
    Spectrum c = nonNegativeColor(t, keyword);
    if (maxComponent(c) > kMaxReflectance)
        t.fail(std::string(keyword) + ": " + shortNumber(maxComponent(c)) +
               " is beyond 10; a reflectance is at most 1, and beyond 10 light grows so fast along a path "
               "that samples overflow float");
    if (maxComponent(c) > 1.0f)
        warnings.once("reflectance:" + path + ":" + material.m.name,
                      t.location() + std::string(keyword) + " above 1 in material \"" + material.m.name +
                          "\" creates energy (it reflects more light than it receives); expected values <= 1");
    return c;
}

float MtlParser::unitInterval(Tokens& t, std::string_view keyword) {
    float v = t.number(keyword);
    if (v < 0.0f || v > 1.0f)
        t.fail(std::string(keyword) + ": expected a value in [0, 1], found " + shortNumber(v));
    return v;
}

// A map line: options, then the file name, which is the rest of the line and may hold spaces.
// -s and -o take one to three numbers (u, v, w; w is for 3D textures and ignored), -clamp on|off,
// -bm a scale (bump and normal maps), -imfchan r|g|b|m|l the channel of a scalar map. Other options
// of the OBJ format (-blendu, -blendv, -boost, -mm, -t, -texres, -cc, -type) change nothing here:
// they are skipped with a warning.
TextureMap MtlParser::loadTexture(std::string_view spec, std::string_view keyword, const LineReader& lines, MapKind kind) {
    std::string where = path + ":" + std::to_string(lines.lineNumber()) + ": ";
    std::string kw(keyword);
    const bool scalar = kind == MapKind::Scalar || kind == MapKind::Bump || kind == MapKind::Alpha;
    TextureMap map;
    map.channel = scalar ? TextureChannel::Luminance : TextureChannel::Rgb;
    bool channelGiven = false;
    Tokens t(spec, lines);
    auto numbers = [&](const std::string& option, int most) {
        std::vector<float> v;
        while (int(v.size()) < most && !t.empty()) {
            Tokens probe = t; // peek: the next word may be the file name
            std::string_view w = probe.word();
            float x;
            auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), x);
            if (ec != std::errc() || ptr != w.data() + w.size()) break;
            v.push_back(t.number(kw + " " + option));
        }
        if (v.empty()) t.fail(kw + " " + option + ": expected a number");
        return v;
    };
    auto ignored = [&](const std::string& option) {
        warnings.once("texopt:" + kw + option, where + kw + ": option " + option + " has no effect on this map; ignored");
    };
    for (;;) {
        Tokens probe = t;
        std::string_view w = probe.word();
        if (w.size() < 2 || w.front() != '-') break;
        std::string option(w);
        t.word();
        if (option == "-s" || option == "-o") {
            std::vector<float> v = numbers(option, 3);
            Vec2 uv(v[0], v.size() > 1 ? v[1] : (option == "-s" ? 1.0f : 0.0f));
            if (option == "-s") map.linear = scaleMatrix(uv);
            else map.offset = uv;
        } else if (option == "-clamp") {
            std::string_view onOff = t.word();
            if (onOff != "on" && onOff != "off") t.fail(kw + " -clamp: expected on or off, found \"" + std::string(onOff) + "\"");
            map.wrapU = map.wrapV = onOff == "on" ? TextureWrap::Clamp : TextureWrap::Repeat;
        } else if (option == "-bm") {
            float bm = numbers(option, 1)[0];
            if (std::abs(bm) > kMaxCoordinate) t.fail(kw + " -bm: " + shortNumber(bm) + " is beyond 1e12");
            if (kind == MapKind::Bump || kind == MapKind::Normal) map.bumpScale = bm;
            else ignored(option);
        } else if (option == "-imfchan") {
            std::string_view c = t.word();
            static const std::pair<std::string_view, TextureChannel> names[] = {
                {"r", TextureChannel::R}, {"g", TextureChannel::G}, {"b", TextureChannel::B},
                {"m", TextureChannel::Alpha}, {"l", TextureChannel::Luminance}};
            auto it = std::find_if(std::begin(names), std::end(names), [&](const auto& n) { return n.first == c; });
            if (it == std::end(names))
                t.fail(kw + " -imfchan: expected r, g, b, m (alpha) or l (luminance), found \"" + std::string(c) + "\"" +
                       (c == "z" ? " (depth channels are not supported)" : ""));
            if (scalar) {
                map.channel = it->second;
                channelGiven = true;
            } else {
                ignored(option);
            }
        } else if (option == "-blendu" || option == "-blendv" || option == "-cc" || option == "-boost" ||
                   option == "-texres" || option == "-type") {
            if (t.word().empty()) t.fail(kw + " " + option + ": expected a value");
            ignored(option);
        } else if (option == "-mm" || option == "-t") {
            numbers(option, option == "-mm" ? 2 : 3);
            ignored(option);
        } else {
            t.fail(kw + ": unknown texture option \"" + option +
                   "\"; expected -s, -o, -clamp, -bm, -imfchan (or -blendu, -blendv, -boost, -mm, -t, -texres, -cc, -type)");
        }
    }
    std::string file(t.restOfLine());
    if (file.empty()) throw LoadError(path, lines.lineNumber(), kw + ": expected a file name");
    std::string full = (std::filesystem::path(path).parent_path() / file).string();
    const bool colour = kind == MapKind::Colour;
    TextureCache& cache = *scene.textures;
    auto fallBack = [&](const std::string& why) {
        warnings.once("texture:" + full + (colour ? ":colour" : ":data"),
                      where + kw + ": " + why + "; " + (colour ? "using the plain colour" : "using the plain value") +
                          " instead (reported once per file)");
        return TextureMap{};
    };
    map.texture = cache.find(full, colour);
    if (map.texture < 0) {
        std::string error;
        Texture tex;
        bool tooLarge = false;
        if (!readTexture(full, colour, tex, error, textureMemoryBudget() - cache.bytes(), tooLarge)) {
            // Too large is an error: a render without the texture would be a silently different image.
            if (tooLarge) throw LoadError(where + kw + ": " + error);
            return fallBack(error);
        }
        scene.sources.push_back({full, tex.sourceHash});
        map.texture = cache.add(std::move(tex));
    }
    const Texture& tex = cache[map.texture];
    if (kind == MapKind::Alpha && !channelGiven && tex.hasAlpha()) map.channel = TextureChannel::Alpha;
    if (map.channel == TextureChannel::Alpha && !tex.hasAlpha())
        return fallBack("texture \"" + full + "\" has no alpha channel for -imfchan m");
    if (kind == MapKind::Normal && tex.channels < 3)
        return fallBack("normal map \"" + full + "\" has " + std::to_string(tex.channels) + " channel(s); expected RGB");
    return map;
}

void MtlParser::finishMaterial() {
    Material m = material.m;
    if (material.metallic) m.metallic = *material.metallic; // the Pm rule is applied at each hit
    if (m.alphaMap.used() && material.d) { // with a cutout, d scales coverage and is no transparency
        m.coverage = *material.d;
        m.transparency = material.tr.value_or(0.0f);
    }
    if (m.normalMap.used() && m.bumpMap.used()) {
        warnings.add(path + ":" + std::to_string(material.line) + ": material \"" + m.name +
                     "\" has both a normal map (norm) and a bump map; the bump map is ignored");
        m.bumpMap = TextureMap{};
    }
    if (materialIndex.count(m.name))
        warnings.add(path + ":" + std::to_string(material.line) + ": material \"" + m.name +
                     "\" defined again; the later definition wins");
    materialIndex[m.name] = uint32_t(scene.materials.size());
    scene.materials.push_back(std::move(m));
}

void MtlParser::finishCamera() {
    const CameraLines& at = cameraLines;
    auto fail = [&](size_t line, const std::string& what) {
        throw LoadError(path, line ? line : blockLine, "camera \"" + camera.name + "\": " + what);
    };
    Vec3 dir = safeNormalize(camera.target - camera.position);
    if (dir == Vec3(0.0f))
        fail(std::max(at.position, at.target), "cameraposition equals cameratarget; expected distinct points");
    Vec3 up = safeNormalize(camera.up);
    if (up == Vec3(0.0f) || safeLength(glm::cross(dir, up)) <= 1e-6f)
        fail(at.up, "cameraup is zero or parallel to the viewing direction");
    if (!(camera.fovY > 0.0f && camera.fovY < 180.0f)) fail(at.fov, "camerafov must be in (0, 180) degrees");
    if (at.position == 0 && at.target == 0)
        warnings.add(path + ":" + std::to_string(blockLine) + ": camera \"" + camera.name +
                     "\" has neither cameraposition nor cameratarget; it sits at the origin looking along -z");
    scene.cameras.push_back(camera);
}

void MtlParser::finishBlock() {
    switch (block) {
    case Block::Material: finishMaterial(); break;
    case Block::Light: {
        LocalLight& l = light.light;
        l.intensity = light.color * light.intensity;
        if (l.source.empty()) l.source = path + ":" + std::to_string(blockLine) + ": ";
        // A sphere's radiance is known here; limits relative to the scene's size are checked once
        // the whole scene is loaded (completeScene).
        if (!l.isPoint() && maxComponent(l.radiance()) > kMaxRadiance)
            throw LoadError(l.source + "light \"" + l.name + "\": lightintensity " + shortNumber(maxComponent(l.intensity)) +
                            " on a sphere of radius " + shortNumber(l.radius) + " emits radiance " +
                            shortNumber(maxComponent(l.radiance())) + ", beyond the 1e18 that float samples and "
                            "their variance can hold");
        scene.lights.push_back(l);
        break;
    }
    case Block::Camera: finishCamera(); break;
    case Block::Environment: {
        PendingEnvironment& e = environment;
        if (e.skyLine) {
            if (!e.file.empty())
                throw LoadError(path, e.fileLine, "envmap: the block is already the sky (envsky, line " +
                                                      std::to_string(e.skyLine) + "); give one of them");
            if (e.rotateLine || e.scaleLine)
                throw LoadError(path, e.rotateLine ? e.rotateLine : e.scaleLine,
                                std::string(e.rotateLine ? "envrotate" : "envscale") +
                                    " applies to an envmap; the sky takes sunazimuth and skyscale");
            if (e.sunDirLine && e.sunAnglesLine)
                throw LoadError(path, std::max(e.sunDirLine, e.sunAnglesLine),
                                "sundir and sunelevation/sunazimuth both place the sun; give one or the other");
            if (!e.sunDirLine) e.sky.sunDirection = sunDirectionFromAngles(e.sunElevation, e.sunAzimuth);
            if (double peak = skyPeakRadiance(e.sky); !(peak <= kMaxRadiance))
                throw LoadError(path, e.skyScaleLine ? e.skyScaleLine : blockLine,
                                "skyscale " + shortNumber(e.sky.scale) + ": the sky's peak radiance (the sun's disk "
                                "where it is up) becomes " + shortNumber(peak) + ", beyond the 1e18 whose samples fit in float");
            scene.environment = skyEnvironment(e.sky);
            if (e.sky.sunDirection.y < 0.0f)
                warnings.add(path + ":" + std::to_string(e.sunDirLine ? e.sunDirLine : e.sunAnglesLine) +
                             ": the sun is below the horizon: the model has no twilight, so the sky is that of a "
                             "sun on the horizon and the sun's disk is hidden");
            break;
        }
        if (e.firstSkyKeywordLine)
            throw LoadError(path, e.firstSkyKeywordLine, e.firstSkyKeyword + ": applies to the sky; the block needs an envsky line");
        if (environment.file.empty())
            throw LoadError(path, blockLine, "newenvironment: the block has neither an envmap line naming its map nor envsky");
        std::string warning;
        try {
            scene.environment.map = std::make_shared<const EnvironmentMap>(
                readEnvironmentMap(environment.file, environment.rotate, environment.scale, warning));
        } catch (const LoadError& e) {
            throw LoadError(path, environment.fileLine, e.what());
        }
        if (!warning.empty()) warnings.add(path + ":" + std::to_string(environment.fileLine) + ": " + warning);
        scene.sources.push_back({environment.file, scene.environment.map->sourceHash});
        break;
    }
    case Block::None: break;
    }
    block = Block::None;
}

void MtlParser::parseLine(std::string_view keyword, Tokens& t, const LineReader& lines) {
    auto is = [&](std::string_view k) { return equalsIgnoreCase(keyword, k); };
    auto blockName = [&](const char* kind) {
        std::string_view name = t.restOfLine();
        if (name.empty()) t.fail(std::string(kind) + ": expected a name");
        return std::string(name);
    };

    if (is("newmtl")) {
        finishBlock();
        block = Block::Material;
        blockLine = lines.lineNumber();
        material = PendingMaterial{};
        material.m.name = blockName("newmtl");
        material.line = lines.lineNumber();
        return;
    }
    if (is("newlight")) {
        finishBlock();
        block = Block::Light;
        blockLine = lines.lineNumber();
        light = PendingLight{};
        light.light.name = blockName("newlight");
        return;
    }
    if (is("newcamera")) {
        finishBlock();
        block = Block::Camera;
        blockLine = lines.lineNumber();
        camera = Camera{};
        cameraLines = CameraLines{};
        camera.name = blockName("newcamera");
        return;
    }

    if (is("newenvironment")) {
        if (environmentLine)
            t.fail("newenvironment: the scene already has one (line " + std::to_string(environmentLine) +
                   "); a scene has at most one environment");
        finishBlock();
        block = Block::Environment;
        blockLine = environmentLine = lines.lineNumber();
        environment = PendingEnvironment{};
        blockName("newenvironment");
        return;
    }
    if (is("envmap")) {
        requireBlock(Block::Environment, keyword, t);
        std::string file(t.restOfLine());
        if (file.empty()) t.fail("envmap: expected a file name");
        environment.file = (std::filesystem::path(path).parent_path() / file).string();
        environment.fileLine = lines.lineNumber();
        return;
    }

    // Materials.
    Material& m = material.m;
    // Map lines: the rest of the line is options and a file name.
    struct MapKeyword {
        const char *name, *alias;
        TextureMap Material::*map;
        MapKind kind;
    };
    static const MapKeyword mapKeywords[] = {
        {"map_Kd", "diffuseReflectanceMap", &Material::kdMap, MapKind::Colour},
        {"map_Ks", "specularReflectanceMap", &Material::ksMap, MapKind::Colour},
        {"map_Pr", nullptr, &Material::roughnessMap, MapKind::Scalar},
        {"map_Pm", nullptr, &Material::metallicMap, MapKind::Scalar},
        {"norm", nullptr, &Material::normalMap, MapKind::Normal},
        {"bump", "map_bump", &Material::bumpMap, MapKind::Bump},
        {"map_d", nullptr, &Material::alphaMap, MapKind::Alpha}};
    for (const MapKeyword& k : mapKeywords)
        if (is(k.name) || (k.alias && is(k.alias))) {
            requireBlock(Block::Material, keyword, t);
            m.*k.map = loadTexture(t.restOfLine(), keyword, lines, k.kind);
            return;
        }

    if (is("Kd") || is("diffuseReflectance")) {
        requireBlock(Block::Material, keyword, t);
        m.kd = reflectance(t, keyword);
    } else if (is("Ks") || is("specularReflectance")) {
        requireBlock(Block::Material, keyword, t);
        m.ks = reflectance(t, keyword);
    } else if (is("reflat0deg")) {
        requireBlock(Block::Material, keyword, t);
        m.r0 = nonNegativeColor(t, keyword);
        if (maxComponent(m.r0) > 1.0f) t.fail("reflat0deg: expected values in [0, 1]");
    } else if (is("reflat90deg")) {
        requireBlock(Block::Material, keyword, t);
        m.blend = unitInterval(t, keyword);
    } else if (is("transparency") || is("Tr")) {
        requireBlock(Block::Material, keyword, t);
        m.transparency = unitInterval(t, keyword);
        material.tr = m.transparency;
    } else if (is("d")) {
        requireBlock(Block::Material, keyword, t);
        material.d = unitInterval(t, keyword);
        m.transparency = 1.0f - *material.d;
    } else if (is("indexofrefraction") || is("Ni")) {
        requireBlock(Block::Material, keyword, t);
        m.eta = t.number(keyword);
        if (!(m.eta > 0.0f)) t.fail(std::string(keyword) + ": expected an index of refraction > 0");
    } else if (is("specularroughness")) { // GGX alpha, as is
        requireBlock(Block::Material, keyword, t);
        m.roughnessAlpha = nonNegative(t, keyword);
    } else if (is("Pr")) { // perceptual roughness, as in glTF and Blender: alpha = Pr^2
        requireBlock(Block::Material, keyword, t);
        m.roughnessAlpha = sqr(unitInterval(t, keyword));
    } else if (is("emittance") || is("Ke")) {
        requireBlock(Block::Material, keyword, t);
        m.emission = nonNegativeColor(t, keyword);
        if (maxComponent(m.emission) > kMaxRadiance)
            t.fail(std::string(keyword) + ": radiance " + shortNumber(maxComponent(m.emission)) +
                   " is beyond the 1e18 that float samples and their variance can hold");
    } else if (is("Pm")) {
        requireBlock(Block::Material, keyword, t);
        material.metallic = unitInterval(t, keyword);
    }
    // Lights.
    else if (is("lightposition")) {
        requireBlock(Block::Light, keyword, t);
        light.light.center = t.point(keyword);
    } else if (is("lightcolor")) {
        requireBlock(Block::Light, keyword, t);
        light.color = nonNegativeColor(t, keyword);
    } else if (is("lightradius")) {
        requireBlock(Block::Light, keyword, t);
        light.light.radius = nonNegative(t, keyword);
        if (light.light.radius > kMaxCoordinate)
            t.fail("lightradius: beyond 1e12, the largest size pt renders correctly; scale the scene down");
        light.light.radiusSource = t.location();
    } else if (is("lightintensity")) {
        requireBlock(Block::Light, keyword, t);
        light.intensity = nonNegative(t, keyword);
        light.light.source = t.location();
    }
    // Environment.
    else if (is("envrotate")) {
        requireBlock(Block::Environment, keyword, t);
        environment.rotate = t.number(keyword);
        if (!(std::abs(environment.rotate) <= 36000.0f)) t.fail("envrotate: expected degrees in [-36000, 36000]");
        environment.rotateLine = lines.lineNumber();
    } else if (is("envscale")) {
        requireBlock(Block::Environment, keyword, t);
        environment.scale = nonNegative(t, keyword);
        environment.scaleLine = lines.lineNumber();
    } else if (is("envsky")) {
        requireBlock(Block::Environment, keyword, t);
        environment.skyLine = lines.lineNumber();
    } else if (is("sunelevation") || is("sunazimuth") || is("sundir") || is("turbidity") || is("skyscale")) {
        requireBlock(Block::Environment, keyword, t);
        PendingEnvironment& e = environment;
        std::string name = toLower(keyword);
        if (!e.firstSkyKeywordLine) e.firstSkyKeywordLine = lines.lineNumber(), e.firstSkyKeyword = name;
        if (name == "sunelevation") {
            e.sunElevation = t.number(keyword);
            if (!(std::abs(e.sunElevation) <= 90.0f)) t.fail("sunelevation: expected degrees in [-90, 90]");
            e.sunAnglesLine = lines.lineNumber();
        } else if (name == "sunazimuth") {
            e.sunAzimuth = t.number(keyword);
            if (!(std::abs(e.sunAzimuth) <= 36000.0f)) t.fail("sunazimuth: expected degrees in [-36000, 36000]");
            e.sunAnglesLine = lines.lineNumber();
        } else if (name == "sundir") {
            Vec3 d = t.vec3(keyword);
            glm::dvec3 exact(d); // in double: a direction of (3e38, 3e38, 3e38) has no float length
            double length = glm::length(exact);
            if (!(length > 0.0) || !std::isfinite(length)) t.fail("sundir: expected a direction X Y Z of non-zero length");
            e.sky.sunDirection = Vec3(exact / length);
            e.sunDirLine = lines.lineNumber();
        } else if (name == "turbidity") {
            e.sky.turbidity = t.number(keyword);
            if (!turbidityInRange(e.sky.turbidity))
                t.fail("turbidity: expected a value in [1.7, 10], the range of Preetham et al.'s fit (1.7 very clear, "
                       "10 hazy), found " + shortNumber(e.sky.turbidity));
        } else {
            e.sky.scale = nonNegative(t, keyword);
            e.skyScaleLine = lines.lineNumber();
        }
    }
    // Cameras.
    else if (is("cameraposition")) {
        requireBlock(Block::Camera, keyword, t);
        camera.position = t.point(keyword);
        cameraLines.position = lines.lineNumber();
    } else if (is("cameratarget")) {
        requireBlock(Block::Camera, keyword, t);
        camera.target = t.point(keyword);
        cameraLines.target = lines.lineNumber();
    } else if (is("cameraup")) {
        requireBlock(Block::Camera, keyword, t);
        camera.up = t.vec3(keyword);
        cameraLines.up = lines.lineNumber();
    } else if (is("camerafov")) {
        requireBlock(Block::Camera, keyword, t);
        camera.fovY = t.number(keyword);
        cameraLines.fov = lines.lineNumber();
    } else {
        std::string k = toLower(keyword);
        warnings.once("mtl:" + k, t.location() + "unknown keyword \"" +
                                      std::string(keyword) + "\" ignored (reported once)");
        return;
    }
    t.expectEnd(keyword);
}

} // namespace

void parseMtl(std::string_view text, const std::string& path, Scene& scene,
              std::unordered_map<std::string, uint32_t>& materialIndex, Warnings& warnings) {
    MtlParser parser(path, scene, materialIndex, warnings);
    parseLines(text, path, parser);
    parser.finishBlock();
}

void loadMtl(const std::string& path, Scene& scene,
             std::unordered_map<std::string, uint32_t>& materialIndex, Warnings& warnings) {
    std::string text = readTextFile(path);
    scene.sources.push_back({path, contentHash(text.data(), text.size())});
    parseMtl(text, path, scene, materialIndex, warnings);
}

} // namespace pt
