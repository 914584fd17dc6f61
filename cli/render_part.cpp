#include "cli/render_part.h"
#include "io/output_file.h"
#include "render/film_part.h"
#include "render/render_job.h"

#include <algorithm>
#include <filesystem>

namespace pt::cli {

std::string jobShare(const RenderArgs& args, JobShare& share) {
    share.first = uint32_t(args.samplesFirst);
    share.last = args.samplesGiven ? uint32_t(args.samplesLast) : uint32_t(args.spp);
    share.window = PixelWindow{0, 0, args.width, args.height};
    if (args.samplesGiven && (args.samplesLast > (1 << 24) || args.samplesLast > args.spp))
        return "--samples " + std::to_string(args.samplesFirst) + ":" + std::to_string(args.samplesLast) + ": " +
               (args.samplesLast > (1 << 24)
                    ? std::string("a pixel has 16777216 (2^24) sample indices per seed; split the job among seeds no further")
                    : "the job has -spp " + std::to_string(args.spp) + ", so its sample indices run from 0 to " +
                          std::to_string(args.spp));
    if (args.cropGiven) {
        if (args.crop[2] > args.width || args.crop[3] > args.height)
            return "--crop " + std::to_string(args.crop[0]) + "," + std::to_string(args.crop[1]) + "," +
                   std::to_string(args.crop[2]) + "," + std::to_string(args.crop[3]) + " passes the " +
                   std::to_string(args.width) + "x" + std::to_string(args.height) + " image";
        share.window = PixelWindow{int(args.crop[0]), int(args.crop[1]), int(args.crop[2]), int(args.crop[3])};
    }
    return "";
}

std::string partialPath(const std::string& output) {
    std::filesystem::path p(output);
    std::string stem = p.stem().string(), tail = ".partial" + p.extension().string();
    long longest = maxNameLength(p.parent_path().empty() ? "." : p.parent_path().string());
    if (long(stem.size() + tail.size()) > longest) stem.resize(size_t(std::max(1L, longest - long(tail.size()))));
    return (p.parent_path() / (stem + tail)).string();
}

std::string readResumePart(const std::string& path, const Image& job, const JobShare& share, bool firstHitLayers,
                           Image& part, Film& film) {
    const PixelWindow& window = share.window;
    const uint32_t first = share.first, last = share.last;
    PartInfo info;
    std::string error = readPart(path, part, film, info);
    if (!error.empty()) return "--resume: " + error;
    std::string field, mine, theirs;
    if (jobMismatch(job, part, field, mine, theirs))
        return "--resume " + path + ": it is a part of another job: its " + field + " is \"" + theirs +
               "\", this command's is \"" + mine + "\"";
    if (info.first != first || info.last != last)
        return "--resume " + path + ": it holds samples " + std::to_string(info.first) + ":" + std::to_string(info.last) +
               ", this command renders " + std::to_string(first) + ":" + std::to_string(last) + " (give the same --samples)";
    if (info.x0 != window.x0 || info.y0 != window.y0 || info.x1 != window.x1 || info.y1 != window.y1)
        return "--resume " + path + ": its pixels are not this command's --crop";
    if (firstHitLayers && !film.hasFirstHitLayers())
        return "--resume " + path + ": it has no first-hit sums, so --aov albedo, normal and depth and --denoise cannot "
               "go on from it (resume without them)";
    return "";
}

} // namespace pt::cli
