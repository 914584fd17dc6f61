#include "render/render_job.h"

#include <cstdio>
#include <fstream>

namespace pt {

const std::vector<std::string>& jobFields() {
    static const std::vector<std::string> fields = {
        "pt:version",   "pt:sceneHash",   "pt:fullWidth",   "pt:fullHeight",  "pt:camera",     "pt:sppRequested",
        "pt:seed",      "pt:maxDepth",    "pt:sampler",     "pt:lightSampling", "pt:lightChoice", "pt:hemisphere",
        "pt:clamp",     "pt:exposure",    "pt:envRotate",   "pt:envScale",    "pt:environment", "pt:sunDirection",
        "pt:turbidity", "pt:skyScale",
    };
    return fields;
}

std::string attributeText(const Image& image, const std::string& name) {
    for (const ImageAttribute& a : image.metadata)
        if (a.name == name) return a.asText();
    return "";
}

bool jobMismatch(const Image& a, const Image& b, std::string& field, std::string& valueA, std::string& valueB) {
    for (const std::string& f : jobFields()) {
        std::string va = attributeText(a, f), vb = attributeText(b, f);
        if (va != vb) {
            field = f, valueA = va, valueB = vb;
            return true;
        }
    }
    return false;
}

std::string contentHash(const std::vector<std::string>& files) {
    uint64_t h = 0xcbf29ce484222325ULL; // FNV-1a, 64 bits: about 1 GB/s, a 50 MB scene in 50 ms
    auto mix = [&](unsigned char c) { h = (h ^ c) * 0x100000001b3ULL; };
    std::vector<char> buffer(1 << 16);
    for (const std::string& path : files) {
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            for (char c : path) mix((unsigned char)c);
            continue;
        }
        while (in) {
            in.read(buffer.data(), std::streamsize(buffer.size()));
            for (std::streamsize i = 0; i < in.gcount(); ++i) mix((unsigned char)buffer[size_t(i)]);
        }
        mix(0xff); // a boundary, so that moving bytes between files changes the hash
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)h);
    return text;
}

} // namespace pt
