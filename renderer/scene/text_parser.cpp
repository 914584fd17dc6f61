#include "scene/text_parser.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace pt {

std::string readTextFile(const std::string& path) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0)
        throw LoadError(path + ": cannot open: " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw LoadError(path + ": is a directory, expected a scene file");
    if (!S_ISREG(st.st_mode)) throw LoadError(path + ": is not a regular file (a device or pipe?)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw LoadError(path + ": cannot open: " + std::strerror(errno));
    std::string text;
    text.resize(size_t(st.st_size));
    in.read(text.data(), std::streamsize(text.size()));
    if (size_t(in.gcount()) != text.size()) throw LoadError(path + ": read failed");
    return text;
}

LineReader::LineReader(std::string_view text, const std::string& file) : text_(text), file_(file) {
    size_t nul = text.find('\0');
    if (nul != std::string_view::npos) {
        size_t line = 1 + size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(nul), '\n'));
        throw LoadError(file_, line, "contains a NUL byte; expected a text file, not binary data");
    }
}

bool LineReader::next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    ++line_;
    return true;
}

static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

void Tokens::skipSpace() {
    size_t i = 0;
    while (i < rest_.size() && isSpace(rest_[i])) ++i;
    rest_.remove_prefix(i);
}

bool Tokens::empty() {
    skipSpace();
    return rest_.empty() || rest_.front() == '#';
}

std::string_view Tokens::word() {
    skipSpace();
    size_t i = 0;
    while (i < rest_.size() && !isSpace(rest_[i])) ++i;
    std::string_view w = rest_.substr(0, i);
    rest_.remove_prefix(i);
    return w;
}

std::string_view Tokens::restOfLine() {
    skipSpace();
    std::string_view r = rest_;
    while (!r.empty() && isSpace(r.back())) r.remove_suffix(1);
    rest_ = {};
    return r;
}

void Tokens::fail(const std::string& message) const {
    throw LoadError(where_.file(), where_.lineNumber(), message);
}

std::string Tokens::location() const { return where_.file() + ":" + std::to_string(where_.lineNumber()) + ": "; }

static std::string quoted(std::string_view s) {
    constexpr size_t kMax = 40; // a 10 MB token must not become a 10 MB message
    std::string q = "\"" + std::string(s.substr(0, kMax));
    if (s.size() > kMax) q += "...";
    return q + "\"";
}

float Tokens::number(std::string_view what) {
    std::string_view w = word();
    if (w.empty()) fail(std::string(what) + ": expected a number, found end of line");
    std::string_view digits = w;
    if (digits.front() == '+') digits.remove_prefix(1); // from_chars rejects a leading '+'
    float value = 0.0f;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && !std::isfinite(value)))
        fail(std::string(what) + ": " + quoted(w) + " is not a finite number");
    if (ec != std::errc() || ptr != digits.data() + digits.size())
        fail(std::string(what) + ": expected a number, found " + quoted(w));
    return value;
}

int Tokens::integer(std::string_view what) {
    std::string_view w = word();
    if (w.empty()) fail(std::string(what) + ": expected an integer, found end of line");
    std::string_view digits = w;
    if (digits.front() == '+') digits.remove_prefix(1);
    int value = 0;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || ptr != digits.data() + digits.size())
        fail(std::string(what) + ": expected an integer, found " + quoted(w));
    return value;
}

Vec3 Tokens::vec3(std::string_view what) {
    float x = number(what), y = number(what), z = number(what);
    return Vec3(x, y, z);
}

Vec3 Tokens::point(std::string_view what) {
    Vec3 p = vec3(what);
    if (maxComponent(glm::abs(p)) > kMaxCoordinate)
        fail(std::string(what) + ": coordinate beyond +-1e12, the largest pt renders correctly (Embree's float "
                                 "arithmetic overflows beyond it); scale the scene down");
    return p;
}

Spectrum Tokens::color(std::string_view what) {
    float r = number(what);
    if (empty()) return Spectrum(r);
    float g = number(what), b = number(what);
    return Spectrum(r, g, b);
}

void Tokens::expectEnd(std::string_view keyword) {
    if (!empty())
        fail(std::string(keyword) + ": unexpected " + quoted(word()) + " at the end of the line");
}

std::string shortNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::tolower((unsigned char)a[i]) != std::tolower((unsigned char)b[i])) return false;
    return true;
}

std::string toLower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = char(std::tolower((unsigned char)c));
    return r;
}

} // namespace pt
