// A strict pass over OBJ text before tinyobjloader reads it. tinyobjloader is
// lenient (a bad number becomes 0, a bad index drops the face) and its messages
// name no line, so every statement it would use is checked here first and the
// first problem is reported as "file.obj:LINE: what is wrong".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

struct ObjNamedRef {
    int line = 0;
    std::string name;
};

struct ObjScan {
    std::vector<ObjNamedRef> mtllibs;  // one entry per file name on each mtllib line
    std::vector<ObjNamedRef> usemtls;
    std::size_t positions = 0;
    std::size_t normals = 0;
    std::size_t texcoords = 0;
    std::size_t faces = 0;
};

// Throws facet::Error naming `path` and the line on the first malformed statement
// (non-numeric or missing fields, NaN/inf positions, face indices that are 0 or out
// of range, faces with fewer than 3 vertices) and when the file has no faces.
ObjScan validate_obj(const std::string& path, std::string_view text);

}  // namespace facet
