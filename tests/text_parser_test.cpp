#include "obj/text_parser.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

TEST(TextParser, LinesAcceptCrLfAndMissingFinalNewline) {
    std::string file = "t.obj";
    LineReader lines("a\r\nb\n\nc", file);
    std::vector<std::string> got;
    std::string_view l;
    while (lines.next(l)) got.emplace_back(l);
    EXPECT_EQ(got, (std::vector<std::string>{"a", "b", "", "c"}));
    EXPECT_EQ(lines.lineNumber(), 4u);
}

TEST(TextParser, NumbersAndErrorsNameFileAndLine) {
    std::string file = "scene.mtl";
    LineReader lines("x\ny\n", file);
    std::string_view l;
    lines.next(l);
    lines.next(l); // line 2
    auto parse = [&](const char* text) {
        Tokens t(text, lines);
        return t.number("Kd");
    };
    EXPECT_FLOAT_EQ(parse("1.5"), 1.5f);
    EXPECT_FLOAT_EQ(parse("+2e-3"), 2e-3f);
    EXPECT_FLOAT_EQ(parse("-.5"), -0.5f);
    for (const char* bad : {"abc", "1.5x", "nan", "inf", "1e99", ""}) {
        try {
            parse(bad);
            ADD_FAILURE() << "accepted \"" << bad << "\"";
        } catch (const LoadError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("scene.mtl:2: Kd:", 0), 0u) << e.what();
        }
    }
}

TEST(TextParser, ColorTakesOneOrThreeValues) {
    std::string file = "m.mtl";
    LineReader lines("", file);
    Tokens one(" 0.5 ", lines);
    EXPECT_EQ(one.color("Kd"), Spectrum(0.5f));
    Tokens three("0.1 0.2 0.3 # comment", lines);
    EXPECT_EQ(three.color("Kd"), Spectrum(0.1f, 0.2f, 0.3f));
    EXPECT_TRUE(three.empty());
    Tokens two("0.1 0.2", lines);
    EXPECT_THROW(two.color("Kd"), LoadError);
}

TEST(TextParser, RejectsNulBytes) {
    std::string file = "bin.obj";
    std::string text = std::string("v 1 2 3\nv \0\x01\x02", 13);
    // Rejected before any line is read, with the line of the first NUL.
    try {
        LineReader lines(text, file);
        FAIL() << "no error";
    } catch (const LoadError& e) {
        EXPECT_STREQ(e.what(), "bin.obj:2: contains a NUL byte; expected a text file, not binary data");
    }
}

TEST(TextParser, CaseInsensitiveKeywords) {
    EXPECT_TRUE(equalsIgnoreCase("map_kd", "MAP_Kd"));
    EXPECT_FALSE(equalsIgnoreCase("Kd", "Ks"));
    EXPECT_FALSE(equalsIgnoreCase("Kd", "Kdx"));
}

} // namespace
} // namespace pt
