// Small helpers shared by the bench's modes.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace pt::bench {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

inline double medianOf(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
inline double minOf(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
inline double maxOf(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

// A flat JSON object writer: enough for result files, no dependency.
class Json {
public:
    Json& field(const std::string& key, const std::string& value) {
        std::string escaped;
        for (char c : value) {
            if (c == '"' || c == '\\') escaped += '\\';
            escaped += c;
        }
        return raw(key, "\"" + escaped + "\"");
    }
    Json& field(const std::string& key, const char* value) { return field(key, std::string(value)); }
    Json& field(const std::string& key, double value) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g", value);
        return raw(key, buf);
    }
    Json& field(const std::string& key, int value) { return raw(key, std::to_string(value)); }
    Json& raw(const std::string& key, const std::string& json) {
        body_ += (body_.empty() ? "  \"" : ",\n  \"") + key + "\": " + json;
        return *this;
    }
    std::string str() const { return "{\n" + body_ + "\n}\n"; }

private:
    std::string body_;
};

int runConverge(int argc, char** argv);
int runTextureBench(int argc, char** argv); // bench/texture_bench.cpp
int runSkyBench(int argc, char** argv);     // bench/sky_bench.cpp
int runLoadBench(int argc, char** argv);    // bench/load_bench.cpp
int runLeakBench(int argc, char** argv);    // bench/leak_bench.cpp

} // namespace pt::bench
