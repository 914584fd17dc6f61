// Subcommands of the pt executable. Each returns the process exit status:
// 0 success, 1 bad input (a scene or image that cannot be used), 2 bad usage.
#pragma once

namespace pt::cli {

int renderCommand(int argc, char** argv); // argv[0] is "render"
int diffCommand(int argc, char** argv);   // argv[0] is "diff"
int mergeCommand(int argc, char** argv);  // argv[0] is "merge"
int denoiseCommand(int argc, char** argv); // argv[0] is "denoise"

} // namespace pt::cli
