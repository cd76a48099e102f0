// gzip'd input files, through zlib.
#include "host/readers/gzip_file.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <new>

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

std::string inflate_gzip(const std::string& path, const char* what, const std::string& in, std::uint64_t max_bytes) {
    z_stream z{};
    if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) throw Error(fmt::format("{} '{}': zlib cannot start", what, path));
    std::string out;
    // gzip's trailer holds the inflated size modulo 2^32 (RFC 1952 ISIZE): a hint that
    // spares the doubling reallocations, never trusted beyond max_bytes.
    if (in.size() >= 18) {
        std::uint32_t isize = 0;
        for (int i = 3; i >= 0; --i)
            isize = (isize << 8) | static_cast<unsigned char>(in[in.size() - 4 + std::size_t(i)]);
        try {
            out.reserve(std::size_t(std::min<std::uint64_t>(isize, max_bytes)));
        } catch (const std::bad_alloc&) {
            // the hint only: the bytes are then taken as they come
        }
    }
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
        const std::size_t got = chunk.size() - z.avail_out;
        if (out.size() + got > max_bytes) {
            inflateEnd(&z);
            throw Error(
                fmt::format("{} '{}': inflates to more than {} bytes ({} MiB), more than facet reads from "
                            "a gzip'd file: a corrupt or hostile file, or unpack it first",
                            what, path, max_bytes, max_bytes >> 20));
        }
        try {
            out.append(chunk.data(), got);
        } catch (const std::bad_alloc&) {
            inflateEnd(&z);
            throw Error(
                fmt::format("{} '{}': not enough memory to inflate it ({} MiB so far)", what, path, out.size() >> 20));
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

std::string read_maybe_gzipped(const std::string& path, const char* what, std::uint64_t max_inflated) {
    std::string bytes = read_input_file(path, what);
    return gzipped(bytes) ? inflate_gzip(path, what, bytes, max_inflated) : bytes;
}

std::string extension_under_gz(const std::string& path) {
    std::filesystem::path p(path);
    std::string ext = lower(p.extension().string());
    if (ext == ".gz") ext = lower(p.stem().extension().string());
    return ext;
}

}  // namespace facet
