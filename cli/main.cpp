// pt: a headless batch path tracer. This file only dispatches to the subcommands.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/console.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

static const char* kUsage = R"(pt )" PT_VERSION R"( - a headless path tracer on Embree

usage: pt <command> [options]

commands:
  render SCENE [options]   render a scene (.obj with the lab's MTL, .gltf, .glb) to .exr or .png
                           (pt render --help lists its options)
  diff TEST REF [options]  compare two renders statistically; exit 0 same, 1 different
                           (pt diff --help lists its options)
  merge PART... -o OUT     merge the parts of a split render (pt render --samples, --crop)
                           into one image (pt merge --help lists its options)
  denoise IN.exr -o OUT    denoise a render that has its albedo and normal layers, with
                           Intel Open Image Denoise (pt denoise --help lists its options)

options:
  -h, --help               show this help
  --version                print the version

exit status: 0 success, 1 bad input (scene, image or output file), 2 bad usage
)";

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    const char* cmd = argv[1];
    if (!std::strcmp(cmd, "-h") || !std::strcmp(cmd, "--help") || !std::strcmp(cmd, "help")) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    if (!std::strcmp(cmd, "--version")) {
        std::puts("pt " PT_VERSION);
        return 0;
    }
    try {
        if (!std::strcmp(cmd, "render")) return pt::cli::renderCommand(argc - 1, argv + 1);
        if (!std::strcmp(cmd, "diff")) return pt::cli::diffCommand(argc - 1, argv + 1);
        if (!std::strcmp(cmd, "merge")) return pt::cli::mergeCommand(argc - 1, argv + 1);
        if (!std::strcmp(cmd, "denoise")) return pt::cli::denoiseCommand(argc - 1, argv + 1);
    } catch (const std::bad_alloc&) { // each stage names what it allocates; this is the last resort
        std::fprintf(pt::cli::errorStream(), "pt: error: out of memory\n");
        return 1;
    } catch (const std::exception& e) { // last resort: never an uncaught exception trace
        std::fprintf(pt::cli::errorStream(), "pt: error: %s\n", e.what()); // the real stderr, even with -q
        return 1;
    }
    std::fprintf(stderr, "pt: unknown command \"%s\"\n\n%s", cmd, kUsage);
    return 2;
}
