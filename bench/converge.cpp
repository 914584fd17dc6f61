// pt-bench converge: error against time for each sampling method on one scene. Each method
// renders at 1, 2, 4, ... samples per pixel until a render takes longer than half the budget;
// the error is the relative MSE against a high-sample reference rendered by pt itself (MIS with
// Sobol), cached as an EXR, averaged over several seeds where renders are short. Writes one CSV
// row per sample count; bench/plot_convergence.py charts it.
#include "accel/accel.h"
#include "bench/bench_common.h"
#include "image/image_io.h"
#include "io/output_file.h"
#include "render/renderer.h"
#include "load/scene_loader.h"

#include <tbb/task_arena.h>

#include <cstring>
#include <filesystem>
#include <sstream>

namespace pt::bench {
namespace {

struct Method {
    const char* name;
    RenderSettings settings;
};

// The study of sampling methods (the lab's path to MIS), or of how an emitter is chosen.
std::vector<Method> methods(const std::string& study) {
    auto make = [](HemisphereSampling h, LightSampling l, SamplerKind s) {
        RenderSettings r;
        r.hemisphere = h;
        r.lightSampling = l;
        r.sampler = s;
        r.seed = 1;
        return r;
    };
    using H = HemisphereSampling;
    using L = LightSampling;
    using S = SamplerKind;
    if (study == "light-choice") {
        auto choose = [&](LightChoice c, L l) {
            RenderSettings r = make(H::Cosine, l, S::Sobol);
            r.lightChoice = c;
            return r;
        };
        return {
            {"NEE, emitter by power", choose(LightChoice::Power, L::Nee)},
            {"NEE, emitter by light tree", choose(LightChoice::Tree, L::Nee)},
            {"MIS, emitter by power", choose(LightChoice::Power, L::Mis)},
            {"MIS, emitter by light tree (default)", choose(LightChoice::Tree, L::Mis)},
        };
    }
    return {
        {"uniform hemisphere, BSDF only", make(H::Uniform, L::Bsdf, S::Random)},
        {"uniform hemisphere + NEE (the lab's start)", make(H::Uniform, L::Nee, S::Random)},
        {"cosine, BSDF sampling only", make(H::Cosine, L::Bsdf, S::Random)},
        {"cosine, light sampling only (NEE)", make(H::Cosine, L::Nee, S::Random)},
        {"cosine, MIS, random", make(H::Cosine, L::Mis, S::Random)},
        {"cosine, MIS, Sobol (default)", make(H::Cosine, L::Mis, S::Sobol)},
    };
}

// Relative MSE: mean over pixels and channels of (x - r)^2 / (r^2 + 0.01).
double relativeMse(const std::vector<float>& x, const std::vector<float>& r) {
    double sum = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        double d = double(x[i]) - r[i];
        sum += d * d / (double(r[i]) * r[i] + 0.01);
    }
    return sum / double(x.size());
}

struct Options {
    std::string scene = "../shared/scenes/lab/cornell.obj";
    std::string name;
    int width = 256, height = 256;
    double budget = 16.0; // seconds: stop doubling once a render takes more than half of it
    uint32_t referenceSpp = 4096;
    int threads = 0;
    std::string outDir = "bench/results";
    std::string env; // an environment map, as pt render --env
    std::string study = "sampling";
};

int usage(int status) {
    std::fputs("usage: pt-bench converge [--scene PATH] [--name NAME] [--res WxH] [--budget SECONDS]\n"
               "                        [--reference-spp N] [--threads N] [--out DIR] [--env MAP]\n"
               "                        [--study sampling|light-choice]\n"
               "defaults: lab cornell, name from the scene file, 256x256, 16 s per method, 4096-spp\n"
               "          reference cached in DIR, CSV to DIR/converge_NAME.csv, DIR = bench/results\n",
               status == 0 ? stdout : stderr);
    return status;
}

} // namespace

