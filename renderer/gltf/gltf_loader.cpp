#include "gltf/gltf_loader.h"

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_document.h"
#include "io/input_file.h"
#include "core/system.h"
#include "io/scene_limits.h"
#include "scene/complete_scene.h"
#include "core/math.h"
#include "core/system.h"
#include "texture/texture_io.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <sys/stat.h>

namespace pt {
namespace {

constexpr const char* kSupportedExtensions[] = {
    "KHR_materials_clearcoat", "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_sheen",
    "KHR_materials_specular", "KHR_materials_unlit",
    "KHR_materials_transmission",
    "KHR_materials_volume", "KHR_lights_punctual", "KHR_mesh_quantization", "KHR_texture_transform",
};

// Lumens per watt: glTF lights are photometric (candela, lux), pt's radiometric. Blender's glTF
// importer divides by the same 683, so a scene is as bright in both.
constexpr double kLumensPerWatt = 683.0;

using tinygltf::Model;

// Images are not decoded by tinygltf (its stb build is not ours): the loader callback keeps the
// bytes of data-URI images, and the loader reads the others itself, from their buffer views or
// files, and has OpenImageIO decode the ones a material uses. A buffer-view image's bytes are not
// touched here: tinygltf passes a pointer it has not checked.
bool keepImageBytes(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void* user) {
    auto* kept = static_cast<std::vector<std::vector<unsigned char>>*>(user);
    if (image->bufferView >= 0) return true;
    if (index < 0 || size < 0 || index > (1 << 24)) return false;
    if (size_t(index) >= kept->size()) kept->resize(size_t(index) + 1);
    (*kept)[size_t(index)].assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// A URI's path as tinygltf decodes it (%XX escapes, and '+' as a space), so that the loader finds
// an image where tinygltf finds a buffer of the same name.
std::string decodeUri(const std::string& uri) {
    auto hex = [](char c) { return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : 0; };
    std::string path;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') path += ' ';
        else if (uri[i] == '%' && i + 2 < uri.size()) path += char(hex(uri[i + 1]) << 4 | hex(uri[i + 2])), i += 2;
        else path += uri[i];
    }
    return path;
}

// tinygltf reads a buffer's file through these callbacks: only a regular file, only beside the
// .gltf (tinygltf would also look in the working directory), and only of a size some buffer
// declares (byteLength, which tinygltf then checks). Image files are refused here, which tinygltf
// takes as a warning: the loader reads the images a material uses itself, header first.
struct ExternalFiles {
    std::string folder;                  // the .gltf's folder, as tinygltf joins it to a URI
    std::vector<uint64_t> bufferLengths; // byteLength of each buffer held in a file
    uint64_t bytesLeft;                  // what all of them may still take (many buffers may name one file)
    std::vector<SourceFile> read;        // the files read, with the hash of their bytes
};

bool externalFileExists(const std::string& path, void* user) {
    const auto& files = *static_cast<const ExternalFiles*>(user);
    struct stat st {};
    std::string prefix = files.folder.back() == '/' ? files.folder : files.folder + "/";
    return path.rfind(prefix, 0) == 0 && stat(path.c_str(), &st) == 0;
}

std::string pathAsGiven(const std::string& path, void*) { return path; } // no ~ or $VAR expansion

bool readExternalFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    auto& files = *static_cast<ExternalFiles*>(user);
    struct stat st {};
    if (stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        std::find(files.bufferLengths.begin(), files.bufferLengths.end(), uint64_t(st.st_size)) == files.bufferLengths.end()) {
        if (err) *err += "its " + std::to_string(st.st_size) + " bytes are no buffer's byteLength";
        return false;
    }
    uint64_t largest = files.bufferLengths.empty() ? 0 : *std::max_element(files.bufferLengths.begin(), files.bufferLengths.end());
    std::string error = readRegularFile(path, std::min(largest, files.bytesLeft), *out);
    if (!error.empty() && err) *err += error + (largest > files.bytesLeft ? " (its buffers together may take half this machine's memory)" : "");
    files.bytesLeft -= std::min<uint64_t>(files.bytesLeft, out->size());
    if (error.empty()) files.read.push_back({path, contentHash(out->data(), out->size())});
    return error.empty();
}

bool writeNothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "pt writes no glTF files";
    return false;
}

glm::dmat4 localTransform(const tinygltf::Node& n, const std::string& what) {
    if (n.matrix.size() == 16) {
        glm::dmat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = n.matrix[size_t(c * 4 + r)]; // column-major, as glm
        return m;
    }
    if (!n.matrix.empty()) throw LoadError(what + ": matrix has " + std::to_string(n.matrix.size()) + " values; expected 16");
    glm::dmat4 m(1.0);
    if (!n.translation.empty()) {
        if (n.translation.size() != 3) throw LoadError(what + ": translation needs 3 values");
        m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (!n.rotation.empty()) {
        if (n.rotation.size() != 4) throw LoadError(what + ": rotation needs 4 values (a quaternion x, y, z, w)");
        glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
        double len = glm::length(q);
        if (!(len > 0.0) || !std::isfinite(len)) throw LoadError(what + ": rotation is not a unit quaternion");
        m = m * glm::mat4_cast(q / len);
    }
    if (!n.scale.empty()) {
        if (n.scale.size() != 3) throw LoadError(what + ": scale needs 3 values");
        m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    }
    return m;
}

// A sampler's wrapS or wrapT (the document check allows only these three values).
TextureWrap wrapOf(int mode) {
    if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::Clamp;
    if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::Mirror;
    return TextureWrap::Repeat;
}

// v / |v| in double, or 0 for a zero vector.
glm::dvec3 unitOrZero(const glm::dvec3& v) {
    double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? v / length : glm::dvec3(0.0);
}

Spectrum colorOf(const std::vector<double>& v, Spectrum fallback) {
    return v.size() >= 3 ? Spectrum(float(v[0]), float(v[1]), float(v[2])) : fallback;
}

// A number or a colour of an extension's object (its type and range checked by gltf_document),
// or `fallback` where it is absent.
float extensionNumber(const tinygltf::Value& object, const char* key, float fallback) {
    return object.Has(key) ? float(object.Get(key).GetNumberAsDouble()) : fallback;
}
Spectrum extensionColor(const tinygltf::Value& object, const char* key, Spectrum fallback) {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    return Spectrum(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()), float(v.Get(2).GetNumberAsDouble()));
}

