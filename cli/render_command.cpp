// pt render: load a scene, trace it, write the image.
#include "accel/accel.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/denoising.h"
#include "cli/stop_signals.h"
#include "core/system.h"
#include "io/output_file.h"
#include "image/image_io.h"
#include "environment/sky_environment.h"
#include "render/film_image.h"
#include "render/film_part.h"
#include "render/render_job.h"
#include "render/renderer.h"
#include "io/scene_limits.h"
#include "load/scene_loader.h"
#include "scene/complete_scene.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <sys/ioctl.h>
#include <csignal>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

namespace pt::cli {
namespace {

const char* kRenderUsage = R"(usage: pt render SCENE [options]

Renders SCENE (Wavefront .obj with the lab's extended .mtl, or glTF 2.0 .gltf/.glb) and writes
one image. glTF: metallic-roughness materials with their textures, alphaMode, KHR_lights_punctual,
KHR_materials_clearcoat, _sheen, _specular, _transmission (thin-walled without a volume), _volume
(refraction, Beer-Lambert absorption), _emissive_strength, _ior and _unlit, each with its textures,
KHR_texture_transform, KHR_mesh_quantization;
lights in candela and lux divided by 683 lm/W; without lights, a uniform white environment.
MTL texture maps: map_Kd, map_Ks (colour), map_Pr, map_Pm, norm, bump/map_bump, map_d (data),
with options -s, -o, -clamp on|off, -bm, -imfchan r|g|b|m|l (see the README).
MTL environment: newenvironment NAME, envmap FILE, envrotate DEG, envscale S (--env replaces it).

options (default in brackets):
  -o, --output PATH      output image [out.exr]; the extension picks the format:
                           .exr  linear float RGB, metadata, and any --aov layers
                           .png  sRGB-encoded 8-bit RGB
  -spp, --spp N          samples per pixel [16; with --time or --noise, the most a pixel
                         may take: 4096]
  --time SECONDS         stop after at most SECONDS of rendering, at the last pass boundary
                         the time allows (every pixel has at least one sample); without
                         --noise the image equals -spp N for the N it reached [none]
  --noise E              adaptive sampling: a pixel stops once the standard error of its
                         mean, relative to its brightness, is at most E, in [1e-4, 1) (0.01
                         to 0.05 are typical; pooled over its 3x3 neighbours, decided
                         between passes, so the image does not depend on --threads) [off]
  --min-spp N            with --noise, samples every pixel takes before it may stop
                         [16, or -spp where that is smaller]
  --res WxH              image size in pixels [512x512; a glTF camera's aspect ratio
                         gives 512 across its longer side]
  --camera NAME|INDEX    camera by name, or by 0-based index in file order; a name two
                         cameras share, or that is the index of another, is refused [0]
  --threads N            worker threads; 0 uses every hardware thread, and more than the
                         machine has are cut to that many, with a warning [0]
  --seed S               random seed in [0, 2147483647]; the image depends only on it,
                         never on --threads [0]
  --max-depth D          most scattering events on a path: 0 shows only emitters seen
                         directly, 1 gives direct lighting [16]
  --light-sampling M     direct light by mis (light and BSDF sampling, weighted),
                         nee (light sampling only) or bsdf (BSDF sampling only) [mis]
  --light-choice M       how next-event estimation picks an emitter: power, or tree
                         (a light tree weighing each by distance and orientation as seen
                         from the shading point; for many emitters); auto takes the
                         tree with 2 or more lights and emissive triangles, or with
                         any beside an environment, sun or directional light [auto]
  --hemisphere M         Lambert sampling, cosine or uniform (a diagnostic; the lab model's
                         Lambert lobe only: glTF's BRDF keeps the cosine, with a warning) [cosine]
  --sampler S            sample values: sobol (Owen-scrambled Sobol points) or random
                         (independent) [sobol]
  --aov LIST             extra EXR layers, comma-separated [none]:
                           variance  variance of each pixel's mean (variance.R/G/B; pt diff uses it)
                           albedo    first-hit reflectance, all lobes (albedo.R/G/B)
                           normal    first-hit shading normal facing the camera (normal.X/Y/Z)
                           depth     distance to the first hit, +inf where none (depth.Z)
                           spp       the samples each pixel holds (spp.Z; --noise, --time)
  --env PATH             light the scene with an HDR lat-long environment map (EXR, HDR,
                         float TIFF; +y up, laid out as in Blender), importance-sampled
                         as a light; it replaces the MTL's newenvironment, and without
                         either the lab's two-tone sky lights the scene [none]
  --env-rotate DEG       turn the map about +y by DEG degrees [0]
  --env-scale S          multiply the map's radiance by S [1]
  --sky                  light the scene with the Preetham clear sky and the sun's disk
                         (both importance-sampled; the ground below the horizon has
                         albedo 0.2); it replaces the MTL's newenvironment [off]
  --sun-elevation DEG    the sun's height above the horizon, -90 to 90 [45]
  --sun-azimuth DEG      the sun's compass direction: 0 is -z (ahead of a camera looking
                         down -z), 90 is +x [135]
  --sun-dir X,Y,Z        the direction towards the sun, instead of the two angles
  --turbidity T          haze, from 1.7 (very clear) to 10 (hazy) [3]
  --sky-scale S          multiply the sky's, sun's and ground's radiance by S [1]
  --denoise              denoise the image with Intel Open Image Denoise (its RT filter on
                         the CPU, guided by the albedo and normal, which are gathered through
                         mirrors and smooth glass and denoised first); after the last pass,
                         outside a --time budget. The EXR's RGB is denoised and the raw
                         estimate is kept as layer noisy (what pt diff compares); a .png holds
                         the denoised picture. Needs tools/install-oidn (or PT_OIDN_LIBRARY
                         naming libOpenImageDenoise.so.2); not with --samples or --crop (denoise
                         the merged image: pt merge --denoise) [off]
  --exposure EV          multiply the image by 2^EV (the variance layer by its square),
                         EV in [-32, 32] [0]
  --clamp X              scale down any sample whose largest channel exceeds X: fewer
                         fireflies, but biased (light is lost); 0 is off [0]
  --samples A:B          render only sample indices [A, B) of the job's -spp per pixel,
                         with the random numbers they get in a whole render; the output
                         is a part for pt merge (an .exr with the exact sums) [0:spp]
  --crop X0,Y0,X1,Y1     render only the pixels [X0, X1) x [Y0, Y1) of the image (row 0 at
                         the top); the output is a part whose EXR data window is the crop
  --resume PART          go on from PART, the .partial.exr of an interrupted render (or a
                         part) of the same job: only its missing samples are rendered
  -q, --quiet            print neither warnings nor progress (nor the libraries' own lines),
                         only errors and the summary line
  -h, --help             show this help
  --                     end of the options: a SCENE named "-x.obj" may follow

Progress goes to stderr when it is a terminal; one summary line always ends the render.
Ctrl-C (SIGINT) or SIGTERM stops the render within a moment: the samples finished so far go to
OUT with ".partial" before the extension (out.partial.exr), and OUT itself is left untouched;
an .exr partial is a part: the same command with --resume OUT.partial.exr finishes it.
A second signal quits at once, removing any file being written: nothing partial is left behind.
Images are written whole or not at all (a temporary file beside OUT, renamed into place); the
temporary file is created before rendering, so an output that cannot be written fails at once.
exit status: 0 success, 1 bad input (scene, texture) or a failed write, 2 bad usage (options,
             an output that cannot be created or is also an input), 130 or 143 interrupted
)";

// The longest --time: a year, beyond any batch job.
constexpr double kMaxTimeBudget = 365.0 * 24 * 3600;
// -spp when --time or --noise decide when to stop and -spp is not given: the cap of a pixel.
constexpr long long kBudgetSppCap = 4096;
// The smallest --noise: a pixel whose samples vary as much as their mean reaches E after 1 / E^2
// samples, 1e8 at 1e-4, beyond the 2^24 a pixel may take. Below it no pixel would ever stop, and
// in float it would round to 0, which means "off".
constexpr double kMinNoise = 1e-4;
const char* const kNoiseFloorReason =
    " (below 1e-4 no pixel stops before the most samples a pixel takes, 2^24: leave --noise out and give -spp instead)";

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

Vec3 parseDirection(const std::string& option, const std::string& v) {
    double c[3];
    char comma1 = 0, comma2 = 0, extra = 0;
    std::istringstream in(v);
    if (!(in >> c[0] >> comma1 >> c[1] >> comma2 >> c[2]) || comma1 != ',' || comma2 != ',' || (in >> extra))
        throw UsageError("option --" + option + ": expected three numbers X,Y,Z such as 1,2,-1, got \"" + v + "\"");
    for (double x : c)
        if (!std::isfinite(x) || std::abs(x) > 1e30)
            throw UsageError("option --" + option + ": " + v + " has a component that is not a number of magnitude below 1e30");
    double length = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (!(length > 1e-20)) throw UsageError("option --" + option + ": " + v + " has no direction (zero length)");
    return Vec3(float(c[0] / length), float(c[1] / length), float(c[2] / length));
}

void parseResolution(const std::string& v, int& w, int& h) {
    unsigned long long a = 0, b = 0;
    char x = 0, extra = 0;
    std::istringstream in(v);
    bool digitsOnly = v.find_first_not_of("0123456789xX") == std::string::npos;
    if (!digitsOnly || !(in >> a >> x >> b) || (x != 'x' && x != 'X') || (in >> extra) || a == 0 || b == 0)
        throw UsageError("option --res: expected WIDTHxHEIGHT with two positive sizes such as 512x512, got \"" + v + "\"");
    if (a > 65536 || b > 65536) throw UsageError("option --res: " + v + " exceeds the 65536 pixel limit per side");
    w = int(a);
    h = int(b);
}

// An option whose value names one of a setting's values.
template <typename E, size_t N>
void setNamed(Args& args, const std::string& opt, const NamedValue<E> (&table)[N], E& value) {
    std::string v = args.value(opt);
    if (!valueNamed(table, v, value))
        throw UsageError("option --" + opt + ": expected " + namesOf(table) + ", got \"" + v + "\"");
}

RenderArgs parseArgs(int argc, char** argv) {
    RenderArgs r;
    Args args(argc, argv, 1);
    std::vector<std::string> positional;
    while (!args.done()) {
        std::string opt;
        if (!args.nextOption(opt)) {
            positional.push_back(args.positional());
            continue;
        }
        if (opt == "h" || opt == "help") {
            std::fputs(kRenderUsage, stdout);
            std::exit(0);
        } else if (opt == "o" || opt == "output") {
            r.output = args.value(opt);
        } else if (opt == "spp") {
            r.spp = args.integer(opt, 1, 1 << 24);
            r.sppGiven = true;
        } else if (opt == "time") {
            r.budget.seconds = args.number(opt, 0.0, kMaxTimeBudget);
            if (!(r.budget.seconds > 0.0))
                throw UsageError("option " + args.spelled(opt) + ": expected a time in seconds above 0, got 0");
        } else if (opt == "noise") {
            double e = args.number(opt, 0.0, 1.0);
            if (!(e >= kMinNoise && e < 1.0))
                throw UsageError("option " + args.spelled(opt) + ": expected a relative error in [1e-4, 1), such as 0.02, "
                                 "got " + shortNumber(e) + (e > 0.0 && e < kMinNoise ? kNoiseFloorReason : ""));
            r.budget.noise = float(e);
        } else if (opt == "min-spp") {
            r.budget.minSpp = uint32_t(args.integer(opt, 1, 1 << 24));
            r.minSppGiven = true;
        } else if (opt == "res") {
            parseResolution(args.value(opt), r.width, r.height);
            r.resGiven = true;
        } else if (opt == "camera") {
            r.camera = args.value(opt);
        } else if (opt == "threads") {
            r.threads = int(args.integer(opt, 0, 4096));
        } else if (opt == "seed") {
            r.settings.seed = uint64_t(args.integer(opt, 0, 2147483647)); // an int in the EXR metadata
        } else if (opt == "max-depth") {
            r.settings.maxDepth = int(args.integer(opt, 0, 100000));
        } else if (opt == "light-sampling") {
            setNamed(args, opt, kLightSamplingNames, r.settings.lightSampling);
        } else if (opt == "light-choice") {
            setNamed(args, opt, kLightChoiceNames, r.settings.lightChoice);
        } else if (opt == "hemisphere") {
            setNamed(args, opt, kHemisphereNames, r.settings.hemisphere);
        } else if (opt == "sampler") {
            setNamed(args, opt, kSamplerNames, r.settings.sampler);
        } else if (opt == "aov") {
            r.aovs = parseAovList(args.value(opt));
        } else if (opt == "denoise") {
            r.denoise = true;
        } else if (opt == "exposure") {
            r.exposure = args.number(opt, -kMaxExposure, kMaxExposure);
        } else if (opt == "clamp") {
            r.settings.clamp = float(args.number(opt, 0.0, 1e30));
        } else if (opt == "env") {
            r.env = args.value(opt);
        } else if (opt == "env-rotate") {
            r.envRotate = args.number(opt, -36000.0, 36000.0);
            r.envRotateGiven = true;
        } else if (opt == "env-scale") {
            r.envScale = args.number(opt, 0.0, 1e30);
            r.envScaleGiven = true;
        } else if (opt == "sky") {
            r.sky = true;
        } else if (opt == "sun-elevation" || opt == "sun-azimuth") {
            double& angle = opt == "sun-elevation" ? r.sunElevation : r.sunAzimuth;
            angle = opt == "sun-elevation" ? args.number(opt, -90.0, 90.0) : args.number(opt, -36000.0, 36000.0);
            r.sunAnglesGiven = true;
            if (r.skyOption.empty()) r.skyOption = args.spelled(opt);
        } else if (opt == "sun-dir") {
            r.skyParameters.sunDirection = parseDirection(opt, args.value(opt));
            r.sunDirGiven = true;
            if (r.skyOption.empty()) r.skyOption = args.spelled(opt);
        } else if (opt == "turbidity") {
            double t = args.number(opt, 0.0, 1e30);
            if (!turbidityInRange(t))
                throw UsageError("option --turbidity: " + shortNumber(t) + " is out of range [1.7, 10], the range of "
                                 "Preetham et al.'s fit (1.7 very clear, 10 hazy)");
            r.skyParameters.turbidity = float(t);
            if (r.skyOption.empty()) r.skyOption = args.spelled(opt);
        } else if (opt == "sky-scale") {
            r.skyParameters.scale = float(args.number(opt, 0.0, 1e30));
            if (r.skyOption.empty()) r.skyOption = args.spelled(opt);
        } else if (opt == "samples") {
            std::string v = args.value(opt);
            size_t colon = v.find(':');
            char* end = nullptr;
            r.samplesFirst = std::strtoll(v.c_str(), &end, 10);
            bool ok = colon != std::string::npos && end == v.c_str() + colon && colon > 0;
            if (ok) {
                r.samplesLast = std::strtoll(v.c_str() + colon + 1, &end, 10);
                ok = *end == '\0' && colon + 1 < v.size();
            }
            if (!ok || r.samplesFirst < 0 || r.samplesLast <= r.samplesFirst)
                throw UsageError("option --samples: expected A:B with 0 <= A < B, got \"" + v + "\"");
            r.samplesGiven = true;
        } else if (opt == "crop") {
            std::string v = args.value(opt);
            std::stringstream in(v);
            std::string item;
            int k = 0;
            bool ok = true;
            while (std::getline(in, item, ',')) {
                char* end = nullptr;
                long long x = std::strtoll(item.c_str(), &end, 10);
                if (k >= 4 || item.empty() || *end != '\0') ok = false;
                else r.crop[k] = x;
                ++k;
            }
            if (!ok || k != 4 || r.crop[0] >= r.crop[2] || r.crop[1] >= r.crop[3] || r.crop[0] < 0 || r.crop[1] < 0)
                throw UsageError("option --crop: expected X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1, got \"" + v + "\"");
            r.cropGiven = true;
        } else if (opt == "resume") {
            r.resume = args.value(opt);
        } else if (opt == "q" || opt == "quiet") {
            r.quiet = true;
        } else {
            throw UsageError("unknown option \"" + args.spelled(opt) + "\" (pt render --help lists the options)");
        }
    }
    if (positional.empty()) throw UsageError("missing the SCENE argument");
    if (positional.size() > 1) throw UsageError("unexpected argument \"" + positional[1] + "\"; expected one SCENE");
    r.scene = positional[0];
    if ((r.envRotateGiven || r.envScaleGiven) && r.env.empty())
        throw UsageError(std::string(r.envRotateGiven ? "--env-rotate" : "--env-scale") + " needs --env PATH");
    if (!r.skyOption.empty() && !r.sky) throw UsageError(r.skyOption + " needs --sky");
    if (r.sky && !r.env.empty()) throw UsageError("--sky and --env both set the environment; give one of them");
    if (r.sunAnglesGiven && r.sunDirGiven)
        throw UsageError("--sun-dir and --sun-elevation/--sun-azimuth both place the sun; give one or the other");
    if (!r.sunDirGiven) r.skyParameters.sunDirection = sunDirectionFromAngles(r.sunElevation, r.sunAzimuth);
    if (double peak = r.sky ? skyPeakRadiance(r.skyParameters) : 0.0; !(peak <= kMaxRadiance))
        throw UsageError("option --sky-scale: " + shortNumber(r.skyParameters.scale) + " makes the sky's peak radiance "
                         "(the sun's disk where it is up) " + shortNumber(peak) + ", beyond the 1e18 whose samples fit "
                         "in float; at most " + shortNumber(kMaxRadiance / (peak / r.skyParameters.scale)) +
                         " for this sun and turbidity");
    if (!r.sppGiven && (r.budget.seconds > 0.0 || r.budget.adaptive())) r.spp = kBudgetSppCap;
    if (r.minSppGiven && !r.budget.adaptive()) throw UsageError("--min-spp needs --noise");
    // The default --min-spp follows a smaller -spp; one the user typed above -spp is refused.
    if (r.budget.adaptive() && !r.minSppGiven) r.budget.minSpp = uint32_t(std::min<long long>(r.budget.minSpp, r.spp));
    if (r.budget.adaptive() && r.budget.minSpp > r.spp)
        throw UsageError("--min-spp " + std::to_string(r.budget.minSpp) + " is above -spp " + std::to_string(r.spp) +
                         ", the most samples a pixel takes");
    if (r.budget.adaptive() && r.samplesGiven)
        throw UsageError("--noise decides per pixel from all of its samples, which a --samples part does not see; "
                         "split an adaptive render with --crop (each crop adaptive over its own pixels)");
    if (r.denoise && r.part())
        throw UsageError(std::string("--denoise with ") + (r.samplesGiven ? "--samples" : "--crop") +
                         ": a part is denoised only once merged (denoising the parts apart would not give the "
                         "merged image); render the parts with --aov albedo,normal and run pt merge --denoise");
    bool anyAov = r.aovs.any();
    if ((r.part() || !r.resume.empty()) && formatFromPath(r.output) != ImageFormat::Exr)
        throw UsageError(std::string(r.samplesGiven ? "--samples" : r.cropGiven ? "--crop" : "--resume") +
                         " writes a part for pt merge, which needs an .exr output, not \"" + r.output + "\"");
    if (anyAov && formatFromPath(r.output) != ImageFormat::Exr)
        throw UsageError("--aov needs an .exr output; \"" + r.output + "\" cannot hold extra layers");
    // Film sums (2 x 3 doubles), sample counts and the output copies: about 80 bytes a pixel.
    double bytes = double(r.width) * r.height * 80.0;
    double physical = physicalMemoryBytes();
    if (physical > 0 && bytes > 0.8 * physical)
        throw UsageError("--res " + std::to_string(r.width) + "x" + std::to_string(r.height) + " needs about " +
                         std::to_string(int(bytes / 1e9)) + " GB, more than this machine's memory");
    return r;
}

// --camera: a name or a 0-based index; none given is camera 0. A spec that names two cameras,
// or names one camera and is the index of another, is refused rather than resolved silently.
size_t pickCamera(const Scene& scene, const std::string& spec) {
    if (spec.empty()) return 0;
    std::vector<size_t> named;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        if (scene.cameras[i].name == spec) named.push_back(i);
    bool numeric = spec.find_first_not_of("0123456789") == std::string::npos && spec.size() < 9;
    size_t index = numeric ? std::stoul(spec) : scene.cameras.size();
    bool isIndex = index < scene.cameras.size();
    if (named.size() > 1)
        throw UsageError("--camera " + spec + ": cameras " + std::to_string(named[0]) + " and " + std::to_string(named[1]) +
                         " are both named \"" + spec + "\"; give the index of the one to render");
    if (named.size() == 1 && isIndex && named[0] != index)
        throw UsageError("--camera " + spec + ": camera " + std::to_string(named[0]) + " is named \"" + spec + "\", and camera " +
                         spec + " is another; rename one of them");
    if (named.size() == 1) return named[0];
    if (isIndex) return index;
    std::string names;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i) + " \"" + scene.cameras[i].name + "\"";
    throw UsageError("--camera " + spec + ": no such camera; the scene has " + names);
}

// Redraws one progress line on stderr until told to stop, cut to the terminal's width so that
// it never wraps onto a second line.
class ProgressLine {
public:
    ProgressLine(const RenderProgress& progress, uint32_t spp, const SampleBudget& budget, bool enabled)
        : progress_(progress), spp_(spp), budget_(budget) {
        if (enabled) thread_ = std::thread([this] { run(); });
    }
    ~ProgressLine() { stop(); }
    void stop() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        if (thread_.joinable()) {
            thread_.join();
            std::fputs("\r\033[K", stderr);
        }
    }

private:
    void run() {
        auto start = std::chrono::steady_clock::now();
        std::unique_lock<std::mutex> lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stop_; })) {
            double total = double(std::max<uint64_t>(1, progress_.total));
            double f = double(progress_.done.load()) / total;
            double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            // With a time budget the time is the measure of progress; with --noise the share of
            // pixels converged is shown, and no estimate of what is left (the samples are not known).
            if (budget_.seconds > 0.0) f = std::max(f, std::min(1.0, elapsed / budget_.seconds));
            char text[200];
            int n = std::snprintf(text, sizeof text, "%5.1f%%  %u/%u spp  %.1f s elapsed", 100.0 * f,
                                  progress_.samplesComplete.load(), spp_, elapsed);
            if (budget_.adaptive() && n > 0 && size_t(n) < sizeof text)
                n += std::snprintf(text + n, sizeof text - size_t(n), ", %.1f%% of pixels converged",
                                   100.0 * double(progress_.converged.load()) / double(std::max<uint64_t>(1, progress_.pixels)));
            if (f > 0.0 && !budget_.adaptive() && n > 0 && size_t(n) < sizeof text)
                std::snprintf(text + n, sizeof text - size_t(n), ", about %.1f s left",
                              budget_.seconds > 0.0 ? std::max(0.0, budget_.seconds - elapsed) : elapsed * (1.0 - f) / f);
            struct winsize ws {};
            size_t width = ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0 ? ws.ws_col : 80;
            std::string line(text);
            if (line.size() >= width) line.resize(width - 1); // the cursor must not reach the last column
            std::fprintf(stderr, "\r\033[K%s", line.c_str());
            std::fflush(stderr);
        }
    }

    const RenderProgress& progress_;
    uint32_t spp_;
    SampleBudget budget_;
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
};

