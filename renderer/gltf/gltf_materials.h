// glTF materials into pt's Material (MaterialModel::MetalRough): the core metallic-roughness
// factors and textures, the KHR_materials_* extensions pt implements, alpha modes as coverage,
// and the textures they read, decoded once each (as colour or as data) by OpenImageIO.
#pragma once

#include "io/load_error.h"
#include "scene/scene.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pt::gltf {

class GltfMaterials {
public:
    // `images`: the bytes of data-URI images, by image index (gltf_file.h).
    GltfMaterials(const std::string& path, const tinygltf::Model& model, std::vector<std::vector<unsigned char>>& images,
                  Scene& scene, Warnings& warnings)
        : path_(path), model_(model), images_(images), scene_(scene), warnings_(warnings),
          materialOf_(model.materials.size(), ~0u), uvSet_(model.materials.size(), 0),
          readsTextures_(model.materials.size(), 0) {}

    // The scene's material for glTF material `index` (-1: the default), a copy that multiplies
    // its base colour by COLOR_0 where the primitive has vertex colours. Read on first use.
    uint32_t materialFor(int index, const std::string& where, bool vertexColors);
    // The texture coordinate set (0 or 1) that material `index`'s textures read (after materialFor).
    int uvSetOf(int index) const { return index >= 0 && size_t(index) < uvSet_.size() ? uvSet_[size_t(index)] : 0; }
    // Whether material `index` has a texture (and so needs that set).
    bool readsTextures(int index) const { return index >= 0 && size_t(index) < uvSet_.size() && readsTextures_[size_t(index)]; }

private:
    uint32_t plainMaterialFor(int index, const std::string& where);
    int texture(int index, bool colour, const std::string& what);
    TextureMap textureMap(int index, int texCoord, const tinygltf::ExtensionMap& extensions, bool colour,
                          const std::string& what);
    TextureMap extensionTexture(const tinygltf::Value& ext, const char* key, const std::string& what, bool colour = false);
    TextureMap alphaOf(TextureMap map) const;
    TextureMap normalMapOf(TextureMap map, const std::string& what);
    static float normalScale(double scale, const std::string& label);
    int constantTexture();
    void warnOnce(bool& warned, const std::string& message) {
        if (!warned) warnings_.add(message);
        warned = true;
    }

    const std::string& path_;
    const tinygltf::Model& model_;
    std::vector<std::vector<unsigned char>>& images_;
    Scene& scene_;
    Warnings& warnings_;
    std::vector<uint32_t> materialOf_;
    std::map<uint32_t, uint32_t> withColors_; // a material's copy for primitives with COLOR_0
    std::vector<int> uvSet_;                   // per glTF material, the TEXCOORD set its textures read
    std::vector<char> readsTextures_;          // per glTF material, whether it has any texture
    int materialUvSet_ = -1;                   // while a material is read: its textures' set so far
    uint32_t defaultMaterial_ = ~0u;
    std::map<std::pair<int, bool>, int> decoded_; // (image, as colour) -> the scene's texture
    int constant_ = -1;
    bool warnedTexCoord_ = false, warnedMixedSets_ = false, warnedThinWalled_ = false, warnedCoatOnTransmission_ = false;
};

} // namespace pt::gltf
