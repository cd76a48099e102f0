// gzip'd input files, through zlib.
#include "host/readers/gzip_file.hpp"

#include <filesystem>

#include <fmt/format.h>
#include <zlib.h>

#include "host/error.hpp"
#include "host/util/input_file.hpp"
#include "host/util/strings.hpp"

namespace facet {
namespace {

bool gzipped(const std::string& bytes) {
    return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
           static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string inflate_gzip(const std::string& path, const char* what, const std::string& in) {
    z_stream z{};
    if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) throw Error(fmt::format("{} '{}': zlib cannot start", what, path));
    std::string out;
    std::string chunk(std::size_t(1) << 20, '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
    std::size_t left = in.size();
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
        if (z.avail_in == 0 && left > 0) {
            const std::size_t n = std::min<std::size_t>(left, 1u << 30);
            z.avail_in = static_cast<uInt>(n);
            left -= n;
        }
        z.next_out = reinterpret_cast<Bytef*>(chunk.data());
        z.avail_out = static_cast<uInt>(chunk.size());
        rc = inflate(&z, Z_NO_FLUSH);
        if (rc != Z_OK && rc != Z_STREAM_END) {
            const std::string why = z.msg ? z.msg : (rc == Z_BUF_ERROR ? "truncated" : "corrupt data");
            inflateEnd(&z);
            throw Error(fmt::format("{} '{}': not a valid gzip stream ({})", what, path, why));
        }
        out.append(chunk.data(), chunk.size() - z.avail_out);
        if (out.size() > kMaxInputFileBytes) {
            inflateEnd(&z);
            throw Error(fmt::format("{} '{}': inflates to more than {} bytes", what, path, kMaxInputFileBytes));
        }
        if (rc != Z_STREAM_END && z.avail_in == 0 && left == 0 && z.avail_out != 0) {
            inflateEnd(&z);
            throw Error(fmt::format("{} '{}': not a valid gzip stream (truncated)", what, path));
        }
    }
    inflateEnd(&z);
    return out;
}

}  // namespace

std::string read_maybe_gzipped(const std::string& path, const char* what) {
    std::string bytes = read_input_file(path, what);
    return gzipped(bytes) ? inflate_gzip(path, what, bytes) : bytes;
}

std::string extension_under_gz(const std::string& path) {
    std::filesystem::path p(path);
    std::string ext = lower(p.extension().string());
    if (ext == ".gz") ext = lower(p.stem().extension().string());
    return ext;
}

}  // namespace facet
