#include "render/render_job.h"

#include "io/input_file.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace pt {

const JobField kJobFields[] = {
    {"Software", JobFieldRole::Describes},
    {"pt:version", JobFieldRole::Identity},
    {"pt:scene", JobFieldRole::Describes},         // as given on the command line
    {"pt:sceneResolved", JobFieldRole::Describes}, // this machine's absolute path
    {"pt:sceneHash", JobFieldRole::Identity},      // every file read, the --env map included
    {"pt:fullWidth", JobFieldRole::Identity},
    {"pt:fullHeight", JobFieldRole::Identity},
    {"pt:camera", JobFieldRole::Identity},
    {"pt:cameraIndex", JobFieldRole::Identity},
    {"pt:sppRequested", JobFieldRole::Identity},
    {"pt:seed", JobFieldRole::Identity},
    {"pt:maxDepth", JobFieldRole::Identity},
    {"pt:sampler", JobFieldRole::Identity},
    {"pt:lightSampling", JobFieldRole::Identity},
    {"pt:lightChoice", JobFieldRole::Identity},
    {"pt:hemisphere", JobFieldRole::Identity},
    {"pt:clamp", JobFieldRole::Identity},
    {"pt:guideSpp", JobFieldRole::Identity}, // --guide: the guide's training samples
    {"pt:exposure", JobFieldRole::Identity},
    {"pt:env", JobFieldRole::Describes}, // its path; its content is in pt:sceneHash
    {"pt:envRotate", JobFieldRole::Identity},
    {"pt:envScale", JobFieldRole::Identity},
    {"pt:environment", JobFieldRole::Identity},
    {"pt:sunDirection", JobFieldRole::Identity},
    {"pt:sunElevation", JobFieldRole::Describes}, // pt:sunDirection's angles
    {"pt:sunAzimuth", JobFieldRole::Describes},
    {"pt:turbidity", JobFieldRole::Identity},
    {"pt:skyScale", JobFieldRole::Identity},
    {"pt:noise", JobFieldRole::Identity},
    {"pt:minSpp", JobFieldRole::Identity},
};
const size_t kJobFieldCount = sizeof kJobFields / sizeof kJobFields[0];

const std::vector<std::string>& jobFields() {
    static const std::vector<std::string> fields = [] {
        std::vector<std::string> names;
        for (size_t i = 0; i < kJobFieldCount; ++i)
            if (kJobFields[i].role == JobFieldRole::Identity) names.push_back(kJobFields[i].name);
        return names;
    }();
    return fields;
}

void JobMetadataWriter::check(const char* name) const {
    for (size_t i = 0; i < kJobFieldCount; ++i)
        if (std::strcmp(kJobFields[i].name, name) == 0) return;
    throw std::logic_error(std::string("job metadata field ") + name + " is not in kJobFields (render/render_job.cpp)");
}

void JobMetadataWriter::text(const char* name, const std::string& value) {
    check(name);
    image_.metadata.push_back(ImageAttribute::string(name, value));
}

void JobMetadataWriter::integer(const char* name, long long value) {
    check(name);
    image_.metadata.push_back(ImageAttribute::integerValue(name, value));
}

void JobMetadataWriter::real(const char* name, double value) {
    check(name);
    image_.metadata.push_back(ImageAttribute::floatValue(name, value));
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