class GltfReader {
public:
    GltfReader(const std::string& path, const Model& model, std::vector<std::vector<unsigned char>>& images, Scene& scene,
               Warnings& warnings)
        : path_(path), model_(model), images_(images), scene_(scene), warnings_(warnings) {}

    void read() {
        materialOf_.assign(model_.materials.size(), ~0u);
        uvSet_.assign(model_.materials.size(), 0);
        readsTextures_.assign(model_.materials.size(), 0);
        if (model_.scenes.empty()) {
            // No scene: every root node, as viewers do.
            std::vector<char> child(model_.nodes.size(), 0);
            for (const auto& n : model_.nodes)
                for (int c : n.children)
                    if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = 1;
            for (size_t i = 0; i < model_.nodes.size(); ++i)
                if (!child[i]) visitTree(int(i));
        } else {
            int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (size_t(s) >= model_.scenes.size())
                throw LoadError(path_ + ": scene " + std::to_string(s) + " does not exist");
            for (int root : model_.scenes[size_t(s)].nodes) visitTree(root);
        }
        if (skippedPrimitives_ > 0)
            warnings_.add(path_ + ": " + std::to_string(skippedPrimitives_) +
                          " point or line primitives skipped; pt renders triangles");
    }

private:
    // Depth first, without recursion (a chain of a million nodes must not exhaust the stack). A
    // node reached twice is a cycle or a node with two parents, both invalid: refused.
    void visitTree(int root) {
        std::vector<std::pair<int, glm::dmat4>> stack{{root, glm::dmat4(1.0)}};
        visited_.resize(model_.nodes.size(), 0);
        while (!stack.empty()) {
            auto [index, parent] = stack.back();
            stack.pop_back();
            std::string what = path_ + ": node " + std::to_string(index);
            if (index < 0 || size_t(index) >= model_.nodes.size())
                throw LoadError(what + " does not exist (the file has " + std::to_string(model_.nodes.size()) + ")");
            if (visited_[size_t(index)])
                throw LoadError(what + " is reached twice in the node hierarchy (a cycle, or two parents)");
            visited_[size_t(index)] = 1;
            const tinygltf::Node& node = model_.nodes[size_t(index)];
            glm::dmat4 world = parent * localTransform(node, what);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    if (!std::isfinite(world[c][r])) throw LoadError(what + ": its transform is not finite");
            if (node.mesh >= 0) addMesh(node.mesh, world, what);
            if (node.camera >= 0) addCamera(node.camera, world, what);
            auto light = node.extensions.find("KHR_lights_punctual");
            if (light != node.extensions.end() && light->second.Has("light"))
                addLight(light->second.Get("light").GetNumberAsInt(), world, what);
            for (int c : node.children) stack.emplace_back(c, world);
        }
    }

