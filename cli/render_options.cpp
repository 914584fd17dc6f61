// pt render's options: parsing, the checks between options, and the help text.
#include "cli/render_options.h"
#include "cli/args.h"
#include "core/system.h"
#include "io/scene_limits.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

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
with options -s, -o, -clamp on|off, -bm, -imfchan r|g|b|m|l (see docs/scene-formats.md).
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
  --guide                path guiding: first learn where light comes from at each region of
                         the scene (training passes of 1, 2, 4, ... samples per pixel of the
                         whole image, kept as the image's first samples; within a quarter
                         of --time; stopped after 7 spp where guiding does not pay; at most
                         256 MiB),
                         then draw a share of each diffuse or glossy bounce's directions
                         from what was learnt, the share each region measured to pay (none
                         where it does not): for indirect light that next-event estimation
                         cannot aim at, such as a room lit by a bright patch of ceiling [off]
  --guide-spp N          with --guide, samples per pixel spent learning, in [1, 1023] and at
                         most -spp
                         [the largest 2^k - 1 up to a quarter of -spp, at most 63]
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

} // namespace

RenderArgs parseRenderArgs(int argc, char** argv) {
    RenderArgs r;
    Args args(argc, argv, 1);
    std::vector<std::string> positional;
    std::string opt;
    while (args.next(opt, positional)) {
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
        } else if (opt == "guide") {
            r.guide = true;
        } else if (opt == "guide-spp") {
            r.settings.guideSpp = uint32_t(args.integer(opt, 1, 1023));
            r.guideSppGiven = true;
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
    if (r.guideSppGiven && !r.guide) throw UsageError("--guide-spp needs --guide");
    // Training's passes are the image's first samples: one past -spp would be traced and thrown away.
    if (r.guideSppGiven && r.settings.guideSpp > r.spp)
        throw UsageError("--guide-spp " + std::to_string(r.settings.guideSpp) + " is above -spp " + std::to_string(r.spp) +
                         ": training's passes are the image's first samples, so it can use at most -spp of them");
    if (r.guide && !r.guideSppGiven) {
        // Training passes draw half their directions from a guide still learning (dearer, and
        // noisier where guiding does not pay): a quarter of -spp at most.
        uint32_t budget = uint32_t(std::min<long long>(63, std::max<long long>(1, r.spp / 4)));
        r.settings.guideSpp = 1;
        while (2 * r.settings.guideSpp + 1 <= budget) r.settings.guideSpp = 2 * r.settings.guideSpp + 1;
    }
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

} // namespace pt::cli
