// gzip'd ASCII PLY to OBJ: see ply_mesh.hpp.
#include "bench/ply_mesh.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#ifdef FACET_HAVE_ZLIB
#include <zlib.h>
#endif

namespace facet {

bool ply_gz_to_obj(const std::string& ply_gz, const std::string& obj_out, std::string* why) {
    namespace fs = std::filesystem;
    if (fs::exists(obj_out)) return true;
#ifndef FACET_HAVE_ZLIB
    *why = "facet_bench was built without zlib";
    (void)ply_gz;
    return false;
#else
    gzFile f = gzopen(ply_gz.c_str(), "rb");
    if (!f) {
        *why = "cannot open " + ply_gz;
        return false;
    }
    std::string text;
    std::vector<char> buf(1 << 20);
    for (;;) {
        int got = gzread(f, buf.data(), unsigned(buf.size()));
        if (got < 0) {
            gzclose(f);
            *why = "gzip error in " + ply_gz;
            return false;
        }
        if (got == 0) break;
        text.append(buf.data(), std::size_t(got));
    }
    gzclose(f);

    // Header: vertex and face counts, ASCII format, x y z as the first three
    // properties of a vertex.
    std::size_t end = text.find("end_header");
    if (text.compare(0, 3, "ply") != 0 || end == std::string::npos) {
        *why = ply_gz + ": not a PLY file";
        return false;
    }
    std::istringstream header(text.substr(0, end));
    std::string line, element;
    long vertices = -1, faces = -1;
    int vertex_props = 0;
    bool ascii = false;
    while (std::getline(header, line)) {
        std::istringstream ls(line);
        std::string word;
        ls >> word;
        if (word == "format") {
            std::string fmt;
            ls >> fmt;
            ascii = fmt == "ascii";
        } else if (word == "element") {
            long count = 0;
            ls >> element >> count;
            if (element == "vertex") vertices = count;
            else if (element == "face") faces = count;
        } else if (word == "property" && element == "vertex") {
            ++vertex_props;
        }
    }
    if (!ascii || vertices < 0 || faces < 0 || vertex_props < 3) {
        *why = ply_gz + ": only ASCII PLY with vertex x y z and faces is read";
        return false;
    }
    const char* p = text.c_str() + end + std::strlen("end_header");
    char* next = nullptr;
    std::string tmp = obj_out + ".part";
    fs::create_directories(fs::path(obj_out).parent_path());
    std::ofstream out(tmp);
    out << "# " << ply_gz << " converted by facet_bench\n";
    char line_buf[160];
    for (long i = 0; i < vertices; ++i) {
        float v[3];
        for (int k = 0; k < vertex_props; ++k) {
            float x = std::strtof(p, &next);
            if (next == p) {
                *why = ply_gz + ": truncated vertex list";
                return false;
            }
            if (k < 3) v[k] = x;
            p = next;
        }
        std::snprintf(line_buf, sizeof line_buf, "v %.9g %.9g %.9g\n", double(v[0]), double(v[1]), double(v[2]));
        out << line_buf;
    }
    for (long i = 0; i < faces; ++i) {
        long n = std::strtol(p, &next, 10);
        if (next == p || n < 3 || n > 64) {
            *why = ply_gz + ": bad face list";
            return false;
        }
        p = next;
        long idx[64];
        for (long k = 0; k < n; ++k) {
            idx[k] = std::strtol(p, &next, 10);
            if (next == p || idx[k] < 0 || idx[k] >= vertices) {
                *why = ply_gz + ": bad vertex index";
                return false;
            }
            p = next;
        }
        for (long k = 1; k + 1 < n; ++k)  // fan
            out << "f " << idx[0] + 1 << ' ' << idx[k] + 1 << ' ' << idx[k + 1] + 1 << '\n';
    }
    out.close();
    if (!out) {
        *why = "cannot write " + tmp;
        return false;
    }
    fs::rename(tmp, obj_out);
    return true;
#endif
}

}  // namespace facet