    void addMesh(int meshIndex, const glm::dmat4& world, const std::string& where) {
        if (size_t(meshIndex) >= model_.meshes.size())
            throw LoadError(where + ": mesh " + std::to_string(meshIndex) + " does not exist");
        const tinygltf::Mesh& mesh = model_.meshes[size_t(meshIndex)];
        for (size_t p = 0; p < mesh.primitives.size(); ++p)
            addPrimitive(mesh.primitives[p], world,
                         path_ + ": mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p));
    }

    int attribute(const tinygltf::Primitive& prim, const char* name) const {
        auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
    }

    void addPrimitive(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& what) {
        int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode <= TINYGLTF_MODE_LINE_STRIP) {
            ++skippedPrimitives_;
            return;
        }
        if (mode > TINYGLTF_MODE_TRIANGLE_FAN) throw LoadError(what + ": unknown mode " + std::to_string(mode));
        const int F = TINYGLTF_COMPONENT_TYPE_FLOAT, B = TINYGLTF_COMPONENT_TYPE_BYTE,
                  UB = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, S = TINYGLTF_COMPONENT_TYPE_SHORT,
                  US = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        int pos = attribute(prim, "POSITION");
        if (pos < 0) throw LoadError(what + ": has no POSITION attribute");
        // KHR_mesh_quantization allows integer positions, normals and texture coordinates.
        std::vector<float> p = gltf::readFloats(model_, pos, 3, {F, B, UB, S, US}, what + " POSITION");
        size_t n = p.size() / 3;
        std::vector<float> normals, uvs, colors, tangents;
        if (int a = attribute(prim, "NORMAL"); a >= 0) normals = gltf::readFloats(model_, a, 3, {F, B, S}, what + " NORMAL");
        if (int a = attribute(prim, "TANGENT"); a >= 0) tangents = gltf::readFloats(model_, a, 4, {F, B, S}, what + " TANGENT");
        // Texture coordinates: the set the material's textures read (TEXCOORD_0 or _1).
        int colorAccessor = attribute(prim, "COLOR_0");
        uint32_t material = materialFor(prim.material, what, colorAccessor >= 0);
        const std::string uvName = "TEXCOORD_" + std::to_string(uvSetOf(prim.material));
        if (int a = attribute(prim, uvName.c_str()); a >= 0) uvs = gltf::readFloats(model_, a, 2, {F, B, UB, S, US}, what + " " + uvName);
        else if (readsTextures(prim.material))
            throw LoadError(what + ": its material " + std::to_string(prim.material) + " reads textures through " + uvName +
                            ", which the primitive does not have");
        if (colorAccessor >= 0) {
            // VEC3 or VEC4 (its alpha is not used); float or normalized unsigned integers.
            bool rgba = size_t(colorAccessor) < model_.accessors.size() &&
                        model_.accessors[size_t(colorAccessor)].type == TINYGLTF_TYPE_VEC4;
            colors = gltf::readFloats(model_, colorAccessor, rgba ? 4 : 3, {F, UB, US}, what + " COLOR_0");
            if (rgba) {
                size_t count = colors.size() / 4;
                for (size_t i = 0; i < count; ++i) std::copy_n(&colors[4 * i], 3, &colors[3 * i]);
                colors.resize(3 * count);
            }
            // A multiplier of the base colour: bounded as the MTL's Kd is.
            float peak = colors.empty() ? 0.0f : *std::max_element(colors.begin(), colors.end());
            float least = colors.empty() ? 0.0f : *std::min_element(colors.begin(), colors.end());
            if (least < 0.0f || peak > kMaxReflectance)
                throw LoadError(what + " COLOR_0: a component is " + shortNumber(least < 0.0f ? least : peak) +
                                "; vertex colours multiply the base colour and must lie in [0, 10]");
            if (peak > 1.0f)
                warnOnce(warnedBrightColors_, what + " COLOR_0: components above 1 (up to " + shortNumber(peak) +
                                                  ") make the surface reflect more light than it receives");
        }
        if ((!normals.empty() && normals.size() != p.size()) || (!uvs.empty() && uvs.size() / 2 != n) ||
            (!colors.empty() && colors.size() != p.size()) || (!tangents.empty() && tangents.size() != 4 * n))
            throw LoadError(what + ": its attributes have different counts (POSITION has " + std::to_string(n) + ")");

        std::vector<uint32_t> index;
        if (prim.indices >= 0) index = gltf::readIndices(model_, prim.indices, n, what + " indices");
        else {
            index.resize(n);
            for (size_t i = 0; i < n; ++i) index[i] = uint32_t(i);
        }
        std::vector<glm::uvec3> tris;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            for (size_t i = 0; i + 2 < index.size(); i += 3) tris.emplace_back(index[i], index[i + 1], index[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < index.size(); ++i) // every other triangle turned to keep the winding
                tris.push_back(i % 2 ? glm::uvec3(index[i + 1], index[i], index[i + 2])
                                     : glm::uvec3(index[i], index[i + 1], index[i + 2]));
        } else {
            for (size_t i = 1; i + 1 < index.size(); ++i) tris.emplace_back(index[0], index[i], index[i + 1]);
        }
        if (scene_.triPositions.size() + tris.size() > kMaxTriangles)
            throw LoadError(what + ": the scene passes " + std::to_string(kMaxTriangles) + " triangles");
        // Nodes may instance a mesh any number of times: a small file can ask for more triangles
        // than memory holds, which must be refused here rather than by Embree running out.
        double bytes = double(scene_.triPositions.size() + tris.size()) * kBytesPerTriangle;
        if (bytes > 0.5 * physicalMemoryBytes())
            throw LoadError(what + ": with it the scene has " + std::to_string(scene_.triPositions.size() + tris.size()) +
                            " triangles, about " + shortNumber(bytes / 1e9) + " GB to render, more than half this machine's memory");

        // Positions to world space; normals by the inverse transpose. A mirroring transform turns
        // the winding around, so each triangle is turned back to keep it counter-clockwise.
        glm::dmat3 linear(world), normalMatrix = glm::transpose(glm::inverse(linear));
        bool mirrored = glm::determinant(linear) < 0.0;
        uint32_t base = uint32_t(scene_.positions.size());
        for (size_t i = 0; i < n; ++i) {
            glm::dvec4 q = world * glm::dvec4(p[3 * i], p[3 * i + 1], p[3 * i + 2], 1.0);
            Vec3 v(float(q.x), float(q.y), float(q.z));
            if (!(std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate && std::abs(v.z) <= kMaxCoordinate))
                throw LoadError(what + ": vertex " + std::to_string(i) + " lies beyond 1e12 once transformed, "
                                "the largest coordinate pt renders correctly");
            scene_.positions.push_back(v);
        }
        int normalBase = -1, uvBase = -1;
        if (!normals.empty()) {
            normalBase = int(scene_.normals.size());
            for (size_t i = 0; i < n; ++i) {
                // Normalized in double: a normal of (3e38, 3e38, 0) has no float length.
                glm::dvec3 m = normalMatrix * glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
                scene_.normals.push_back(Vec3(unitOrZero(m)));
            }
            if (!anyNormals_) scene_.triNormals.assign(scene_.triPositions.size(), glm::ivec3(-1));
            anyNormals_ = true;
        }
        if (!uvs.empty()) {
            uvBase = int(scene_.uvs.size());
            for (size_t i = 0; i < n; ++i) scene_.uvs.emplace_back(uvs[2 * i], 1.0f - uvs[2 * i + 1]); // glTF's v runs down
            if (!anyUvs_) scene_.triUvs.assign(scene_.triPositions.size(), glm::ivec3(-1));
            anyUvs_ = true;
        }
        if (!tangents.empty() || !scene_.vertexTangents.empty()) {
            // Tangents per position, once any primitive has them (w = 0, none, elsewhere): along
            // the surface, so by the linear part; a mirroring transform flips the handedness.
            scene_.vertexTangents.resize(base, glm::vec4(0.0f));
            for (size_t i = 0; i < n; ++i) {
                if (tangents.empty()) {
                    scene_.vertexTangents.emplace_back(0.0f);
                    continue;
                }
                glm::dvec3 t = linear * glm::dvec3(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
                float w = tangents[4 * i + 3] < 0.0f ? -1.0f : 1.0f;
                if (tangents[4 * i + 3] != 1.0f && tangents[4 * i + 3] != -1.0f)
                    warnOnce(warnedTangentSign_, what + " TANGENT: w is " + shortNumber(tangents[4 * i + 3]) +
                                                     " at vertex " + std::to_string(i) + ", not +1 or -1; taken by its sign (0 as +1)");
                Vec3 unit = Vec3(unitOrZero(t));
                scene_.vertexTangents.emplace_back(unit, unit == Vec3(0.0f) ? 0.0f : (mirrored ? -w : w));
            }
        }
        if (!colors.empty() || !scene_.vertexColors.empty()) {
            // Colours per position, once any primitive has them (white elsewhere).
            scene_.vertexColors.resize(base, Spectrum(1.0f));
            for (size_t i = 0; i < n; ++i)
                scene_.vertexColors.push_back(colors.empty() ? Spectrum(1.0f) : Spectrum(colors[3 * i], colors[3 * i + 1], colors[3 * i + 2]));
        }
        for (glm::uvec3 t : tris) {
            if (mirrored) std::swap(t.y, t.z);
            scene_.triPositions.push_back(t + base);
            // The per-corner index arrays exist once any primitive has normals or uvs (-1 elsewhere).
            if (anyNormals_) scene_.triNormals.push_back(normalBase < 0 ? glm::ivec3(-1) : glm::ivec3(t) + normalBase);
            if (anyUvs_) scene_.triUvs.push_back(uvBase < 0 ? glm::ivec3(-1) : glm::ivec3(t) + uvBase);
            scene_.triMaterial.push_back(material);
        }
    }

    // The scene's texture for glTF texture `index`, decoded as colour (sRGB) or data.
    int texture(int index, bool colour, const std::string& what) {
        if (index < 0 || size_t(index) >= model_.textures.size())
            throw LoadError(what + ": texture " + std::to_string(index) + " does not exist");
        int image = model_.textures[size_t(index)].source;
        if (image < 0 || size_t(image) >= model_.images.size())
            throw LoadError(what + ": texture " + std::to_string(index) + " has no image (source " + std::to_string(image) + ")");
        auto key = std::make_pair(image, colour);
        if (auto it = decoded_.find(key); it != decoded_.end()) return it->second;
        const tinygltf::Image& img = model_.images[size_t(image)];
        // tinygltf keeps the URI of a file image only (a data URI's bytes came through keepImageBytes).
        bool inFile = img.bufferView < 0 && !img.uri.empty() && img.uri.rfind("data:", 0) != 0;
        std::string name = inFile ? (std::filesystem::path(path_).parent_path() / decodeUri(img.uri)).string()
                                  : path_ + " image " + std::to_string(image);
        std::string format = img.mimeType == "image/jpeg" ? ".jpg" : img.mimeType == "image/png" ? ".png" : "";
        if (format.empty()) {
            std::string ext = std::filesystem::path(img.uri).extension().string();
            format = ext.empty() ? ".png" : ext;
        }
        Texture t;
        std::string error;
        bool tooLarge, read;
        double budget = textureMemoryBudget() - scene_.textures->bytes();
        if (size_t(image) < images_.size() && !images_[size_t(image)].empty()) // bytes tinygltf decoded (a data URI)
            read = readTextureFromMemory(images_[size_t(image)], name, format, colour, t, error, budget, tooLarge);
        else if (img.bufferView >= 0)
            read = readTextureFromMemory(gltf::bufferViewBytes(model_, img.bufferView, what + ", image " + std::to_string(image)),
                                         name, format, colour, t, error, budget, tooLarge);
        else if (inFile)
            read = readTexture(name, colour, t, error, budget, tooLarge); // the file's bytes, hashed
        else
            throw LoadError(what + ": image " + std::to_string(image) + " has no data");
        if (!read) throw LoadError(what + ": image " + std::to_string(image) + ": " + error);
        if (t.sourceHash != 0) scene_.sources.push_back({name, t.sourceHash});
        int cached = scene_.textures->add(std::move(t));
        decoded_[key] = cached;
        return cached;
    }

    // A texture reference inside a material extension (a JSON object, not tinygltf's TextureInfo):
    // an unused map where `key` is absent. A normal texture's scale becomes bumpScale.
    TextureMap extensionTexture(const tinygltf::Value& ext, const char* key, const std::string& what, bool colour = false) {
        if (!ext.Has(key)) return TextureMap{};
        const tinygltf::Value& info = ext.Get(key);
        tinygltf::ExtensionMap extensions;
        if (info.Has("extensions"))
            for (const std::string& name : info.Get("extensions").Keys()) extensions[name] = info.Get("extensions").Get(name);
        int texCoord = info.Has("texCoord") ? info.Get("texCoord").GetNumberAsInt() : 0;
        TextureMap map = textureMap(info.Get("index").GetNumberAsInt(), texCoord, extensions, colour, what);
        if (info.Has("scale")) map.bumpScale = normalScale(info.Get("scale").GetNumberAsDouble(), what + ": scale");
        return map;
    }

    // A map that reads its texture's alpha, as the extensions' A-channel textures do; a texture
    // without alpha has alpha 1 everywhere, so the map is dropped and its factor alone applies.
    TextureMap alphaOf(TextureMap map) const {
        if (!map.used() || !(*scene_.textures)[map.texture].hasAlpha()) return TextureMap{};
        map.channel = TextureChannel::Alpha;
        return map;
    }

    // A normal map needs three channels (x, y, z): one of one or two (grey, grey and alpha) is
    // dropped with a warning naming it, as the MTL's norm does, instead of being read past its texels.
    TextureMap normalMapOf(TextureMap map, const std::string& what) {
        if (!map.used()) return map;
        const Texture& t = (*scene_.textures)[map.texture];
        if (t.channels >= 3) return map; // RGB, or RGB and alpha
        warnings_.add(what + ": image \"" + t.path + "\" has " + std::to_string(t.channels) + " channel" +
                      (t.channels == 1 ? "" : "s") + (t.hasAlpha() ? " (grey and alpha)" : " (grey)") +
                      "; a normal map needs RGB, so it is ignored and the surface keeps its interpolated normals");
        return TextureMap{};
    }

    // A normal texture's scale, refused (naming it as `label`) where the perturbed normal's length
    // would overflow float.
    static float normalScale(double scale, const std::string& label) {
        if (!(std::abs(scale) <= kMaxNormalScale))
            throw LoadError(label + " " + shortNumber(scale) + " is beyond +-1e6, where the perturbed normal's length "
                            "overflows float");
        return float(scale);
    }

    // A texture reference with its sampler's wrap modes and KHR_texture_transform (in pt's uv,
    // whose v runs up where glTF's runs down: setGltfTransform).
    TextureMap textureMap(int index, int texCoord, const tinygltf::ExtensionMap& extensions, bool colour,
                          const std::string& what) {
        TextureMap map;
        map.texture = texture(index, colour, what);
        const tinygltf::Texture& tex = model_.textures[size_t(index)];
        if (tex.sampler >= 0 && size_t(tex.sampler) < model_.samplers.size()) {
            const tinygltf::Sampler& s = model_.samplers[size_t(tex.sampler)];
            map.wrapU = wrapOf(s.wrapS);
            map.wrapV = wrapOf(s.wrapT);
        }
        Vec2 offset(0.0f), scale(1.0f);
        float rotation = 0.0f;
        auto t = extensions.find("KHR_texture_transform");
        if (t != extensions.end()) {
            const tinygltf::Value& v = t->second;
            if (v.Has("offset") && v.Get("offset").ArrayLen() == 2)
                offset = Vec2(float(v.Get("offset").Get(0).GetNumberAsDouble()), float(v.Get("offset").Get(1).GetNumberAsDouble()));
            if (v.Has("scale") && v.Get("scale").ArrayLen() == 2)
                scale = Vec2(float(v.Get("scale").Get(0).GetNumberAsDouble()), float(v.Get("scale").Get(1).GetNumberAsDouble()));
            if (v.Has("rotation")) rotation = float(v.Get("rotation").GetNumberAsDouble());
            if (v.Has("texCoord")) texCoord = v.Get("texCoord").GetNumberAsInt();
        }
        // One set of texture coordinates per material: the first texture's (0 or 1) serves all.
        if (texCoord < 0 || texCoord > 1) {
            warnOnce(warnedTexCoord_, what + ": TEXCOORD_" + std::to_string(texCoord) + " is not supported (0 and 1 are); "
                                      "TEXCOORD_0 is used");
            texCoord = 0;
        }
        if (materialUvSet_ < 0) materialUvSet_ = texCoord;
        else if (texCoord != materialUvSet_)
            warnOnce(warnedMixedSets_, what + ": reads TEXCOORD_" + std::to_string(texCoord) + " where the material's other "
                                       "textures read TEXCOORD_" + std::to_string(materialUvSet_) + "; those are used");
        if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(scale.x) || !std::isfinite(scale.y) ||
            !std::isfinite(rotation))
            throw LoadError(what + ": KHR_texture_transform has a value that is not finite");
        setGltfTransform(map, offset, rotation, scale);
        return map;
    }

