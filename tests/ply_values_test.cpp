// PlyValues.*: the values of a PLY body are checked, not only its structure: a vertex of
// NaN or infinity is an error naming the element (it was dropped as a "zero area"
// triangle), an ASCII line with a value missing or one too many is an error naming the
// line and element (the values after it shifted by one), a binary body is read as written
// whatever its first byte, and a face's texcoord list must fit its vertices.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "host/readers/load_scene.hpp"
#include "tests/scene_test_util.hpp"

namespace facet {
namespace {

using test::expect_error;
using test::TempDir;

// Four vertices (one per line after the header's 10 lines) and two triangles.
std::string square_ply(const std::string& vertex2) {
    std::string s =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n";
    s += vertex2;
    s += "\n0 1 0\n3 0 1 2\n3 0 2 3\n";
    return s;
}

// square_ply("1 1 0") with the first `from` replaced by `to`.
std::string square_ply_with(const std::string& from, const std::string& to) {
    std::string s = square_ply("1 1 0");
    s.replace(s.find(from), from.size(), to);
    return s;
}

TEST(PlyValues, NonFiniteVerticesAreErrors) {
    TempDir d;
    EXPECT_GE(load_scene(d.write("ok.ply", square_ply("1 1 0"))).triangle_count(), 2u);
    expect_error([&] { load_scene(d.write("nan.ply", square_ply("1 nan 0"))); },
                 {"nan.ply", "element 'vertex' 2", "not finite"});
    expect_error([&] { load_scene(d.write("inf.ply", square_ply("inf 1 0"))); },
                 {"inf.ply", "element 'vertex' 2", "not finite"});
    // Binary: vertex 1's y is a NaN.
    std::string bin =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float v[9] = {0, 0, 0, 1, std::numeric_limits<float>::quiet_NaN(), 0, 0, 1, 0};
    bin.append(reinterpret_cast<const char*>(v), sizeof v);
    const unsigned char n = 3;
    const int idx[3] = {0, 1, 2};
    bin.push_back(char(n));
    bin.append(reinterpret_cast<const char*>(idx), sizeof idx);
    expect_error([&] { load_scene(d.write("nan_bin.ply", bin)); }, {"nan_bin.ply", "element 'vertex' 1", "not finite"});
}

TEST(PlyValues, AsciiLineWithAValueMissingOrTooManyIsAnError) {
    TempDir d;
    expect_error([&] { load_scene(d.write("short.ply", square_ply("1 1"))); },
                 {"short.ply:12:", "element 'vertex' 2 has 2 values on its line"});
    expect_error([&] { load_scene(d.write("long.ply", square_ply("1 1 0 7"))); },
                 {"long.ply:12:", "element 'vertex' 2 has more values on its line than the 3"});
    const std::string face = square_ply_with("3 0 2 3", "3 0 2");
    expect_error([&] { load_scene(d.write("face.ply", face)); }, {"face.ply:15:", "element 'face' 1 has 3 values"});
    // Blank lines between elements and CRLF line ends are fine.
    std::string crlf;
    for (char c : square_ply("1 1 0")) {
        if (c == '\n') crlf.push_back('\r');
        crlf.push_back(c);
    }
    crlf.insert(crlf.find("0 1 0"), "\n\n");
    EXPECT_GE(load_scene(d.write("crlf.ply", crlf)).triangle_count(), 2u);
}

// Assimp 5.2 drops the first byte of a binary body when it is a newline (0x0A), meant for
// "end_header\r\n" files, so a file whose first vertex's first byte is 0x0A was read one
// byte out of step (its triangles degenerate or garbage). Every byte that a text reader
// might take for white space, after either line end, either byte order, is read as written.
TEST(PlyValues, BinaryBodyStartingWithWhiteSpaceBytesIsReadAsWritten) {
    TempDir d;
    for (const bool big : {false, true})
        for (const char* end : {"\n", "\r\n"})
            for (const unsigned char first : {0x0A, 0x0D, 0x20, 0x09, 0x00, 0x3F}) {
                SCOPED_TRACE(testing::Message()
                             << "big endian " << big << ", end_header" << (end[0] == '\r' ? "\\r\\n" : "\\n")
                             << ", first byte " << int(first));
                std::string bin =
                    std::string("ply\nformat binary_") + (big ? "big" : "little") +
                    "_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header" +
                    end;
                // x of vertex 0, a finite float whose first byte in the file is `first`.
                const std::uint32_t x0_bits = big ? std::uint32_t(first) << 24 | 0x3F8000u : 0x3F800000u | first;
                float x0 = 0;
                std::memcpy(&x0, &x0_bits, 4);
                const float v[9] = {x0, 0, 0, 3, 0, 0, 0, 2, 0};
                auto put = [&](const void* p) {  // 4 bytes in the file's order
                    unsigned char b[4];
                    std::memcpy(b, p, 4);
                    for (int k = 0; k < 4; ++k) bin.push_back(char(b[big ? 3 - k : k]));
                };
                for (float f : v) put(&f);
                bin.push_back(char(3));
                for (int i : {0, 1, 2}) put(&i);
                ASSERT_EQ(static_cast<unsigned char>(bin[bin.find("end_header") + 10 + std::strlen(end)]), first);
                const Scene s = load_scene(d.write("first.ply", bin));
                ASSERT_GE(s.vertices.size(), 3u);
                EXPECT_EQ(s.vertices[0], glm::vec3(x0, 0, 0));
                EXPECT_EQ(s.vertices[1], glm::vec3(3, 0, 0));
                EXPECT_EQ(s.vertices[2], glm::vec3(0, 2, 0));
            }
}

// Per-face texcoords (two per vertex of the face) load; more than two per vertex were read
// past the face's index list by Assimp 5.2, and are an error naming the face, ASCII or binary.
TEST(PlyValues, FaceTexcoordListsMatchTheirFaces) {
    TempDir d;
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_GE(load_scene(d.write("uv.ply", head + "3 0 1 2 6 0 0 1 0 0 1\n")).triangle_count(), 1u);
    expect_error([&] { load_scene(d.write("uv8.ply", head + "3 0 1 2 8 0 0 1 0 0 1 1 1\n")); },
                 {"uv8.ply:14:", "element 'face' 0 has a 'texcoord' list of 8 values for 3 vertices"});
    std::string bin =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
        "property list uchar float texcoord\nend_header\n";
    const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    bin.append(reinterpret_cast<const char*>(v), sizeof v);
    bin.push_back(char(2));  // two vertex indices, six texcoords
    const int idx[2] = {0, 1};
    bin.append(reinterpret_cast<const char*>(idx), sizeof idx);
    bin.push_back(char(6));
    const float uv[6] = {0, 0, 1, 0, 0, 1};
    bin.append(reinterpret_cast<const char*>(uv), sizeof uv);
    expect_error([&] { load_scene(d.write("uv_bin.ply", bin)); },
                 {"uv_bin.ply: element 'face' 0 has a 'texcoord' list of 6 values for 2 vertices"});
}

// A header is ASCII text: a control byte in a name made Assimp read another header than
// facet's check (and a list count from elsewhere in the body); UTF-8 is fine in comments.
TEST(PlyValues, HeaderIsTextWithUtf8OnlyInComments) {
    TempDir d;
    std::string ok = square_ply("1 1 0");
    ok.insert(ok.find("element"), "comment scanned by J\xC3\xBCrgen\n");
    EXPECT_GE(load_scene(d.write("utf8.ply", ok)).triangle_count(), 2u);
    const std::string nul = square_ply_with("float y", std::string("float \0y", 8));
    expect_error([&] { load_scene(d.write("nul.ply", nul)); }, {"nul.ply:5:", "byte 0x00 in a PLY header line"});
    const std::string cr = square_ply_with("float y", "float\ry");
    expect_error([&] { load_scene(d.write("cr.ply", cr)); }, {"cr.ply:5:", "byte 0x0D in a PLY header line"});
    const std::string latin = square_ply_with("float y", "float \xC3\xBF");
    expect_error([&] { load_scene(d.write("latin.ply", latin)); },
                 {"latin.ply:5:", "byte 0xC3 in a PLY header line", "beyond comments"});
}

// Element counts as Assimp reads them (digits, below 2^32): "+3" was 3 here and 0 there, so
// the body walked here was not the one Assimp read. 'TextureFile' is a file name to Assimp.
TEST(PlyValues, ElementCountsAreDigitsBelowTwoToThe32) {
    TempDir d;
    const std::string plus = square_ply_with("vertex 4", "vertex +4");
    expect_error([&] { load_scene(d.write("plus.ply", plus)); }, {"plus.ply:3:", "a count of digits only"});
    const std::string big = square_ply_with("vertex 4", "vertex 4294967300");
    expect_error([&] { load_scene(d.write("big.ply", big)); }, {"big.ply:3:", "below 2^32"});
    const std::string zeros = square_ply_with("vertex 4", "vertex 004");
    EXPECT_GE(load_scene(d.write("zeros.ply", zeros)).triangle_count(), 2u);
    std::string tex = square_ply("1 1 0");
    tex.insert(tex.find("end_header"), "element TextureFile 0\n");
    expect_error([&] { load_scene(d.write("tex.ply", tex)); }, {"tex.ply:9:", "an element named 'TextureFile'"});
}

// Assimp 5.2 takes a second blank line in a row (or one after "\r\n"), a line of blanks or a
// lone carriage return for an element, so these bodies lost a face, silently; they are handed
// to Assimp one element per line and load as written.
TEST(PlyValues, BlankLinesInAnAsciiBodyLoseNothing) {
    TempDir d;
    const std::string plain = square_ply("1 1 0");
    const Scene want = load_scene(d.write("plain.ply", plain));
    ASSERT_EQ(want.triangle_count(), 2u + 2u);  // the square and the default light's two
    std::string crlf;
    for (char c : plain) {
        if (c == '\n') crlf.push_back('\r');
        crlf.push_back(c);
    }
    const std::string body = "0 0 0\n";
    auto with = [&](std::string s, const std::string& at, const std::string& what) {
        s.insert(s.find(at), what);
        return s;
    };
    const std::string cases[] = {
        with(plain, "0 1 0", "\n\n"),        // two blank lines
        with(plain, "0 1 0", "  \t \n"),     // a line of blanks
        with(plain, body, "\n"),             // a blank line before the first element
        with(crlf, "0 1 0", "\r\n"),         // one blank line, CRLF
        with(plain, "3 0 2 3", "\n \n\n"),   // between faces
        with(crlf, "0 1 0", "\r \r\n"),      // a line of a CR and a blank, CRLF
        square_ply_with("1 0 0", "1\r0 0"),  // a lone CR between two values of a line
    };
    int k = 0;
    for (const std::string& c : cases) {
        SCOPED_TRACE(k++);
        const Scene got = load_scene(d.write("blank.ply", c));
        EXPECT_EQ(got.triangle_count(), want.triangle_count());
        ASSERT_GE(got.vertices.size(), 6u);
        for (int v = 0; v < 6; ++v) EXPECT_EQ(got.vertices[std::size_t(v)], want.vertices[std::size_t(v)]) << v;
    }
    const std::string ctrl = square_ply_with("1 0 0", "1 \f 0");
    expect_error([&] { load_scene(d.write("ctrl.ply", ctrl)); }, {"ctrl.ply:11:", "byte 0x0C in the PLY body"});
}

// Each ASCII value must read whole as its type: Assimp 5.2 stops inside "1-5" and takes "-5"
// for the next value, so a list count could come from a place the check never saw.
TEST(PlyValues, AsciiValuesReadWholeAsTheirType) {
    TempDir d;
    for (const char* ok : {"1 1 0", "1. .5 -0", "1e0 +1E-0 0.0e+0", "1 1 0.0"})
        EXPECT_GE(load_scene(d.write("ok.ply", square_ply(ok))).triangle_count(), 2u) << ok;
    expect_error([&] { load_scene(d.write("dash.ply", square_ply("1-5 1 0"))); },
                 {"dash.ply:12:", "element 'vertex' 2 has '1-5' where its property 'x' needs a number"});
    expect_error([&] { load_scene(d.write("e.ply", square_ply("1 1e 0"))); }, {"e.ply:12:", "'1e'"});
    const std::string face = square_ply_with("3 0 2 3", "3 0 2 3.5");
    expect_error([&] { load_scene(d.write("idx.ply", face)); },
                 {"idx.ply:15:", "element 'face' 1 has '3.5' where its property 'vertex_indices' needs an integer"});
}

// The format line is the second line, once: Assimp 5.2 takes line 2 for it whatever it
// says, so "format ascii" there and a binary format below had it read another body.
TEST(PlyValues, FormatIsTheSecondLineAndComesOnce) {
    TempDir d;
    expect_error(
        [&] { load_scene(d.write("twice.ply", square_ply_with("end_header", "format ascii 1.0\nend_header"))); },
        {"twice.ply:9:", "a second 'format' line"});
    expect_error(
        [&] {
            load_scene(d.write("late.ply", square_ply_with("format ascii 1.0\n", "comment x\nformat ascii 1.0\n")));
        },
        {"late.ply:2:", "the second line of a PLY file must be its 'format' line"});
    expect_error([&] { load_scene(d.write("version.ply", square_ply_with("ascii 1.0", "ascii ply"))); },
                 {"version.ply:2:", "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'"});
}

// Assimp 5.2 ends an element's property list at a comment or blank line and skips the
// properties after it: such a header is an error naming the line; before an element, fine.
TEST(PlyValues, NoCommentOrBlankLineBetweenAnElementsProperties) {
    TempDir d;
    expect_error(
        [&] { load_scene(d.write("c.ply", square_ply_with("property float y", "comment y\nproperty float y"))); },
        {"c.ply:5:", "a comment between the properties of element 'vertex'", "before the 'element' line"});
    expect_error([&] { load_scene(d.write("b.ply", square_ply_with("property float z", "\nproperty float z"))); },
                 {"b.ply:6:", "a blank line between the properties of element 'vertex'"});
    EXPECT_EQ(load_scene(d.write("ok.ply", square_ply_with("element face", "comment faces\n\nelement face")))
                  .triangle_count(),
              2u + 2u);  // the square and the default light's two
}

}  // namespace
}  // namespace facet
