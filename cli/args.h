// Command-line parsing shared by the subcommands. Options may be written -name or --name, with
// the value as the next argument or after '='; "--" ends the options, so a file named "-x.obj"
// can follow it. Errors are UsageError (exit status 2) and quote the option as it was typed.
#pragma once

#include "render/film_image.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace pt::cli {

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Args {
public:
    Args(int argc, char** argv, int first);

    // The next option's name without dashes (its "=value" kept for value()), after adding the
    // positional arguments before it to `positional`; false once every argument is read.
    bool next(std::string& name, std::vector<std::string>& positional);
    std::string value(const std::string& option);
    long long integer(const std::string& option, long long lo, long long hi);
    double number(const std::string& option, double lo, double hi); // finite, in [lo, hi]
    // The option as the user typed it ("-o", "--spp"), for messages.
    std::string spelled(const std::string& option) const;

private:
    bool done() const { return pos_ >= args_.size(); }
    // If the next argument is an option, returns its name without dashes (and splits "=value").
    bool nextOption(std::string& name);
    std::string positional();

    std::vector<std::string> args_;
    size_t pos_ = 0;
    std::string pendingOption_, pendingValue_, spelled_;
    bool hasPending_ = false;
    size_t endOfOptions_ = std::string::npos; // index of the first argument after "--"
};

// The layers of an --aov list ("variance,albedo"); a UsageError names an unknown one.
AovSelection parseAovList(const std::string& value);

} // namespace pt::cli