    // A 1 x 1 data texture of value 1, so that a constant coverage goes through the cutout path.
    int constantTexture() {
        if (constant_ < 0) {
            Texture t = Texture::fromFloats(1, 1, 1, {1.0f}, false);
            t.path = path_ + " (constant coverage)";
            constant_ = scene_.textures->add(std::move(t));
        }
        return constant_;
    }

    // The scene's material for glTF material `index` (-1: the default), a copy that multiplies
    // its base colour by COLOR_0 where the primitive has vertex colours.
    uint32_t materialFor(int index, const std::string& where, bool vertexColors) {
        uint32_t plain = plainMaterialFor(index, where);
        if (!vertexColors) return plain;
        auto [it, isNew] = withColors_.try_emplace(plain, uint32_t(scene_.materials.size()));
        if (isNew) {
            Material m = scene_.materials[plain];
            m.vertexColors = true;
            scene_.materials.push_back(m);
        }
        return it->second;
    }

    // The texture coordinate set (0 or 1) that material `index`'s textures read.
    int uvSetOf(int index) const { return index >= 0 && size_t(index) < uvSet_.size() ? uvSet_[size_t(index)] : 0; }
    // Whether material `index` has a texture (and so needs that set).
    bool readsTextures(int index) const { return index >= 0 && size_t(index) < uvSet_.size() && readsTextures_[size_t(index)]; }

