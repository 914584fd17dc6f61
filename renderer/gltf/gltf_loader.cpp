// The glTF loader's own job: the node hierarchy, flattened into the scene's world-space triangles
// with their attributes. The file policy is gltf_file.cpp, materials and textures
// gltf_materials.cpp, cameras and lights gltf_cameras_lights.cpp.
#include "gltf/gltf_loader.h"

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_cameras_lights.h"
#include "gltf/gltf_file.h"
#include "gltf/gltf_materials.h"
#include "core/math.h"
#include "core/system.h"
#include "io/input_file.h"
#include "io/scene_limits.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pt {
namespace {

using tinygltf::Model;

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

// v / |v| in double, or 0 for a zero vector.
glm::dvec3 unitOrZero(const glm::dvec3& v) {
    double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? v / length : glm::dvec3(0.0);
}


class GltfReader {
public:
    GltfReader(const std::string& path, const Model& model, std::vector<std::vector<unsigned char>>& images, Scene& scene,
               Warnings& warnings)
        : path_(path), model_(model), scene_(scene), warnings_(warnings), materials_(path, model, images, scene, warnings) {}

    void read() {
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
            if (node.camera >= 0) gltf::addCamera(model_, path_, node.camera, world, what, scene_);
            auto light = node.extensions.find("KHR_lights_punctual");
            if (light != node.extensions.end() && light->second.Has("light"))
                gltf::addLight(model_, path_, light->second.Get("light").GetNumberAsInt(), world, what, scene_);
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
        uint32_t material = materials_.materialFor(prim.material, what, colorAccessor >= 0);
        const std::string uvName = "TEXCOORD_" + std::to_string(materials_.uvSetOf(prim.material));
        if (int a = attribute(prim, uvName.c_str()); a >= 0) uvs = gltf::readFloats(model_, a, 2, {F, B, UB, S, US}, what + " " + uvName);
        else if (materials_.readsTextures(prim.material))
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

    const std::string& path_;
    const Model& model_;
    Scene& scene_;
    Warnings& warnings_;
    gltf::GltfMaterials materials_;
    std::vector<char> visited_;
    size_t skippedPrimitives_ = 0;
    bool warnedBrightColors_ = false, warnedTangentSign_ = false;
    void warnOnce(bool& warned, const std::string& message) {
        if (!warned) warnings_.add(message);
        warned = true;
    }
    bool anyNormals_ = false, anyUvs_ = false;
};

} // namespace

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
    gltf::GltfFile file = gltf::readGltfFile(path, bytes, binary, warnings);
    Scene scene;
    scene.path = path;
    scene.sources.push_back({path, contentHash(bytes.data(), bytes.size())});
    scene.sources.insert(scene.sources.end(), file.buffers.begin(), file.buffers.end());
    GltfReader(path, file.model, file.images, scene, warnings).read();
    return scene;
}

} // namespace pt