// out.exr -> out.partial.exr: where an interrupted render puts what it finished. A name that
// would then be too long for the file system loses the end of its stem instead.
std::string partialPath(const std::string& output) {
    std::filesystem::path p(output);
    std::string stem = p.stem().string(), tail = ".partial" + p.extension().string();
    long longest = maxNameLength(p.parent_path().empty() ? "." : p.parent_path().string());
    if (long(stem.size() + tail.size()) > longest) stem.resize(size_t(std::max(1L, longest - long(tail.size()))));
    return (p.parent_path() / (stem + tail)).string();
}

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}


// Every option that changes the image, so that a file says how to make it again.
// The job's fields (render/render_job.h) and what else describes the scene and its options.
void addJobMetadata(Image& image, const RenderArgs& args, const Scene& scene, size_t cameraIndex,
                    const std::string& sceneHash) {
    JobMetadataWriter write(image);
    auto text = [&](const char* k, const std::string& v) { write.text(k, v); };
    auto integer = [&](const char* k, long long v) { write.integer(k, v); };
    auto real = [&](const char* k, double v) { write.real(k, v); };
    std::error_code ec;
    std::string resolved = std::filesystem::weakly_canonical(std::filesystem::absolute(scene.path, ec), ec).string();
    text("Software", "pt " PT_VERSION);
    text("pt:version", PT_VERSION);
    text("pt:scene", args.scene);
    text("pt:sceneResolved", ec ? args.scene : resolved);
    text("pt:sceneHash", sceneHash);
    integer("pt:fullWidth", args.width);
    integer("pt:fullHeight", args.height);
    text("pt:camera", scene.cameras[cameraIndex].name);
    integer("pt:cameraIndex", (long long)cameraIndex); // two cameras may share a name
    if (const auto& preetham = scene.environment.preetham) { // from --sky or the MTL
        const SkyParameters* sky = &preetham->parameters();
        const Vec3& d = sky->sunDirection;
        text("pt:environment", "preetham");
        text("pt:sunDirection", shortNumber(d.x) + "," + shortNumber(d.y) + "," + shortNumber(d.z));
        real("pt:sunElevation", sunElevationDegrees(d));
        real("pt:sunAzimuth", sunAzimuthDegrees(d));
        real("pt:turbidity", sky->turbidity);
        real("pt:skyScale", sky->scale);
    } else if (const auto& map = scene.environment.map) { // from --env or the MTL
        text("pt:env", map->path);
        real("pt:envRotate", double(map->rotation()) * 180.0 / kPi);
        real("pt:envScale", map->scale);
    }
    integer("pt:sppRequested", args.spp);
    integer("pt:seed", (long long)args.settings.seed);
    integer("pt:maxDepth", args.settings.maxDepth);
    text("pt:sampler", nameOf(kSamplerNames, args.settings.sampler));
    text("pt:lightSampling", nameOf(kLightSamplingNames, args.settings.lightSampling));
    text("pt:lightChoice", nameOf(kLightChoiceNames, args.settings.lightChoice));
    text("pt:hemisphere", nameOf(kHemisphereNames, args.settings.hemisphere));
    real("pt:clamp", args.settings.clamp);
    real("pt:exposure", args.exposure);
    if (args.budget.adaptive()) { // a part must be resumed and merged with the same rule
        real("pt:noise", args.budget.noise);
        integer("pt:minSpp", std::min<long long>(args.budget.minSpp, args.spp));
    }
}