    uint32_t plainMaterialFor(int index, const std::string& where) {
        if (index < 0) {
            if (defaultMaterial_ == ~0u) {
                // The specification's default material: white, metallic 1, roughness 1.
                Material m;
                m.name = "default";
                m.model = MaterialModel::MetalRough;
                m.kd = Spectrum(1.0f);
                m.metallic = 1.0f;
                m.roughnessAlpha = 1.0f;
                m.eta = 1.5f;
                defaultMaterial_ = uint32_t(scene_.materials.size());
                scene_.materials.push_back(m);
            }
            return defaultMaterial_;
        }
        if (size_t(index) >= model_.materials.size())
            throw LoadError(where + ": material " + std::to_string(index) + " does not exist");
        if (materialOf_[size_t(index)] != ~0u) return materialOf_[size_t(index)];
        materialUvSet_ = -1;
        const tinygltf::Material& g = model_.materials[size_t(index)];
        std::string what = path_ + ": material " + std::to_string(index) + (g.name.empty() ? "" : " \"" + g.name + "\"");
        const auto& pbr = g.pbrMetallicRoughness;
        Material m;
        m.name = g.name.empty() ? "material " + std::to_string(index) : g.name;
        m.model = MaterialModel::MetalRough;
        m.kd = colorOf(pbr.baseColorFactor, Spectrum(1.0f));
        float opacity = pbr.baseColorFactor.size() == 4 ? float(pbr.baseColorFactor[3]) : 1.0f;
        float metallic = float(pbr.metallicFactor), roughness = float(pbr.roughnessFactor);
        auto unit = [&](float v, const char* name) {
            if (!(v >= 0.0f && v <= 1.0f)) throw LoadError(what + ": " + name + " " + shortNumber(v) + " is outside [0, 1]");
            return v;
        };
        for (int c = 0; c < 3; ++c) unit(m.kd[c], "baseColorFactor");
        m.metallic = unit(metallic, "metallicFactor");
        m.roughnessAlpha = sqr(unit(roughness, "roughnessFactor")); // alpha
        unit(opacity, "baseColorFactor's alpha");
        m.eta = 1.5f;
        if (auto ior = g.extensions.find("KHR_materials_ior"); ior != g.extensions.end() && ior->second.Has("ior")) {
            m.eta = float(ior->second.Get("ior").GetNumberAsDouble());
            if (!(m.eta >= 1.0f && m.eta <= 10.0f)) throw LoadError(what + ": KHR_materials_ior ior " + shortNumber(m.eta) + " is outside [1, 10]");
        }
        if (auto e = g.extensions.find("KHR_materials_specular"); e != g.extensions.end()) {
            std::string ext = what + " KHR_materials_specular";
            m.specular = extensionNumber(e->second, "specularFactor", 1.0f);
            m.ks = extensionColor(e->second, "specularColorFactor", Spectrum(1.0f));
            if (!(maxComponent(m.ks) <= 1e6f))
                throw LoadError(ext + ": specularColorFactor " + shortNumber(maxComponent(m.ks)) + " is beyond 1e6, pt's limit");
            m.specularMap = alphaOf(extensionTexture(e->second, "specularTexture", ext + " specularTexture"));
            m.ksMap = extensionTexture(e->second, "specularColorTexture", ext + " specularColorTexture", true);
        }
        if (auto e = g.extensions.find("KHR_materials_clearcoat"); e != g.extensions.end()) {
            // Ranges and texture indices were checked with the document (gltf_document.cpp).
            std::string ext = what + " KHR_materials_clearcoat";
            m.clearcoat = extensionNumber(e->second, "clearcoatFactor", 0.0f);
            m.clearcoatAlpha = sqr(extensionNumber(e->second, "clearcoatRoughnessFactor", 0.0f));
            if (m.clearcoat > 0.0f) {
                m.clearcoatMap = extensionTexture(e->second, "clearcoatTexture", ext + " clearcoatTexture");
                m.clearcoatMap.channel = TextureChannel::R;
                m.clearcoatRoughnessMap = extensionTexture(e->second, "clearcoatRoughnessTexture", ext + " clearcoatRoughnessTexture");
                m.clearcoatRoughnessMap.channel = TextureChannel::G;
                m.clearcoatNormalMap = normalMapOf(extensionTexture(e->second, "clearcoatNormalTexture", ext + " clearcoatNormalTexture"),
                                                   ext + " clearcoatNormalTexture");
            }
        }
        if (auto e = g.extensions.find("KHR_materials_sheen"); e != g.extensions.end()) {
            // Ranges and texture indices were checked with the document.
            std::string ext = what + " KHR_materials_sheen";
            m.sheenColor = extensionColor(e->second, "sheenColorFactor", Spectrum(0.0f));
            m.sheenRoughness = extensionNumber(e->second, "sheenRoughnessFactor", 0.0f);
            if (maxComponent(m.sheenColor) > 0.0f) {
                m.sheenColorMap = extensionTexture(e->second, "sheenColorTexture", ext + " sheenColorTexture", true);
                m.sheenRoughnessMap = alphaOf(extensionTexture(e->second, "sheenRoughnessTexture", ext + " sheenRoughnessTexture"));
            }
        }
        if (auto e = g.extensions.find("KHR_materials_transmission"); e != g.extensions.end()) {
            std::string ext = what + " KHR_materials_transmission";
            m.transparency = extensionNumber(e->second, "transmissionFactor", 0.0f);
            if (m.transparency > 0.0f) {
                m.transmissionMap = extensionTexture(e->second, "transmissionTexture", ext + " transmissionTexture");
                m.transmissionMap.channel = TextureChannel::R;
            }
        }
        if ((m.clearcoat > 0.0f || maxComponent(m.sheenColor) > 0.0f) && m.transparency > 0.0f)
            warnOnce(warnedCoatOnTransmission_, what + ": KHR_materials_clearcoat and KHR_materials_sheen on a transmitting "
                                                       "material are ignored (pt's transmission is the lab's refraction "
                                                       "tree, without a coat or sheen)");
        if (auto e = g.extensions.find("KHR_materials_volume"); e != g.extensions.end() && m.transparency > 0.0f) {
            // Ranges were checked with the document. A thickness above 0 makes the mesh a volume's
            // boundary; the thickness itself (and its texture) serves renderers without the
            // geometry: pt measures the distance a path travels inside.
            m.volume = extensionNumber(e->second, "thicknessFactor", 0.0f) > 0.0f;
            float distance = extensionNumber(e->second, "attenuationDistance", kInf);
            Spectrum color = extensionColor(e->second, "attenuationColor", Spectrum(1.0f));
            if (m.volume && distance < kInf)
                for (int c = 0; c < 3; ++c) m.attenuation[c] = std::min(-std::log(std::max(color[c], 1e-6f)) / distance, 1e30f);
        }
        if (m.transparency > 0.0f && !m.volume)
            warnOnce(warnedThinWalled_, what + ": without KHR_materials_volume (or with thicknessFactor 0) the surface is "
                                               "thin-walled: light passes through it unbent (Blender's importer refracts "
                                               "it with the ior instead)");
        if (pbr.baseColorTexture.index >= 0)
            m.kdMap = textureMap(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions,
                                 true, what + " baseColorTexture");
        if (pbr.metallicRoughnessTexture.index >= 0) {
            const auto& info = pbr.metallicRoughnessTexture;
            m.roughnessMap = textureMap(info.index, info.texCoord, info.extensions, false, what + " metallicRoughnessTexture");
            m.roughnessMap.channel = TextureChannel::G;
            m.metallicMap = m.roughnessMap;
            m.metallicMap.channel = TextureChannel::B;
        }
        if (g.normalTexture.index >= 0) {
            m.normalMap = textureMap(g.normalTexture.index, g.normalTexture.texCoord, g.normalTexture.extensions, false,
                                     what + " normalTexture");
            m.normalMap.bumpScale = normalScale(g.normalTexture.scale, what + ": normalTexture.scale");
            m.normalMap = normalMapOf(m.normalMap, what + " normalTexture");
        }
        float strength = 1.0f;
        if (auto e = g.extensions.find("KHR_materials_emissive_strength");
            e != g.extensions.end() && e->second.Has("emissiveStrength"))
            strength = float(e->second.Get("emissiveStrength").GetNumberAsDouble());
        if (!(strength >= 0.0f && strength <= 1e12f)) throw LoadError(what + ": emissiveStrength " + shortNumber(strength) + " is out of range");
        m.emission = colorOf(g.emissiveFactor, Spectrum(0.0f)) * strength;
        if (!(m.emission.x >= 0.0f && m.emission.y >= 0.0f && m.emission.z >= 0.0f) || !isFinite(m.emission))
            throw LoadError(what + ": emissiveFactor must be finite and not negative");
        if (maxComponent(m.emission) > kMaxRadiance)
            throw LoadError(what + ": emission " + shortNumber(maxComponent(m.emission)) +
                            " is beyond 1e18, where samples and their variance overflow float");
        if (g.emissiveTexture.index >= 0 && m.isEmissive())
            m.emissionMap = textureMap(g.emissiveTexture.index, g.emissiveTexture.texCoord, g.emissiveTexture.extensions,
                                       true, what + " emissiveTexture");

        // KHR_materials_unlit: the base colour alone, seen by camera rays only (the rest of the
        // material is not used; it neither lights nor shadows anything).
        if (g.extensions.count("KHR_materials_unlit")) {
            m.unlit = true;
            m.emission = Spectrum(0.0f);
            m.emissionMap = TextureMap{};
        }
        // Coverage: MASK cuts at alphaCutoff, BLEND is stochastic (rays pass 1 - alpha of the time).
        std::string mode = g.alphaMode.empty() ? "OPAQUE" : g.alphaMode;
        if (mode == "MASK" || mode == "BLEND") {
            m.coverage = opacity;
            if (mode == "MASK") m.alphaCutoff = float(g.alphaCutoff);
            if (pbr.baseColorTexture.index >= 0 &&
                (*scene_.textures)[texture(pbr.baseColorTexture.index, false, what + " baseColorTexture")].hasAlpha()) {
                m.alphaMap = textureMap(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                        pbr.baseColorTexture.extensions, false, what + " baseColorTexture");
                m.alphaMap.channel = TextureChannel::Alpha;
            } else if (mode == "BLEND" ? opacity < 1.0f : opacity < m.alphaCutoff) {
                m.alphaMap.texture = constantTexture();
            }
        }
        uvSet_[size_t(index)] = std::max(0, materialUvSet_);
        readsTextures_[size_t(index)] = materialUvSet_ >= 0;
        materialOf_[size_t(index)] = uint32_t(scene_.materials.size());
        scene_.materials.push_back(m);
        return materialOf_[size_t(index)];
    }

