#include "render/render_job.h"

#include "io/input_file.h"

#include <cstdio>

namespace pt {

const std::vector<std::string>& jobFields() {
    static const std::vector<std::string> fields = {
        "pt:version",   "pt:sceneHash",   "pt:fullWidth",   "pt:fullHeight",  "pt:camera",     "pt:cameraIndex", "pt:sppRequested",
        "pt:seed",      "pt:maxDepth",    "pt:sampler",     "pt:lightSampling", "pt:lightChoice", "pt:hemisphere",
        "pt:clamp",     "pt:exposure",    "pt:envRotate",   "pt:envScale",    "pt:environment", "pt:sunDirection",
        "pt:turbidity", "pt:skyScale",    "pt:noise",       "pt:minSpp",
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

std::string jobHash(const std::vector<SourceFile>& files) {
    std::vector<uint64_t> hashes;
    for (const SourceFile& f : files) hashes.push_back(f.hash);
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)contentHash(hashes.data(), hashes.size() * sizeof(uint64_t)));
    return text;
}

} // namespace pt
