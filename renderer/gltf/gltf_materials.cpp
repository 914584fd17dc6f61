#include "gltf/gltf_materials.h"
#include "gltf/gltf_accessors.h"
#include "gltf/gltf_cameras_lights.h"
#include "gltf/gltf_file.h"
#include "core/math.h"
#include "core/system.h"
#include "io/scene_limits.h"
#include "texture/texture_io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace pt::gltf {
namespace {

// A sampler's wrapS or wrapT (the document check allows only these three values).
TextureWrap wrapOf(int mode) {
    if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::Clamp;
    if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::Mirror;
    return TextureWrap::Repeat;
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

} // namespace

// The scene's texture for glTF texture `index`, decoded as colour (sRGB) or data.
int GltfMaterials::texture(int index, bool colour, const std::string& what) {
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
TextureMap GltfMaterials::extensionTexture(const tinygltf::Value& ext, const char* key, const std::string& what, bool colour) {
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
TextureMap GltfMaterials::alphaOf(TextureMap map) const {
    if (!map.used() || !(*scene_.textures)[map.texture].hasAlpha()) return TextureMap{};
    map.channel = TextureChannel::Alpha;
    return map;
}

// A normal map needs three channels (x, y, z): one of one or two (grey, grey and alpha) is
// dropped with a warning naming it, as the MTL's norm does, instead of being read past its texels.
TextureMap GltfMaterials::normalMapOf(TextureMap map, const std::string& what) {
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
float GltfMaterials::normalScale(double scale, const std::string& label) {
    if (!(std::abs(scale) <= kMaxNormalScale))
        throw LoadError(label + " " + shortNumber(scale) + " is beyond +-1e6, where the perturbed normal's length "
                        "overflows float");
    return float(scale);
}

// A texture reference with its sampler's wrap modes and KHR_texture_transform (in pt's uv,
// whose v runs up where glTF's runs down: setGltfTransform).
TextureMap GltfMaterials::textureMap(int index, int texCoord, const tinygltf::ExtensionMap& extensions, bool colour,
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
int GltfMaterials::constantTexture() {
    if (constant_ < 0) {
        Texture t = Texture::fromFloats(1, 1, 1, {1.0f}, false);
        t.path = path_ + " (constant coverage)";
        constant_ = scene_.textures->add(std::move(t));
    }
    return constant_;
}

// The scene's material for glTF material `index` (-1: the default), a copy that multiplies
// its base colour by COLOR_0 where the primitive has vertex colours.
uint32_t GltfMaterials::materialFor(int index, const std::string& where, bool vertexColors) {
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


uint32_t GltfMaterials::plainMaterialFor(int index, const std::string& where) {
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
            m.singleSided = true; // as every material that does not say doubleSided
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
    m.singleSided = !g.doubleSided;
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

} // namespace pt::gltf
