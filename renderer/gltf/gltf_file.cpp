#include "gltf/gltf_file.h"
#include "gltf/gltf_document.h"
#include "gltf/gltf_loader.h"
#include "core/system.h"
#include "io/input_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>

namespace pt {
namespace {

constexpr const char* kSupportedExtensions[] = {
    "KHR_materials_clearcoat", "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_sheen",
    "KHR_materials_specular", "KHR_materials_unlit",
    "KHR_materials_transmission",
    "KHR_materials_volume", "KHR_lights_punctual", "KHR_mesh_quantization", "KHR_texture_transform",
};

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

} // namespace

bool gltfExtensionSupported(const std::string& name) {
    return std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), name) != std::end(kSupportedExtensions);
}

namespace gltf {

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

GltfFile readGltfFile(const std::string& path, const std::vector<unsigned char>& bytes, bool binary, Warnings& warnings) {
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
    GltfFile file;
    tinygltf::Model& model = file.model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepImageBytes, &file.images);
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

    file.buffers = std::move(files.read);
    return file;
}

} // namespace gltf
} // namespace pt
