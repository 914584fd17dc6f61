#include "obj/text_parser.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace pt {

// 1-based line of byte `offset`, counting LF, CR and CRLF each as one line break.
static size_t lineOfOffset(std::string_view text, size_t offset) {
    size_t line = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i)
        if (text[i] == '\n' || (text[i] == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n'))) ++line;
    return line;
}

std::string readTextFile(const std::string& path) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0)
        throw LoadError(path + ": cannot open: " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw LoadError(path + ": is a directory, expected a scene file");
    if (!S_ISREG(st.st_mode)) throw LoadError(path + ": is not a regular file (a device or pipe?)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw LoadError(path + ": cannot open: " + std::strerror(errno));
    // Binary content shows in the first block: refuse it before reading (and allocating) the
    // whole file, which for a 2 GB sparse file of zeros would take seconds and gigabytes.
    std::string head(size_t(std::min<off_t>(st.st_size, 65536)), '\0');
    in.read(head.data(), std::streamsize(head.size()));
    if (size_t(in.gcount()) != head.size()) throw LoadError(path + ": read failed");
    if (size_t nul = head.find('\0'); nul != std::string::npos)
        throw LoadError(path, lineOfOffset(head, nul), "contains a NUL byte; expected a text file, not binary data");
    double physical = physicalMemoryBytes();
    if (physical > 0 && double(st.st_size) > 0.5 * physical)
        throw LoadError(path + ": is " + std::to_string(int(double(st.st_size) / 1e9 + 0.5)) +
                        " GB, more than half this machine's memory; a scene text file must fit in memory");
    std::string text;
    try {
        text.resize(size_t(st.st_size));
    } catch (const std::bad_alloc&) {
        throw LoadError(path + ": out of memory reading its " + std::to_string(st.st_size) + " bytes");
    }
    std::memcpy(text.data(), head.data(), head.size());
    in.read(text.data() + head.size(), std::streamsize(text.size() - head.size()));
    if (size_t(in.gcount()) != text.size() - head.size()) throw LoadError(path + ": read failed");
    return text;
}

LineReader::LineReader(std::string_view text, const std::string& file) : text_(text), file_(file) {
    size_t nul = text.find('\0');
    if (nul != std::string_view::npos)
        throw LoadError(file_, lineOfOffset(text, nul), "contains a NUL byte; expected a text file, not binary data");
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3; // a UTF-8 byte-order mark is not part of line 1
}

bool LineReader::next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    size_t end = text_.find_first_of("\r\n", pos_); // LF, CRLF and CR (old Mac) all end a line
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (end + 1 < text_.size() && text_[end] == '\r' && text_[end + 1] == '\n') ++pos_;
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
    if (ec == std::errc::result_out_of_range && ptr == digits.data() + digits.size()) {
        // Out of float's range: an underflow (1e-320) is a number, zero in float; an overflow is not.
        double d = std::strtod(std::string(digits.substr(0, 400)).c_str(), nullptr);
        if (std::abs(d) < 1.0) {
            value = float(d);
            ec = std::errc();
        } else {
            fail(std::string(what) + ": " + quoted(w) + " is beyond float's range (+-3.4e38)");
        }
    }
    if (ec == std::errc() && !std::isfinite(value)) fail(std::string(what) + ": " + quoted(w) + " is not a finite number");
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

} // namespace pt