    void addCamera(int index, const glm::dmat4& world, const std::string& where) {
        if (size_t(index) >= model_.cameras.size())
            throw LoadError(where + ": camera " + std::to_string(index) + " does not exist");
        const tinygltf::Camera& g = model_.cameras[size_t(index)];
        std::string what = path_ + ": camera " + std::to_string(index);
        Camera c;
        c.name = g.name.empty() ? "camera " + std::to_string(index) : g.name;
        glm::dvec3 eye(world * glm::dvec4(0, 0, 0, 1)), ahead(world * glm::dvec4(0, 0, -1, 0)), up(world * glm::dvec4(0, 1, 0, 0));
        if (!(glm::length(ahead) > 0.0) || !(glm::length(glm::cross(ahead, up)) > 0.0))
            throw LoadError(what + ": its node's transform collapses the view direction");
        c.position = Vec3(eye);
        c.target = Vec3(eye + glm::normalize(ahead));
        c.up = Vec3(glm::normalize(up));
        if (g.type == "perspective") {
            double fov = g.perspective.yfov * 180.0 / M_PI;
            if (!(fov > 0.0 && fov < 180.0)) throw LoadError(what + ": yfov " + shortNumber(g.perspective.yfov) + " must be in (0, pi)");
            c.fovY = float(fov);
            if (g.perspective.aspectRatio > 0.0) c.aspect = aspectOf(c, g.perspective.aspectRatio);
        } else { // orthographic: gltf_document allows no other type
            double ymag = std::abs(g.orthographic.ymag), xmag = std::abs(g.orthographic.xmag);
            if (!(ymag > 0.0 && xmag > 0.0)) throw LoadError(what + ": xmag and ymag must not be zero");
            // A value float loses (to 0, which means "not orthographic", or to a denormal) meets
            // checkCamera's rule here, named as the file gives it.
            if (float h = float(ymag); !(std::isnormal(h) && h <= kMaxCoordinate))
                throw LoadError(path_ + ": camera \"" + c.name + "\": " + orthoHalfHeightProblem(ymag, c.position));
            c.orthoHalfHeight = float(ymag);
            c.aspect = aspectOf(c, xmag / ymag);
        }
        scene_.cameras.push_back(c);
    }

