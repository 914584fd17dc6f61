#include "gltf/gltf_document.h"

#include "core/system.h"
#include "io/load_error.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>

namespace pt::gltf {
namespace {

using Json = nlohmann::json;

constexpr double kPiOver2 = 1.57079632679489661923;
// Counts and byte offsets: 64-bit in tinygltf, but nothing pt can read passes 2^53 bytes, and
// every later sum of them then stays exact in 64 bits.
constexpr uint64_t kMaxBytes = uint64_t(1) << 53;
// No bound: a number's range where the specification gives none (JSON holds no NaN or infinity).
constexpr double kAny = std::numeric_limits<double>::max();

uint32_t littleEndian32(const unsigned char* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// A JSON value for a message, cut short: a file may put a megabyte where a number belongs.
std::string shown(const Json& v) {
    if (v.is_object()) return "an object";
    if (v.is_array()) return "an array of " + std::to_string(v.size());
    std::string s = v.dump();
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

// Where a property is: the object ("material 2 \"Gold\"", empty for the document itself) and the
// path to the property inside it ("pbrMetallicRoughness.").
struct At {
    std::string object, prefix;
    size_t index = 0; // of the object in its array
    At inside(const std::string& key) const { return {object, prefix + key + ".", index}; }
};

class Schema {
public:
    Schema(const Json& root, const std::string& path, bool binary) : root_(root), path_(path), binary_(binary) {}

    DocumentFacts check() {
        if (!root_.is_object()) throw LoadError(path_ + ": the JSON document is " + shown(root_) + ", not an object");
        At top;
        const Json* asset = object(root_, top, "asset", true);
        text(*asset, top.inside("asset"), "version", true);
        const std::string& version = asset->at("version").get_ref<const std::string&>();
        if (version.rfind("2.", 0) != 0)
            throw LoadError(path_ + ": asset.version \"" + version + "\"; pt reads glTF 2.0");
        text(*asset, top.inside("asset"), "minVersion");
        for (const char* key : {"extensionsUsed", "extensionsRequired"})
            if (const Json* list = array(root_, top, key))
                for (const Json& e : *list)
                    if (!e.is_string()) fail(top, key, "must be an array of strings, found " + shown(e));
        // The document's arrays first: every reference below counts on them.
        for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                                "meshes", "nodes", "samplers", "scenes", "skins", "textures"})
            array(root_, top, key);
        index(root_, top, "scene", "scenes");
        if (const Json* ext = extension(root_, top, "KHR_lights_punctual")) {
            lights_ = array(*ext, top.inside("extensions.KHR_lights_punctual"), "lights", true);
            each(*lights_, "KHR_lights_punctual light", [&](const Json& l, const At& at) { checkLight(l, at); });
        }
        forEach("scenes", "scene", [&](const Json& s, const At& at) { indexList(s, at, "nodes", "nodes"); });
        forEach("nodes", "node", [&](const Json& n, const At& at) { checkNode(n, at); });
        forEach("meshes", "mesh", [&](const Json& m, const At& at) { checkMesh(m, at); });
        forEach("buffers", "buffer", [&](const Json& b, const At& at) { checkBuffer(b, at); });
        forEach("bufferViews", "bufferView", [&](const Json& v, const At& at) { checkBufferView(v, at); });
        forEach("accessors", "accessor", [&](const Json& a, const At& at) { checkAccessor(a, at); });
        forEach("images", "image", [&](const Json& i, const At& at) { checkImage(i, at); });
        forEach("textures", "texture", [&](const Json& t, const At& at) {
            index(t, at, "sampler", "samplers");
            index(t, at, "source", "images");
        });
        forEach("samplers", "sampler", [&](const Json& s, const At& at) {
            integerOneOf(s, at, "magFilter", {9728, 9729});
            integerOneOf(s, at, "minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
            integerOneOf(s, at, "wrapS", {33071, 33648, 10497});
            integerOneOf(s, at, "wrapT", {33071, 33648, 10497});
        });
        forEach("materials", "material", [&](const Json& m, const At& at) { checkMaterial(m, at); });
        forEach("cameras", "camera", [&](const Json& c, const At& at) { checkCamera(c, at); });
        forEach("skins", "skin", [&](const Json& s, const At& at) {
            index(s, at, "inverseBindMatrices", "accessors");
            index(s, at, "skeleton", "nodes");
            indexList(s, at, "joints", "nodes", true);
        });
        forEach("animations", "animation", [&](const Json& a, const At& at) { checkAnimation(a, at); });
        return facts_;
    }

private:
    [[noreturn]] void fail(const At& at, const std::string& key, const std::string& what) const {
        throw LoadError(path_ + ": " + (at.object.empty() ? "" : at.object + ": ") + at.prefix + key + " " + what);
    }

    static const Json* get(const Json& o, const std::string& key) {
        auto it = o.find(key);
        return it == o.end() ? nullptr : &*it;
    }
    const Json* present(const Json& o, const At& at, const std::string& key, bool required) const {
        const Json* v = get(o, key);
        if (!v && required) fail(at, key, "is missing");
        return v;
    }

    const Json* object(const Json& o, const At& at, const std::string& key, bool required = false) const {
        const Json* v = present(o, at, key, required);
        if (v && !v->is_object()) fail(at, key, "must be an object, found " + shown(*v));
        return v;
    }
    const Json* array(const Json& o, const At& at, const std::string& key, bool required = false) const {
        const Json* v = present(o, at, key, required);
        if (v && !v->is_array()) fail(at, key, "must be an array, found " + shown(*v));
        return v;
    }
    void text(const Json& o, const At& at, const std::string& key, bool required = false) const {
        const Json* v = present(o, at, key, required);
        if (v && !v->is_string()) fail(at, key, "must be a string, found " + shown(*v));
    }
    void boolean(const Json& o, const At& at, const std::string& key) const {
        const Json* v = present(o, at, key, false);
        if (v && !v->is_boolean()) fail(at, key, "must be true or false, found " + shown(*v));
    }
    // An integer in [lo, hi], as the specification's "integer": written without a fraction.
    const Json* integer(const Json& o, const At& at, const std::string& key, int64_t lo, uint64_t hi,
                        bool required = false) const {
        const Json* v = present(o, at, key, required);
        if (!v) return nullptr;
        if (!v->is_number_integer()) fail(at, key, "must be an integer, found " + shown(*v));
        // The parser keeps non-negative integers unsigned and negative ones signed.
        bool fits = v->is_number_unsigned() ? v->get<uint64_t>() <= hi && (lo <= 0 || v->get<uint64_t>() >= uint64_t(lo))
                                            : v->get<int64_t>() >= lo;
        if (!fits) fail(at, key, shown(*v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return v;
    }
    void integerOneOf(const Json& o, const At& at, const std::string& key, std::initializer_list<int> allowed,
                      bool required = false) const {
        const Json* v = integer(o, at, key, INT32_MIN, INT32_MAX, required);
        if (!v) return;
        std::vector<std::string> names;
        for (int a : allowed) {
            if (v->get<int64_t>() == a) return;
            names.push_back(std::to_string(a));
        }
        fail(at, key, shown(*v) + "; expected " + listOf(names));
    }
    void textOneOf(const Json& o, const At& at, const std::string& key, std::initializer_list<const char*> allowed,
                   bool required = false) const {
        text(o, at, key, required);
        const Json* v = get(o, key);
        if (!v) return;
        for (const char* a : allowed)
            if (v->get_ref<const std::string&>() == a) return;
        fail(at, key, shown(*v) + "; expected " + listOf(std::vector<std::string>(allowed.begin(), allowed.end())));
    }
    // "a, b or c"
    static std::string listOf(const std::vector<std::string>& names) {
        std::string list;
        for (size_t i = 0; i < names.size(); ++i)
            list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
        return list;
    }
    // "in [0, 1]", "in (0, 1]", "of at least 0", "above 0", or "" for any number.
    static std::string rangeText(double lo, double hi, bool openLo) {
        if (hi == kAny) return lo == -kAny ? "" : (openLo ? "above " : "of at least ") + shortNumber(lo);
        return std::string("in ") + (openLo ? "(" : "[") + shortNumber(lo) + ", " + shortNumber(hi) + "]";
    }
    // A number in [lo, hi]; `openLo`: lo itself excluded.
    void number(const Json& o, const At& at, const std::string& key, double lo, double hi, bool required = false,
                bool openLo = false) const {
        const Json* v = present(o, at, key, required);
        if (!v) return;
        if (!v->is_number()) fail(at, key, "must be a number, found " + shown(*v));
        double x = v->get<double>();
        if (!(openLo ? x > lo : x >= lo) || !(x <= hi)) fail(at, key, shown(*v) + " must be a number " + rangeText(lo, hi, openLo));
    }
    // An array of `n` numbers in [lo, hi] (any length from 1 when n is 0).
    void numbers(const Json& o, const At& at, const std::string& key, size_t n, double lo, double hi) const {
        const Json* v = present(o, at, key, false);
        if (!v) return;
        std::string range = rangeText(lo, hi, false);
        std::string expected = "must be an array of " + (n ? std::to_string(n) : std::string("one or more")) + " numbers" +
                               (range.empty() ? "" : " " + range) + ", found ";
        if (!v->is_array() || (n ? v->size() != n : v->empty())) fail(at, key, expected + shown(*v));
        for (const Json& x : *v)
            if (!x.is_number() || !(x.get<double>() >= lo && x.get<double>() <= hi)) fail(at, key, expected + shown(x) + " in it");
    }

    // Checks the "uri" of `o`: a data URI of one of `types` (true, with the number of bytes its
    // base64 holds in `bytes`), or a relative path (false). tinygltf reads other data URIs as file
    // names, and stops decoding base64 at the first other character.
    bool dataUri(const Json& o, const At& at, std::initializer_list<const char*> types, uint64_t& bytes) const {
        text(o, at, "uri", true);
        const std::string& uri = o.at("uri").get_ref<const std::string&>();
        if (uri.rfind("data:", 0) != 0) {
            size_t colon = uri.find(':'), slash = uri.find('/');
            if (uri.empty() || uri[0] == '/' || (colon != std::string::npos && (slash == std::string::npos || colon < slash)))
                fail(at, "uri", shown(o.at("uri")) + " is not a relative path; pt reads files beside the glTF file and data: URIs");
            if (uri.find("%00") != std::string::npos) fail(at, "uri", shown(o.at("uri")) + " holds an encoded NUL (%00)");
            return false;
        }
        std::vector<std::string> names;
        for (const char* type : types) {
            std::string header = std::string("data:") + type + ";base64,";
            names.push_back(type);
            if (uri.compare(0, header.size(), header) != 0) continue;
            size_t n = 0, at64 = header.size();
            auto base64 = [](char c) { return std::isalnum((unsigned char)c) || c == '+' || c == '/'; };
            while (at64 + n < uri.size() && base64(uri[at64 + n])) ++n;
            size_t end = at64 + n;
            while (end < uri.size() && uri[end] == '=') ++end;
            if (end != uri.size())
                fail(at, "uri", "holds a character that is not base64 at position " + std::to_string(end) + " of its data");
            bytes = n / 4 * 3 + (n % 4 ? n % 4 - 1 : 0);
            return true;
        }
        fail(at, "uri", "is a data URI of another type than " + listOf(names) + " with base64 data");
    }

    // How many objects `array` of the document holds (the lights of KHR_lights_punctual for "lights").
    size_t countOf(const std::string& array) const {
        const Json* a = array == "lights" ? lights_ : get(root_, array);
        return a && a->is_array() ? a->size() : 0;
    }
    static std::string nounOf(const std::string& array) {
        if (array == "meshes") return "mesh";
        return array.substr(0, array.size() - 1); // accessors -> accessor, lights -> light
    }
    void checkReference(const Json& v, const At& at, const std::string& key, const std::string& array) const {
        std::string noun = nounOf(array);
        size_t n = countOf(array);
        if (v.get<uint64_t>() < n) return;
        std::string where = (at.object.empty() ? "" : at.object + ": ") + (at.prefix.empty() && key == noun ? "" : at.prefix + key + ": ");
        throw LoadError(path_ + ": " + where + noun + " " + shown(v) + " does not exist (the file has " + std::to_string(n) + ")");
    }
    // An index of an object of the document's array `array`.
    void index(const Json& o, const At& at, const std::string& key, const std::string& array, bool required = false) const {
        if (const Json* v = integer(o, at, key, 0, INT32_MAX, required)) checkReference(*v, at, key, array);
    }
    void indexList(const Json& o, const At& at, const std::string& key, const std::string& array, bool required = false) const {
        const Json* list = this->array(o, at, key, required);
        if (!list) return;
        for (const Json& v : *list) {
            if (!v.is_number_integer() || v.get<int64_t>() < 0 || v.get<int64_t>() > INT32_MAX)
                fail(at, key, "must be an array of indices, found " + shown(v) + " in it");
            checkReference(v, at, key, array);
        }
    }

    const Json* extension(const Json& o, const At& at, const std::string& name) const {
        const Json* all = object(o, at, "extensions");
        return all ? object(*all, at.inside("extensions"), name) : nullptr;
    }

    // Each element of `list`, an object, named "NOUN I" with its "name" where it has one.
    void each(const Json& list, const std::string& noun, const std::function<void(const Json&, const At&)>& check) const {
        for (size_t i = 0; i < list.size(); ++i) {
            const Json& item = list[i];
            std::string name = noun + " " + std::to_string(i);
            if (!item.is_object()) throw LoadError(path_ + ": " + name + " is " + shown(item) + ", not an object");
            if (const Json* n = get(item, "name"); n && n->is_string() && !n->get_ref<const std::string&>().empty())
                name += " " + shown(*n);
            text(item, At{name, "", i}, "name");
            check(item, At{name, "", i});
        }
    }
    void forEach(const std::string& array, const std::string& noun,
                 const std::function<void(const Json&, const At&)>& check) const {
        if (const Json* list = this->array(root_, At{}, array)) each(*list, noun, check);
    }

    void checkBuffer(const Json& b, const At& at) {
        integer(b, at, "byteLength", 1, kMaxBytes, true);
        uint64_t length = b.at("byteLength").get<uint64_t>();
        // Only a .glb's first buffer may go without a URI: it is the BIN chunk.
        if (!get(b, "uri")) {
            if (!(binary_ && at.index == 0)) fail(at, "uri", "is missing");
        } else if (uint64_t bytes; dataUri(b, at, {"application/octet-stream", "application/gltf-buffer"}, bytes)) {
            if (bytes != length)
                fail(at, "uri", "holds " + std::to_string(bytes) + " bytes of base64 data; byteLength says " + std::to_string(length));
        } else {
            facts_.fileBuffers.push_back({at.index, b.at("uri").get<std::string>(), length});
        }
    }

    void checkBufferView(const Json& v, const At& at) const {
        index(v, at, "buffer", "buffers", true);
        integer(v, at, "byteOffset", 0, kMaxBytes);
        integer(v, at, "byteLength", 1, kMaxBytes, true);
        integer(v, at, "byteStride", 4, 252);
        integerOneOf(v, at, "target", {34962, 34963});
        // Within the buffer's declared length, which tinygltf holds each buffer's data to: an
        // image's bytes are then never read past the buffer (each term is below 2^53).
        uint64_t offset = v.value("byteOffset", uint64_t(0)), length = v.at("byteLength").get<uint64_t>();
        uint64_t buffer = v.at("buffer").get<uint64_t>();
        uint64_t bufferLength = root_.at("buffers").at(buffer).at("byteLength").get<uint64_t>();
        if (offset + length > bufferLength)
            throw LoadError(path_ + ": " + at.object + ": bytes " + std::to_string(offset) + " to " +
                            std::to_string(offset + length) + " pass the end of buffer " + std::to_string(buffer) + " (" +
                            std::to_string(bufferLength) + " bytes)");
    }

    void checkImage(const Json& i, const At& at) const {
        text(i, at, "mimeType");
        index(i, at, "bufferView", "bufferViews");
        if (!get(i, "uri") && !get(i, "bufferView")) fail(at, "uri", "is missing, and so is bufferView");
        if (get(i, "uri") && get(i, "bufferView")) fail(at, "uri", "and bufferView are both given; an image has one");
        if (get(i, "bufferView") && !get(i, "mimeType")) fail(at, "mimeType", "is missing; an image in a bufferView needs it");
        uint64_t bytes;
        if (get(i, "uri")) dataUri(i, at, {"image/png", "image/jpeg", "image/bmp", "image/gif"}, bytes);
    }

    void checkNode(const Json& n, const At& at) const {
        index(n, at, "camera", "cameras");
        index(n, at, "mesh", "meshes");
        index(n, at, "skin", "skins");
        indexList(n, at, "children", "nodes");
        numbers(n, at, "matrix", 16, -kAny, kAny);
        if (const Json* m = get(n, "matrix")) {
            for (const char* trs : {"translation", "rotation", "scale"})
                if (get(n, trs)) fail(at, "matrix", std::string("and ") + trs + " are both given; a node has one or the other");
            // Column-major: the last row is elements 3, 7, 11 and 15.
            if (std::abs((*m)[3].get<double>()) > 1e-6 || std::abs((*m)[7].get<double>()) > 1e-6 ||
                std::abs((*m)[11].get<double>()) > 1e-6 || std::abs((*m)[15].get<double>() - 1.0) > 1e-6)
                fail(at, "matrix", "is not affine: its last row must be 0, 0, 0, 1");
        }
        numbers(n, at, "rotation", 4, -1.0, 1.0);
        numbers(n, at, "scale", 3, -kAny, kAny);
        numbers(n, at, "translation", 3, -kAny, kAny);
        numbers(n, at, "weights", 0, -kAny, kAny);
        if (const Json* light = extension(n, at, "KHR_lights_punctual"))
            index(*light, at.inside("extensions.KHR_lights_punctual"), "light", "lights", true);
    }

    void checkMesh(const Json& m, const At& at) const {
        const Json* primitives = array(m, at, "primitives", true);
        if (primitives->empty()) fail(at, "primitives", "is empty");
        numbers(m, at, "weights", 0, -kAny, kAny);
        for (size_t p = 0; p < primitives->size(); ++p) {
            const Json& prim = (*primitives)[p];
            At pat{at.object + " primitive " + std::to_string(p), ""};
            if (!prim.is_object()) throw LoadError(path_ + ": " + pat.object + " is " + shown(prim) + ", not an object");
            attributeMap(*object(prim, pat, "attributes", true), pat.inside("attributes"));
            index(prim, pat, "indices", "accessors");
            index(prim, pat, "material", "materials");
            integer(prim, pat, "mode", 0, 6);
            if (const Json* targets = array(prim, pat, "targets"))
                for (size_t t = 0; t < targets->size(); ++t) {
                    At tat = pat.inside("targets[" + std::to_string(t) + "]");
                    if (!(*targets)[t].is_object()) fail(pat, "targets", "must hold objects, found " + shown((*targets)[t]));
                    attributeMap((*targets)[t], tat);
                }
        }
    }
    void attributeMap(const Json& attributes, const At& at) const {
        for (auto it = attributes.begin(); it != attributes.end(); ++it) index(attributes, at, it.key(), "accessors");
    }

    void checkAccessor(const Json& a, const At& at) const {
        index(a, at, "bufferView", "bufferViews");
        integer(a, at, "byteOffset", 0, kMaxBytes);
        integerOneOf(a, at, "componentType", {5120, 5121, 5122, 5123, 5125, 5126}, true);
        // Components lie on multiples of their size, in the view and in the buffer.
        int64_t type = a.at("componentType").get<int64_t>();
        uint64_t size = type <= 5121 ? 1 : type <= 5123 ? 2 : 4;
        uint64_t offset = a.value("byteOffset", uint64_t(0));
        if (offset % size) fail(at, "byteOffset", std::to_string(offset) + " is not a multiple of the component size " + std::to_string(size));
        if (const Json* v = get(a, "bufferView")) {
            const Json& view = root_.at("bufferViews").at(v->get<size_t>());
            if ((offset + view.value("byteOffset", uint64_t(0))) % size)
                fail(at, "byteOffset", "plus its bufferView's byteOffset is not a multiple of the component size " + std::to_string(size));
            if (view.value("byteStride", uint64_t(0)) % size)
                fail(at, "bufferView", "has a byteStride that is not a multiple of the component size " + std::to_string(size));
        }
        boolean(a, at, "normalized");
        integer(a, at, "count", 1, UINT32_MAX, true);
        textOneOf(a, at, "type", {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"}, true);
        for (const char* bound : {"max", "min"}) {
            numbers(a, at, bound, 0, -kAny, kAny);
            if (const Json* v = get(a, bound); v && v->size() > 16) fail(at, bound, "has " + shown(*v) + "; at most 16 numbers");
        }
        if (const Json* sparse = object(a, at, "sparse")) {
            At sat = at.inside("sparse");
            integer(*sparse, sat, "count", 1, INT32_MAX, true); // tinygltf keeps these three as int
            const Json* indices = object(*sparse, sat, "indices", true);
            At iat = sat.inside("indices");
            index(*indices, iat, "bufferView", "bufferViews", true);
            integer(*indices, iat, "byteOffset", 0, INT32_MAX);
            integerOneOf(*indices, iat, "componentType", {5121, 5123, 5125}, true);
            const Json* values = object(*sparse, sat, "values", true);
            index(*values, sat.inside("values"), "bufferView", "bufferViews", true);
            integer(*values, sat.inside("values"), "byteOffset", 0, INT32_MAX);
        }
    }

    // A textureInfo (and a normalTextureInfo's scale, an occlusionTextureInfo's strength).
    void textureInfo(const Json& o, const At& at, const std::string& key) const {
        const Json* info = object(o, at, key);
        if (!info) return;
        At tat = at.inside(key);
        index(*info, tat, "index", "textures", true);
        integer(*info, tat, "texCoord", 0, INT32_MAX);
        number(*info, tat, "scale", -kAny, kAny);
        number(*info, tat, "strength", 0.0, 1.0);
        if (const Json* t = extension(*info, tat, "KHR_texture_transform")) {
            At xat = tat.inside("extensions.KHR_texture_transform");
            numbers(*t, xat, "offset", 2, -kAny, kAny);
            number(*t, xat, "rotation", -kAny, kAny);
            numbers(*t, xat, "scale", 2, -kAny, kAny);
            integer(*t, xat, "texCoord", 0, INT32_MAX);
        }
    }

    void checkMaterial(const Json& m, const At& at) const {
        if (const Json* pbr = object(m, at, "pbrMetallicRoughness")) {
            At pat = at.inside("pbrMetallicRoughness");
            numbers(*pbr, pat, "baseColorFactor", 4, 0.0, 1.0);
            textureInfo(*pbr, pat, "baseColorTexture");
            number(*pbr, pat, "metallicFactor", 0.0, 1.0);
            number(*pbr, pat, "roughnessFactor", 0.0, 1.0);
            textureInfo(*pbr, pat, "metallicRoughnessTexture");
        }
        textureInfo(m, at, "normalTexture");
        textureInfo(m, at, "occlusionTexture");
        textureInfo(m, at, "emissiveTexture");
        numbers(m, at, "emissiveFactor", 3, 0.0, 1.0);
        textOneOf(m, at, "alphaMode", {"OPAQUE", "MASK", "BLEND"});
        number(m, at, "alphaCutoff", 0.0, kAny);
        boolean(m, at, "doubleSided");
        if (const Json* e = extension(m, at, "KHR_materials_emissive_strength"))
            number(*e, at.inside("extensions.KHR_materials_emissive_strength"), "emissiveStrength", 0.0, kAny);
        if (const Json* e = extension(m, at, "KHR_materials_ior"))
            number(*e, at.inside("extensions.KHR_materials_ior"), "ior", 0.0, kAny);
        if (const Json* e = extension(m, at, "KHR_materials_specular")) {
            At eat = at.inside("extensions.KHR_materials_specular");
            number(*e, eat, "specularFactor", 0.0, 1.0);
            textureInfo(*e, eat, "specularTexture");
            numbers(*e, eat, "specularColorFactor", 3, 0.0, kAny);
            textureInfo(*e, eat, "specularColorTexture");
        }
        if (const Json* e = extension(m, at, "KHR_materials_clearcoat")) {
            At eat = at.inside("extensions.KHR_materials_clearcoat");
            number(*e, eat, "clearcoatFactor", 0.0, 1.0);
            textureInfo(*e, eat, "clearcoatTexture");
            number(*e, eat, "clearcoatRoughnessFactor", 0.0, 1.0);
            textureInfo(*e, eat, "clearcoatRoughnessTexture");
            textureInfo(*e, eat, "clearcoatNormalTexture");
        }
        extension(m, at, "KHR_materials_unlit"); // an object (of no keys pt reads)
        if (const Json* e = extension(m, at, "KHR_materials_sheen")) {
            At eat = at.inside("extensions.KHR_materials_sheen");
            numbers(*e, eat, "sheenColorFactor", 3, 0.0, 1.0);
            textureInfo(*e, eat, "sheenColorTexture");
            number(*e, eat, "sheenRoughnessFactor", 0.0, 1.0);
            textureInfo(*e, eat, "sheenRoughnessTexture");
        }
        if (const Json* e = extension(m, at, "KHR_materials_transmission")) {
            At eat = at.inside("extensions.KHR_materials_transmission");
            number(*e, eat, "transmissionFactor", 0.0, 1.0);
            textureInfo(*e, eat, "transmissionTexture");
        }
        if (const Json* e = extension(m, at, "KHR_materials_volume")) {
            At eat = at.inside("extensions.KHR_materials_volume");
            number(*e, eat, "thicknessFactor", 0.0, kAny);
            textureInfo(*e, eat, "thicknessTexture");
            number(*e, eat, "attenuationDistance", 0.0, kAny, false, true);
            numbers(*e, eat, "attenuationColor", 3, 0.0, 1.0);
        }
    }

    void checkCamera(const Json& c, const At& at) const {
        textOneOf(c, at, "type", {"perspective", "orthographic"}, true);
        bool perspective = c.at("type") == "perspective";
        const Json* p = object(c, at, perspective ? "perspective" : "orthographic", true);
        At pat = at.inside(perspective ? "perspective" : "orthographic");
        if (perspective) {
            number(*p, pat, "aspectRatio", 0.0, kAny, false, true);
            number(*p, pat, "yfov", 0.0, kAny, true, true);
            number(*p, pat, "zfar", 0.0, kAny, false, true);
            number(*p, pat, "znear", 0.0, kAny, true, true);
        } else {
            number(*p, pat, "xmag", -kAny, kAny, true);
            number(*p, pat, "ymag", -kAny, kAny, true);
            number(*p, pat, "zfar", 0.0, kAny, true, true);
            number(*p, pat, "znear", 0.0, kAny, true);
        }
        if (get(*p, "zfar") && !(p->at("zfar").get<double>() > p->at("znear").get<double>()))
            fail(pat, "zfar", shown(p->at("zfar")) + " is not beyond znear " + shown(p->at("znear")));
    }

    void checkLight(const Json& l, const At& at) const {
        textOneOf(l, at, "type", {"point", "spot", "directional"}, true);
        numbers(l, at, "color", 3, 0.0, 1.0);
        number(l, at, "intensity", 0.0, kAny);
        number(l, at, "range", 0.0, kAny, false, true);
        if (l.at("type") == "spot") {
            const Json* spot = object(l, at, "spot", true);
            number(*spot, at.inside("spot"), "innerConeAngle", 0.0, kPiOver2);
            number(*spot, at.inside("spot"), "outerConeAngle", 0.0, kPiOver2, false, true);
        }
    }

    void checkAnimation(const Json& a, const At& at) const {
        const Json* samplers = array(a, at, "samplers", true);
        for (size_t s = 0; s < samplers->size(); ++s) {
            At sat{at.object + " sampler " + std::to_string(s), ""};
            const Json& sampler = (*samplers)[s];
            if (!sampler.is_object()) throw LoadError(path_ + ": " + sat.object + " is " + shown(sampler) + ", not an object");
            index(sampler, sat, "input", "accessors", true);
            index(sampler, sat, "output", "accessors", true);
            textOneOf(sampler, sat, "interpolation", {"LINEAR", "STEP", "CUBICSPLINE"});
        }
        const Json* channels = array(a, at, "channels", true);
        for (size_t c = 0; c < channels->size(); ++c) {
            At cat{at.object + " channel " + std::to_string(c), ""};
            const Json& channel = (*channels)[c];
            if (!channel.is_object()) throw LoadError(path_ + ": " + cat.object + " is " + shown(channel) + ", not an object");
            if (const Json* s = integer(channel, cat, "sampler", 0, INT32_MAX, true); s->get<uint64_t>() >= samplers->size())
                fail(cat, "sampler", shown(*s) + " does not exist (the animation has " + std::to_string(samplers->size()) + ")");
            const Json* target = object(channel, cat, "target", true);
            index(*target, cat.inside("target"), "node", "nodes");
            text(*target, cat.inside("target"), "path", true);
        }
    }

    const Json& root_;
    const std::string& path_;
    bool binary_;
    const Json* lights_ = nullptr;
    DocumentFacts facts_;
};

} // namespace

std::string_view gltfJson(const std::vector<unsigned char>& bytes, bool binary, const std::string& path) {
    if (!binary) return std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    // A .glb: a 12-byte header (magic, version 2, total length), then chunks of (length, type, data).
    if (bytes.size() < 20 || littleEndian32(bytes.data()) != 0x46546c67u) // "glTF"
        throw LoadError(path + ": not a binary glTF file (it must start with \"glTF\" and a 20-byte header)");
    uint32_t version = littleEndian32(&bytes[4]), length = littleEndian32(&bytes[8]);
    uint32_t jsonLength = littleEndian32(&bytes[12]), jsonType = littleEndian32(&bytes[16]);
    if (version != 2) throw LoadError(path + ": binary glTF version " + std::to_string(version) + "; pt reads version 2");
    if (length != bytes.size())
        throw LoadError(path + ": its header gives a length of " + std::to_string(length) + " bytes, but the file has " +
                        std::to_string(bytes.size()) + (length > bytes.size() ? " (truncated?)" : ""));
    if (jsonType != 0x4e4f534au) throw LoadError(path + ": its first chunk is not JSON");
    if (uint64_t(jsonLength) + 20 > length)
        throw LoadError(path + ": its JSON chunk of " + std::to_string(jsonLength) + " bytes passes the end of the file");
    // Every later chunk (BIN, or one of a type readers skip) must fit with its 8-byte header:
    // tinygltf leaves the header out of its bound and reads 8 bytes past a chunk that lies.
    for (uint64_t at = 20 + uint64_t(jsonLength); at < length;) {
        if (length - at < 8) throw LoadError(path + ": " + std::to_string(length - at) + " stray bytes after its last chunk");
        uint64_t chunk = littleEndian32(&bytes[at]);
        if (chunk > length - at - 8)
            throw LoadError(path + ": the chunk at byte " + std::to_string(at) + " declares " + std::to_string(chunk) +
                            " bytes, past the end of the file");
        at += 8 + chunk;
    }
    return std::string_view(reinterpret_cast<const char*>(&bytes[20]), jsonLength);
}

void checkJsonDepth(std::string_view json, const std::string& path) {
    int depth = 0;
    bool inString = false, escaped = false;
    size_t line = 1;
    for (char c : json) {
        if (c == '\n') ++line;
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw LoadError(path, line, "arrays and objects nest deeper than " + std::to_string(kMaxJsonDepth) +
                                                " levels; pt reads at most that");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

DocumentFacts checkGltfDocument(std::string_view json, bool binary, const std::string& path) {
    checkJsonDepth(json, path);
    Json root;
    try {
        root = Json::parse(json.begin(), json.end());
    } catch (const Json::exception& e) {
        throw LoadError(path + ": not valid JSON: " + e.what());
    }
    return Schema(root, path, binary).check();
}

} // namespace pt::gltf
