#include "cli/args.h"

#include "core/system.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace pt::cli {

Args::Args(int argc, char** argv, int first) {
    for (int i = first; i < argc; ++i) {
        if (endOfOptions_ == std::string::npos && std::string(argv[i]) == "--") {
            endOfOptions_ = args_.size(); // "--" itself is not an argument
            continue;
        }
        args_.emplace_back(argv[i]);
    }
}

bool Args::next(std::string& name, std::vector<std::string>& positional) {
    while (!done()) {
        if (nextOption(name)) return true;
        positional.push_back(this->positional());
    }
    // "--flag=value" as the last argument, of an option that takes none.
    if (hasPending_) throw UsageError("option " + spelled_ + " does not take a value");
    return false;
}

bool Args::nextOption(std::string& name) {
    if (hasPending_) throw UsageError("option " + spelled_ + " does not take a value");
    if (pos_ >= endOfOptions_) return false;
    const std::string& a = args_[pos_];
    if (a.size() < 2 || a[0] != '-' || (a[1] >= '0' && a[1] <= '9')) return false;
    ++pos_;
    size_t dashes = a[1] == '-' ? 2 : 1;
    name = a.substr(dashes);
    if (auto eq = name.find('='); eq != std::string::npos) {
        pendingValue_ = name.substr(eq + 1);
        hasPending_ = true;
        name = name.substr(0, eq);
        pendingOption_ = name;
    }
    spelled_ = a.substr(0, dashes) + name;
    return true;
}

std::string Args::spelled(const std::string& option) const {
    return spelled_.empty() ? "--" + option : spelled_;
}

std::string Args::positional() { return args_[pos_++]; }

std::string Args::value(const std::string& option) {
    if (hasPending_) {
        hasPending_ = false;
        return pendingValue_;
    }
    if (pos_ >= args_.size()) throw UsageError("option " + spelled(option) + " needs a value");
    return args_[pos_++];
}

long long Args::integer(const std::string& option, long long lo, long long hi) {
    std::string v = value(option);
    long long x = 0;
    auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
    if (ec != std::errc() || ptr != v.data() + v.size() || v.empty())
        throw UsageError("option " + spelled(option) + ": expected an integer, got \"" + v + "\"");
    if (x < lo || x > hi)
        throw UsageError("option " + spelled(option) + ": " + v + " is out of range [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "]");
    return x;
}

double Args::number(const std::string& option, double lo, double hi) {
    std::string v = value(option);
    double x = 0;
    auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
    if (ec == std::errc::result_out_of_range && ptr == v.data() + v.size()) {
        // Underflow (1e-400) is a number, just a very small one; overflow is refused below.
        x = std::strtod(v.c_str(), nullptr);
        ec = std::errc();
    }
    if (ec != std::errc() || ptr != v.data() + v.size() || v.empty() || !std::isfinite(x))
        throw UsageError("option " + spelled(option) + ": expected a finite number, got \"" + v + "\"");
    if (x < lo || x > hi)
        throw UsageError("option " + spelled(option) + ": " + v + " is out of range [" + shortNumber(lo) + ", " +
                         shortNumber(hi) + "]");
    return x;
}

AovSelection parseAovList(const std::string& value) {
    AovSelection aovs;
    std::stringstream list(value);
    for (std::string name; std::getline(list, name, ',');) {
        if (name == "variance") aovs.variance = true;
        else if (name == "albedo") aovs.albedo = true;
        else if (name == "normal") aovs.normal = true;
        else if (name == "depth") aovs.depth = true;
        else if (name == "spp") aovs.spp = true;
        else throw UsageError("option --aov: unknown layer \"" + name + "\"; known: variance, albedo, normal, depth, spp");
    }
    return aovs;
}

} // namespace pt::cli
