// What makes renders parts of one job, so that their samples may be merged: the same value of
// every sample of every pixel. pt render writes these fields into every EXR's metadata; pt merge
// and pt render --resume compare them and name the first that differs.
#pragma once

#include "image/image_io.h"

#include <string>
#include <vector>

namespace pt {

// The metadata names of a job's identity, in the order a mismatch is reported.
const std::vector<std::string>& jobFields();

// The first job field whose value differs between two images' metadata (a field absent from both
// is equal); false when they are one job.
bool jobMismatch(const Image& a, const Image& b, std::string& field, std::string& valueA, std::string& valueB);

// A 64-bit hash (16 hex digits) of the bytes of the given files, in order: the scene's content,
// whatever path it is read from on each machine. Unreadable files hash as their name.
std::string contentHash(const std::vector<std::string>& files);

// The metadata attribute `name` as text; "" when absent.
std::string attributeText(const Image& image, const std::string& name);

} // namespace pt
