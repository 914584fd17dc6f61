// What makes renders parts of one job, so that their samples may be merged: the same value of
// every sample of every pixel. pt render writes these fields into every EXR's metadata; pt merge
// and pt render --resume compare them and name the first that differs.
#pragma once

#include "image/image_io.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace pt {

// The metadata names of a job's identity, in the order a mismatch is reported.
const std::vector<std::string>& jobFields();

// The first job field whose value differs between two images' metadata (a field absent from both
// is equal); false when they are one job.
bool jobMismatch(const Image& a, const Image& b, std::string& field, std::string& valueA, std::string& valueB);

// The scene's content as 16 hex digits: a hash of its files' hashes (taken from the bytes pt
// read, scene/scene.h), in order, whatever path each is read from on each machine.
std::string jobHash(const std::vector<SourceFile>& files);

// The metadata attribute `name` as text; "" when absent.
std::string attributeText(const Image& image, const std::string& name);

} // namespace pt
