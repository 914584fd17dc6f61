// What makes renders parts of one job, so that their samples may be merged: the same value of
// every sample of every pixel. pt render writes a job's fields into every EXR's metadata through
// JobMetadataWriter; pt merge and pt render --resume compare the identity fields and name the
// first that differs.
#pragma once

#include "image/image_io.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace pt {

// Every field of a job that pt render writes, once, with whether parts must agree on it. A field
// only describes where it cannot change a sample: a path that differs between machines (the
// content is pt:sceneHash), a value derived from an identity field.
enum class JobFieldRole : uint8_t { Identity, Describes };
struct JobField {
    const char* name;
    JobFieldRole role;
};
extern const JobField kJobFields[];
extern const size_t kJobFieldCount;

// The identity fields' names, in the order a mismatch is reported.
const std::vector<std::string>& jobFields();

// Writes a job's fields into an image's metadata. A name not in kJobFields is a programming
// error (std::logic_error): no setting can be written without saying whether parts must agree.
class JobMetadataWriter {
public:
    explicit JobMetadataWriter(Image& image) : image_(image) {}
    void text(const char* name, const std::string& value);
    void integer(const char* name, long long value);
    void real(const char* name, double value);

private:
    void check(const char* name) const;
    Image& image_;
};

// The first job field whose value differs between two images' metadata (a field absent from both
// is equal); false when they are one job.
bool jobMismatch(const Image& a, const Image& b, std::string& field, std::string& valueA, std::string& valueB);

// The scene's content as 16 hex digits: a hash of its files' hashes (taken from the bytes pt
// read, scene/scene.h), in order, whatever path each is read from on each machine.
std::string jobHash(const std::vector<SourceFile>& files);

// The metadata attribute `name` as text; "" when absent.
std::string attributeText(const Image& image, const std::string& name);

} // namespace pt
