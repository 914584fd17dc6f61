// Line and token reading shared by the text scene formats (OBJ, MTL). Every error names the file
// and line; numbers are parsed with std::from_chars (locale-independent, no allocation).
#pragma once

#include "core/math.h"
#include "core/system.h"
#include "io/load_error.h"
#include "io/scene_limits.h"

#include <string>
#include <string_view>

namespace pt {

// Reads a whole regular file into memory, or throws a LoadError saying why it could not
// (missing, a folder, a device or pipe that could block or never end, binary content in its
// first 64 KiB, more than half the machine's memory, an allocation that fails).
std::string readTextFile(const std::string& path);

// Splits a buffer into lines: LF, CRLF and CR each end a line, a final newline may be missing, and
// a UTF-8 byte-order mark at the start is skipped.
class LineReader {
public:
    // Throws a LoadError naming the line of the first NUL byte: binary files are rejected before
    // any line is parsed, not after a screen of warnings about garbage keywords.
    LineReader(std::string_view text, const std::string& file);

    bool next(std::string_view& line);
    size_t lineNumber() const { return line_; }
    const std::string& file() const { return file_; }

private:
    std::string_view text_;
    size_t pos_ = 0;
    size_t line_ = 0;
    const std::string& file_;
};

// Tokens of one line, with typed readers that throw a LoadError naming file, line and keyword.
class Tokens {
public:
    Tokens(std::string_view line, const LineReader& where) : rest_(line), where_(where) {}

    bool empty();                 // true when only whitespace or a comment remains
    std::string_view word();      // next whitespace-separated token ("" at the end)
    std::string_view restOfLine(); // the remaining text, trimmed
    float number(std::string_view what);
    int integer(std::string_view what);
    Vec3 vec3(std::string_view what);
    // A point in the scene: three numbers within +-kMaxCoordinate (io/scene_limits.h). Embree
    // loses hits beyond it, so larger ones are refused here, where the line is known.
    Vec3 point(std::string_view what);
    // One value replicated to three channels, or three values (the MTL colour forms).
    Spectrum color(std::string_view what);
    void expectEnd(std::string_view keyword);

    [[noreturn]] void fail(const std::string& message) const;
    std::string location() const; // "file:line: ", to start a warning

private:
    void skipSpace();

    std::string_view rest_;
    const LineReader& where_;
};

// Hands every line of `text` that is not blank or a comment to parser.parseLine(keyword, tokens,
// lines), the keyword read: the line loop of OBJ and MTL alike.
template <typename Parser>
void parseLines(std::string_view text, const std::string& path, Parser& parser) {
    LineReader lines(text, path);
    std::string_view line;
    while (lines.next(line)) {
        Tokens t(line, lines);
        if (t.empty()) continue;
        std::string_view keyword = t.word();
        parser.parseLine(keyword, t, lines);
    }
}

} // namespace pt