    // A camera's aspect ratio, checked in double: one that float rounds to 0 (which means "none
    // given") or to infinity is refused as any other outside the range.
    float aspectOf(const Camera& c, double aspect) const {
        if (!(aspect >= 1.0 / kMaxAspect && aspect <= kMaxAspect))
            throw LoadError(path_ + ": camera \"" + c.name + "\": its aspect ratio " + shortNumber(aspect) +
                            " is outside [1/65536, 65536]");
        return float(aspect);
    }

    void addLight(int index, const glm::dmat4& world, const std::string& where) {
        if (index < 0 || size_t(index) >= model_.lights.size())
            throw LoadError(where + ": light " + std::to_string(index) + " does not exist");
        const tinygltf::Light& g = model_.lights[size_t(index)];
        std::string what = path_ + ": light " + std::to_string(index) + (g.name.empty() ? "" : " \"" + g.name + "\"");
        Spectrum color = colorOf(g.color, Spectrum(1.0f)); // in [0, 1], as gltf_document checked
        if (!(g.intensity < 1e15)) throw LoadError(what + ": intensity " + shortNumber(g.intensity) + " is beyond 1e15, pt's limit");
        glm::dvec3 at(world * glm::dvec4(0, 0, 0, 1)), ahead(world * glm::dvec4(0, 0, -1, 0));
        if (g.type == "directional") {
            if (!(glm::length(ahead) > 0.0)) throw LoadError(what + ": its node's transform collapses its direction");
            DirectionalLight d;
            d.name = g.name;
            d.direction = Vec3(glm::normalize(-ahead)); // towards the light
            d.irradiance = color * float(g.intensity / kLumensPerWatt); // lux to W/m^2
            scene_.directionalLights.push_back(d);
            return;
        }
        LocalLight l;
        l.name = "light " + std::to_string(index) + (g.name.empty() ? "" : " " + g.name);
        l.center = Vec3(at);
        l.radius = 0.0f;
        l.intensity = color * float(g.intensity / kLumensPerWatt); // candela to W/sr
        l.range = float(g.range);
        if (g.range > 0.0 && !(l.range > 0.0f && std::isfinite(l.range)))
            throw LoadError(what + ": range " + shortNumber(g.range) + " underflows float (0 would mean no range)");
        l.source = path_ + ": ";
        l.intensityKeyword = "intensity";
        if (g.type == "spot") {
            double inner = g.spot.innerConeAngle, outer = g.spot.outerConeAngle;
            if (!(inner >= 0.0 && inner < outer && outer <= M_PI / 2))
                throw LoadError(what + ": spot cone angles must satisfy 0 <= inner < outer <= pi/2");
            if (!(glm::length(ahead) > 0.0)) throw LoadError(what + ": its node's transform collapses its direction");
            l.spotDirection = Vec3(glm::normalize(ahead));
            l.cosInner = float(std::cos(inner));
            l.cosOuter = float(std::cos(outer));
            // In float the cone must still be a cone: a narrower one is a point light in disguise.
            if (!(l.cosOuter < l.cosInner))
                throw LoadError(what + ": spot cone angles " + shortNumber(inner) + " and " + shortNumber(outer) +
                                " have the same cosine in float; make the outer cone wider");
        }
        scene_.lights.push_back(l);
    }

