// PlyValues.*: the values of a PLY body are checked, not only its structure: a vertex of
// NaN or infinity is an error naming the element (it was dropped as a "zero area"
// triangle), and an ASCII line with a value missing or one too many is an error naming
// the line and element (the values after it shifted by one).
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
    std::string face = square_ply("1 1 0");
    face.replace(face.find("3 0 2 3"), 7, "3 0 2");
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

}  // namespace
}  // namespace facet