// What this run did, after the job's fields; a part's share of the job and its window.
void addRunMetadata(Image& image, const RenderArgs& args, const RenderResult& result, int threads,
                    uint32_t first, uint32_t last, const PixelWindow& window, bool part) {
    auto integer = [&](const char* k, long long v) { image.metadata.push_back(ImageAttribute::integerValue(k, v)); };
    const Film& film = result.film;
    const Film::SampleCounts counts = film.sampleCounts();
    image.metadata.push_back(ImageAttribute::integerValue("pt:spp", counts.fewest));
    if (counts.most != counts.fewest) { // adaptive, or a resumed part: per pixel in --aov spp
        integer("pt:sppMax", counts.most);
        image.metadata.push_back(ImageAttribute::floatValue("pt:sppMean", counts.mean));
    }
    if (film.hasConvergence()) integer("pt:converged", (long long)film.convergedCount());
    if (args.budget.seconds > 0.0) {
        image.metadata.push_back(ImageAttribute::floatValue("pt:time", args.budget.seconds));
        integer("pt:outOfTime", result.outOfTime ? 1 : 0);
    }
    integer("pt:threadsRequested", args.threads);
    integer("pt:threads", threads);
    image.metadata.push_back(ImageAttribute::floatValue("pt:renderSeconds", result.seconds));
    if (!part) return;
    addPartLayers(image, result.film);
    image.x = window.x0, image.y = window.y0;
    image.fullWidth = args.width, image.fullHeight = args.height;
    integer("pt:part", 1);
    integer("pt:samplesFirst", first);
    integer("pt:samplesLast", last);
}