int runConverge(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) std::exit(usage(2));
            return argv[++i];
        };
        if (a == "--scene") o.scene = next();
        else if (a == "--name") o.name = next();
        else if (a == "--res") {
            if (std::sscanf(next().c_str(), "%dx%d", &o.width, &o.height) != 2) return usage(2);
        } else if (a == "--budget") o.budget = std::stod(next());
        else if (a == "--reference-spp") o.referenceSpp = uint32_t(std::stoul(next()));
        else if (a == "--threads") o.threads = std::stoi(next());
        else if (a == "--out") o.outDir = next();
        else if (a == "--env") o.env = next();
        else if (a == "--study") {
            o.study = next();
            if (o.study != "sampling" && o.study != "light-choice") return usage(2);
        } else if (a == "-h" || a == "--help") return usage(0);
        else return usage(2);
    }
    if (o.name.empty()) o.name = std::filesystem::path(o.scene).stem().string();
    std::filesystem::create_directories(o.outDir);
    const int threads = o.threads > 0 ? o.threads : tbb::this_task_arena::max_concurrency();

    Warnings warnings;
    Scene scene = loadScene(o.scene, warnings);
    if (!o.env.empty()) {
        std::string warning;
        scene.environment.map = std::make_shared<const EnvironmentMap>(readEnvironmentMap(o.env, 0.0f, 1.0f, warning));
    }
    std::unique_ptr<Accel> accel;
    tbb::task_arena(threads).execute([&] { accel = std::make_unique<Accel>(scene, threads); });
    const Camera& camera = scene.cameras[0];

    // The reference: reused while its size and sample count match.
    std::string refPath = o.outDir + "/converge_" + o.name + "_reference.exr";
    std::vector<float> reference;
    Image cached;
    if (readImage(refPath, cached).empty() && cached.width == o.width && cached.height == o.height) {
        for (const ImageAttribute& a : cached.metadata)
            if (a.name == "pt:spp" && a.asText() == std::to_string(o.referenceSpp)) reference = cached.rgb;
    }
    if (reference.empty()) {
        std::printf("converge %s: rendering the %u-spp reference...\n", o.name.c_str(), o.referenceSpp);
        std::fflush(stdout);
        RenderSettings ref;
        ref.seed = 999;
        RenderResult r = renderImage(scene, *accel, camera, o.width, o.height, o.referenceSpp, threads, ref);
        Image img;
        img.width = o.width;
        img.height = o.height;
        img.rgb = r.film.mean();
        img.metadata = {ImageAttribute::integerValue("pt:spp", o.referenceSpp), ImageAttribute::string("pt:scene", o.scene)};
        std::string error = writeImage(refPath, img);
        if (!error.empty()) std::fprintf(stderr, "converge: %s\n", error.c_str());
        reference = img.rgb;
        std::printf("  reference took %.1f s\n", r.seconds);
    }

    std::string csvPath = o.outDir + "/converge_" + o.name + ".csv";
    std::ostringstream csv;
    csv << "method,spp,seconds,rel_mse,renders\n"; // seconds and rel_mse: means over the renders
    for (const Method& m : methods(o.study)) {
        std::printf("  %-44s", m.name);
        for (uint32_t spp = 1;; spp *= 2) {
            // One render's error is itself noisy (a firefly more or less), worst at low sample
            // counts: average over renders with other seeds until about a second was spent.
            double seconds = 0, err = 0;
            int runs = 0;
            RenderSettings settings = m.settings;
            do {
                settings.seed = m.settings.seed + uint64_t(runs);
                RenderResult r = renderImage(scene, *accel, camera, o.width, o.height, spp, threads, settings);
                seconds += r.seconds;
                err += relativeMse(r.film.mean(), reference);
                ++runs;
            } while (seconds < 1.0 && runs < 16);
            seconds /= runs;
            err /= runs;
            csv << "\"" << m.name << "\"," << spp << "," << seconds << "," << err << "," << runs << "\n";
            std::printf(" %u:%.2g", spp, err);
            std::fflush(stdout);
            if (seconds > 0.5 * o.budget || spp >= o.referenceSpp / 8) break;
        }
        std::printf("\n");
    }
    std::string error = writeWholeFile(csvPath, csv.str());
    if (!error.empty()) {
        std::fprintf(stderr, "converge: %s\n", error.c_str());
        return 1;
    }
    std::printf("wrote %s\n", csvPath.c_str());
    return 0;
}

} // namespace pt::bench