    const std::string& path_;
    const Model& model_;
    std::vector<std::vector<unsigned char>>& images_;
    Scene& scene_;
    Warnings& warnings_;
    std::vector<uint32_t> materialOf_;
    std::map<uint32_t, uint32_t> withColors_; // a material's copy for primitives with COLOR_0
    std::vector<int> uvSet_;                   // per glTF material, the TEXCOORD set its textures read
    std::vector<char> readsTextures_;          // per glTF material, whether it has any texture
    int materialUvSet_ = -1;                   // while a material is read: its textures' set so far
    uint32_t defaultMaterial_ = ~0u;
    std::vector<char> visited_;
    std::map<std::pair<int, bool>, int> decoded_;
    int constant_ = -1;
    size_t skippedPrimitives_ = 0;
    bool warnedColor_ = false, warnedTexCoord_ = false, warnedBrightColors_ = false,
         warnedTangentSign_ = false;
    bool warnedMixedSets_ = false, warnedThinWalled_ = false,
         warnedCoatOnTransmission_ = false;
    void warnOnce(bool& warned, const std::string& message) {
        if (!warned) warnings_.add(message);
        warned = true;
    }
    bool anyNormals_ = false, anyUvs_ = false;
};

} // namespace

bool gltfExtensionSupported(const std::string& name) {
    return std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), name) != std::end(kSupportedExtensions);
}

Scene loadGltf(const std::string& path, Warnings& warnings) {
    std::vector<unsigned char> bytes;
    // A glTF file's own length fields are 32-bit: a .glb cannot pass 4 GB.
    uint64_t limit = std::min<uint64_t>(uint64_t(0.5 * physicalMemoryBytes()), 0xffffffffu);
    if (std::string error = readRegularFile(path, limit, bytes); !error.empty()) throw LoadError(path + ": " + error);
    // A .glb by its magic, not its name: a binary file saved as .gltf loads as well.
    bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    return loadGltfFromMemory(path, bytes, binary, warnings);
}

Scene loadGltfFromMemory(const std::string& path, const std::vector<unsigned char>& bytes, bool binary,
                         Warnings& warnings) {
    if (bytes.size() > 0xffffffffu) throw LoadError(path + ": larger than the 4 GB a glTF file can address");
    gltf::DocumentFacts facts = gltf::checkGltfDocument(gltf::gltfJson(bytes, binary, path), binary, path);
    // Each buffer's file, looked at before tinygltf reads it: a regular file of the declared size,
    // and all of them within half the memory. (The callbacks below refuse anything else again.)
    std::vector<uint64_t> lengths;
    double total = 0.0;
    for (const auto& b : facts.fileBuffers) {
        std::string file = (std::filesystem::path(path).parent_path() / decodeUri(b.uri)).string();
        std::string what = path + ": buffer " + std::to_string(b.index) + ": \"" + file + "\" ";
        struct stat st {};
        if (stat(file.c_str(), &st) != 0) throw LoadError(what + "cannot be opened: " + std::strerror(errno));
        if (!S_ISREG(st.st_mode)) throw LoadError(what + "is not a regular file (a folder, device or pipe)");
        if (uint64_t(st.st_size) != b.length)
            throw LoadError(what + "has " + std::to_string(st.st_size) + " bytes; its byteLength says " + std::to_string(b.length));
        if ((total += double(b.length)) > 0.5 * physicalMemoryBytes())
            throw LoadError(what + "brings the buffers to " + shortNumber(total / 1e9) + " GB, more than half this machine's memory");
        lengths.push_back(b.length);
    }
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::vector<std::vector<unsigned char>> images;
    loader.SetImageLoader(keepImageBytes, &images);
    std::string base = std::filesystem::path(path).parent_path().string();
    if (base.empty()) base = ".";
    ExternalFiles files{base, lengths, uint64_t(0.5 * physicalMemoryBytes()), {}};
    loader.SetFsCallbacks(tinygltf::FsCallbacks{externalFileExists, pathAsGiven, readExternalFile, writeNothing, &files});
    std::string err, warn;
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base)
                    : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                 unsigned(bytes.size()), base);
    } catch (const std::exception& e) {
        throw LoadError(path + ": not a valid glTF file: " + e.what());
    }
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
        throw LoadError(path + ": " + (err.empty() ? "cannot be read as glTF" : err));
    }
    for (const std::string& e : model.extensionsRequired)
        if (!gltfExtensionSupported(e))
            throw LoadError(path + ": requires the extension " + e + ", which pt does not support");
    for (const std::string& e : model.extensionsUsed)
        if (!gltfExtensionSupported(e))
            warnings.add(path + ": uses the extension " + e + ", which pt ignores");

    Scene scene;
    scene.path = path;
    scene.sources.push_back({path, contentHash(bytes.data(), bytes.size())});
    scene.sources.insert(scene.sources.end(), files.read.begin(), files.read.end());
    GltfReader(path, model, images, scene, warnings).read();
    return scene;
}

} // namespace pt