// Reads the part to resume and checks it belongs to this job, window and range; "" or why not.
std::string readResumePart(const std::string& path, const Image& job, const PixelWindow& window, uint32_t first,
                           uint32_t last, bool firstHitLayers, Image& part, Film& film) {
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

} // namespace

int renderCommand(int argc, char** argv) {
    FILE* err = errorStream();
    RenderArgs args;
    std::string partial;
    try {
        args = parseArgs(argc, argv);
        if (args.quiet) {
            silenceLibraryOutput();
            err = errorStream();
        }
        std::string problem = checkOutputPath(args.output);
        partial = partialPath(args.output);
        // The partial image's name must fit as well: found out only at Ctrl-C would be too late.
        if (problem.empty()) problem = checkOutputLocation(partial);
        if (problem.empty()) problem = outputIsInput({args.output, partial}, {args.scene});
        if (!problem.empty()) throw UsageError(problem);
    } catch (const UsageError& e) {
        std::fprintf(err, "pt render: %s\n", e.what());
        return 2;
    }

    // The denoiser is opened before anything is loaded or written: a missing library is a usage
    // error found at once, not after an hour of rendering.
    const int hardware = tbb::info::default_concurrency();
    const int threads = args.threads > 0 ? std::min(args.threads, hardware) : hardware;
    std::unique_ptr<Denoiser> denoiser;
    if (args.denoise) {
        int status = 0;
        denoiser = openDenoiser("pt render", threads, err, status);
        if (!denoiser) return status;
    }
    // Gathered for --aov albedo, normal, depth, and as the denoiser's guides.
    const bool firstHitLayers = args.aovs.firstHit() || args.denoise;

    RenderProgress progress;
    // Until the render starts a signal quits at once (there is nothing to keep); from then on it
    // stops the render, whose finished samples are written.
    installStopHandlers("pt: interrupted before rendering began; nothing was written\n");

    auto t0 = std::chrono::steady_clock::now();
    Scene scene;
    Warnings warnings;
    try {
        scene = loadScene(args.scene, warnings);
    } catch (const LoadError& e) {
        std::fprintf(err, "pt: error: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(err, "pt: error: %s: out of memory while loading the scene (its files or textures are too large "
                          "for this machine)\n", args.scene.c_str());
        return 1;
    }
    if (!args.env.empty()) {
        try {
            std::string warning;
            scene.environment = Environment{}; // replaces the MTL's environment, a sky included
            auto map = std::make_shared<const EnvironmentMap>(
                readEnvironmentMap(args.env, float(args.envRotate), float(args.envScale), warning));
            scene.environment.map = map;
            scene.sources.push_back({args.env, map->sourceHash});
            if (!warning.empty()) warnings.add(warning);
        } catch (const LoadError& e) {
            std::fprintf(err, "pt: error: %s\n", e.what());
            return 1;
        } catch (const std::bad_alloc&) {
            std::fprintf(err, "pt: error: %s: out of memory while reading the environment map\n", args.env.c_str());
            return 1;
        }
    }
    if (args.sky) {
        scene.environment = skyEnvironment(args.skyParameters);
        if (args.skyParameters.sunDirection.y < 0.0f)
            warnings.add("the sun is below the horizon: the model has no twilight, so the sky is that of a sun on the "
                         "horizon and the sun's disk is hidden");
    }
    addDefaultLighting(scene, warnings);
    if (args.settings.hemisphere == HemisphereSampling::Uniform) {
        // Only the lab model's Lambert lobe has the choice; glTF's BRDF samples its diffuse lobe
        // by the cosine always (its transmitting materials go through the lab model and take it).
        size_t ignoring = 0;
        for (const Material& m : scene.materials) ignoring += m.model == MaterialModel::MetalRough && !(m.transparency > 0.0f);
        if (ignoring > 0)
            warnings.add("--hemisphere uniform: " + std::to_string(ignoring) + " of the scene's " +
                         std::to_string(scene.materials.size()) + " materials (glTF metallic-roughness) ignore it and "
                         "sample their diffuse lobe by the cosine");
    }
    double loadSeconds = secondsSince(t0);

    if (args.threads > hardware)
        warnings.add("--threads " + std::to_string(args.threads) + ": this machine runs " + std::to_string(hardware) +
                     " threads at once; using " + std::to_string(hardware));
    if (!args.quiet)
        for (const std::string& w : warnings.messages()) std::fprintf(err, "pt: warning: %s\n", w.c_str());

    size_t cameraIndex;
    OutputFile output;
    std::string sceneHash;
    try {
        cameraIndex = pickCamera(scene, args.camera);
        // A camera that asks for an aspect ratio (glTF) gets it unless --res says otherwise:
        // 512 pixels across its longer side.
        if (float aspect = scene.cameras[cameraIndex].aspect; aspect > 0.0f && !args.resGiven) {
            if (aspect >= 1.0f) args.height = std::max(1, int(std::lround(512.0f / aspect)));
            else args.width = std::max(1, int(std::lround(512.0f * aspect)));
        }
        std::vector<std::string> inputs;
        for (const SourceFile& f : scene.sources) inputs.push_back(f.path);
        std::string problem = outputIsInput({args.output, partial}, inputs);
        // The partial may replace the part it resumes (read whole before rendering); OUT may not.
        if (problem.empty() && !args.resume.empty()) problem = outputIsInput({args.output}, {args.resume});
        // Created now, before any rendering: a folder that refuses it fails here, not in an hour.
        if (problem.empty()) problem = output.open(args.output);
        if (!problem.empty()) throw UsageError(problem);
        sceneHash = jobHash(scene.sources);
    } catch (const UsageError& e) {
        std::fprintf(err, "pt render: %s\n", e.what());
        return 2;
    }

    // The share of the job this run renders: sample indices [first, last) of the window's pixels.
    const uint32_t first = uint32_t(args.samplesFirst), last = args.samplesGiven ? uint32_t(args.samplesLast) : uint32_t(args.spp);
    PixelWindow window{0, 0, args.width, args.height};
    if (args.samplesGiven && (args.samplesLast > (1 << 24) || args.samplesLast > args.spp)) {
        std::fprintf(err, "pt: error: --samples %lld:%lld: %s\n", args.samplesFirst, args.samplesLast,
                     args.samplesLast > (1 << 24)
                         ? "a pixel has 16777216 (2^24) sample indices per seed; split the job among seeds no further"
                         : ("the job has -spp " + std::to_string(args.spp) + ", so its sample indices run from 0 to " +
                            std::to_string(args.spp)).c_str());
        return 1;
    }
    if (args.cropGiven) {
        if (args.crop[2] > args.width || args.crop[3] > args.height) {
            std::fprintf(err, "pt: error: --crop %lld,%lld,%lld,%lld passes the %dx%d image\n", args.crop[0], args.crop[1],
                         args.crop[2], args.crop[3], args.width, args.height);
            return 1;
        }
        window = PixelWindow{int(args.crop[0]), int(args.crop[1]), int(args.crop[2]), int(args.crop[3])};
    }
    Image job; // the job's fields, compared with a part to resume and written into the output
    addJobMetadata(job, args, scene, cameraIndex, sceneHash);
    Image resumeImage;
    Film resumeFilm(0, 0);
    if (!args.resume.empty()) {
        std::string error = readResumePart(args.resume, job, window, first, last, firstHitLayers, resumeImage, resumeFilm);
        if (!error.empty()) {
            std::fprintf(err, "pt: error: %s\n", error.c_str());
            return 1;
        }
    }

    auto t1 = std::chrono::steady_clock::now();
    std::unique_ptr<Accel> accel;
    try {
        tbb::task_arena arena(threads);
        arena.execute([&] { accel = std::make_unique<Accel>(scene, threads); });
    } catch (const LoadError& e) {
        std::fprintf(err, "pt: error: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(err, "pt: error: %s: out of memory while building the BVH of %zu triangles\n", args.scene.c_str(),
                     scene.triangleCount());
        return 1;
    }
    double bvhSeconds = secondsSince(t1);

    setStopTarget(&progress.cancel);
    ProgressLine line(progress, last - first, args.budget, !args.quiet && isatty(STDERR_FILENO));
    // The dark floor of adaptive sampling is meant in the image's units, after --exposure.
    SampleBudget budget = args.budget;
    budget.darkFloor = float(1e-3 / std::exp2(args.exposure));
    std::optional<RenderResult> rendered;
    try {
        RenderRange range{first, last, window, args.resume.empty() ? nullptr : &resumeFilm};
        rendered.emplace(renderImage(scene, *accel, scene.cameras[cameraIndex], args.width, args.height,
                                     uint32_t(args.spp), threads, args.settings, &progress,
                                     firstHitLayers, range, budget));
    } catch (const std::bad_alloc&) {
        line.stop();
        std::fprintf(err, "pt: error: out of memory for a %dx%d image; choose a smaller --res\n", args.width, args.height);
        return 1;
    }
    line.stop();
    const RenderResult& result = *rendered;

    size_t overflowed;
    Image image = filmImage(result.film, args.aovs, args.exposure, overflowed);
    if (overflowed > 0 && !args.quiet)
        std::fprintf(err, "pt: warning: %zu values of the image and its layers pass float's range (at --exposure %g) and "
                          "are written as the largest float\n", overflowed, args.exposure);
    image.metadata = job.metadata;
    // A part (or the partial image of an .exr render, so that it can be resumed or merged) carries
    // the sums merging needs.
    bool writePart = args.part() || (result.cancelled && formatFromPath(args.output) == ImageFormat::Exr);
    addRunMetadata(image, args, result, threads, first, last, window, writePart);

    if (result.cancelled) {
        // Never replace OUT with a partial image: the finished samples go beside it.
        // Every tile finished is kept, those of the first pass too (the pixels of tiles still in
        // flight then hold no sample): only when none had finished is there nothing to write.
        int status = 128 + (stopSignal() ? stopSignal() : SIGINT);
        const Film::SampleCounts done = result.film.sampleCounts();
        if (done.most == 0) {
            std::fprintf(err, "pt: interrupted before any tile of the first pass was finished; nothing written\n");
            return status;
        }
        image.metadata.push_back(ImageAttribute::integerValue("pt:interrupted", 1));
        OutputFile partialFile;
        std::string error = partialFile.open(partial);
        if (error.empty()) error = writeImage(partialFile, image);
        if (!error.empty()) std::fprintf(err, "pt: error: interrupted, and the partial image was lost: %s\n", error.c_str());
        else if (done.fewest == done.most)
            std::fprintf(err, "pt: interrupted after %u of %lld spp; wrote them to %s (%s untouched)\n", done.fewest,
                         args.spp, partial.c_str(), args.output.c_str());
        else
            std::fprintf(err, "pt: interrupted after %u to %u of %lld spp (mean %.2f)%s; wrote them to %s (%s untouched)\n",
                         done.fewest, done.most, args.spp, done.mean,
                         done.fewest == 0 ? ", pixels of the tiles in flight without a sample" : "", partial.c_str(),
                         args.output.c_str());
        return status;
    }
    // Denoised only here, whole: an interrupted render has written its raw partial above.
    DenoiseReport denoised;
    if (denoiser) {
        std::string error = denoiseImage(*denoiser, image, result.film.albedo(), result.film.normal(), DenoiseOptions{}, denoised);
        if (!error.empty()) {
            std::fprintf(err, "pt: error: %s; nothing was written\n", error.c_str());
            return 1;
        }
        if (denoised.replaced > 0 && !args.quiet)
            std::fprintf(err, "pt: warning: %zu values of the image passed float's range and were given 0 before denoising\n",
                         denoised.replaced);
    }
    if (std::string error = writeImage(output, image); !error.empty()) {
        std::fprintf(err, "pt: error: %s\n", error.c_str());
        return 1;
    }
    // The partial this run resumed is inside OUT now: left beside it, a merge of the folder
    // would count its samples twice.
    std::error_code ec;
    if (!args.resume.empty() && std::filesystem::equivalent(args.resume, partial, ec)) std::filesystem::remove(partial, ec);

    if (stopSignal() != 0)
        std::fprintf(err, "pt: the signal came after the last sample; the whole image was written\n");
    // A few discarded samples are rounding; many mean light lost somewhere: say so, not just count.
    const Film& film = result.film;
    const Film::SampleCounts counts = film.sampleCounts();
    uint64_t samples = uint64_t(std::llround(double(window.width()) * window.height() * counts.mean));
    if (!args.quiet && result.rays.discarded > std::max<uint64_t>(10, samples / 10000))
        std::fprintf(err, "pt: warning: %llu of %llu samples came out NaN, infinite or negative and were dropped; the image is "
                          "darker than it should be where they fell\n",
                     (unsigned long long)result.rays.discarded, (unsigned long long)samples);
    const RayCounts& r = result.rays;
    std::string clampNote =
        args.settings.clamp > 0.0f ? ", " + std::to_string(r.clamped) + " clamped (--clamp biases the image)" : "";
    // Pixels of an adaptive render hold different counts: the range, the mean and what stopped it.
    char sppText[160];
    if (counts.most == counts.fewest) std::snprintf(sppText, sizeof sppText, "%u spp", counts.fewest);
    else std::snprintf(sppText, sizeof sppText, "%u to %u spp (mean %.1f)", counts.fewest, counts.most, counts.mean);
    std::string stopNote;
    if (film.hasConvergence())
        stopNote += ", " + std::to_string(film.convergedCount()) + " of " + std::to_string(uint64_t(window.width()) * window.height()) +
                    " pixels converged";
    if (result.outOfTime) stopNote += ", stopped by --time";
    char denoiseText[160] = "";
    if (denoiser) std::snprintf(denoiseText, sizeof denoiseText, ", denoised in %.3f s (OIDN %s)", denoised.seconds, denoiser->version().c_str());
    std::printf("pt: %dx%d, %s%s, %.3f s render (load %.3f s, bvh %.3f s)%s, %.2f Mrays/s "
                "(camera %.2fM, continuation %.2fM, shadow %.2fM), %llu discarded samples%s, %d threads -> %s\n",
                window.width(), window.height(), sppText, stopNote.c_str(), result.seconds, loadSeconds, bvhSeconds, denoiseText,
                double(r.total()) / result.seconds * 1e-6, r.camera * 1e-6, r.continuation * 1e-6, r.shadow * 1e-6,
                (unsigned long long)r.discarded, clampNote.c_str(), threads, args.output.c_str());
    return 0;
}

} // namespace pt::cli
