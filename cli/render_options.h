// pt render's command line: the options, their checks against each other, and the help text.
#pragma once

#include "environment/sky_environment.h"
#include "render/film_image.h"
#include "render/renderer.h"

#include <string>

namespace pt::cli {

// What the command line asks of one render, checked: options that contradict each other, or
// that need another, are a UsageError.
struct RenderArgs {
    std::string scene;
    std::string output = "out.exr";
    long long spp = 16;
    bool sppGiven = false;
    SampleBudget budget;
    bool minSppGiven = false;
    int width = 512, height = 512;
    bool resGiven = false;
    double exposure = 0.0; // EV: the image is scaled by 2^exposure
    std::string camera; // --camera as given; none: camera 0
    int threads = 0;
    RenderSettings settings;
    AovSelection aovs;
    bool denoise = false;
    bool guide = false, guideSppGiven = false; // the training samples are settings.guideSpp
    bool quiet = false;
    std::string env;
    double envRotate = 0.0, envScale = 1.0;
    bool envRotateGiven = false, envScaleGiven = false;
    bool sky = false;
    SkyParameters skyParameters;
    double sunElevation = 45.0, sunAzimuth = 135.0;
    std::string skyOption; // the first sky option given, for "needs --sky" messages
    bool sunAnglesGiven = false, sunDirGiven = false;
    // A share of the job: sample indices [samplesFirst, samplesLast) of the pixels in `crop`.
    bool samplesGiven = false, cropGiven = false;
    long long samplesFirst = 0, samplesLast = 0;
    long long crop[4] = {0, 0, 0, 0};
    std::string resume;
    bool part() const { return samplesGiven || cropGiven; }
};

// Parses argv (argv[0] is "render"); prints the help and exits 0 on -h/--help.
RenderArgs parseRenderArgs(int argc, char** argv);

} // namespace pt::cli
