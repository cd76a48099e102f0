// DecodedLimits.*: sizes a small file can claim decoded are bounded before the memory is
// taken, with an error naming the file and the limit: a PNG of 16384 x 16384 (a few
// hundred KB of deflate) is refused from its header, and a gzip'd file stops inflating
// at the limit.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <string>

#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/readers/gzip_file.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

using test::error_of;

void put_u32(std::string& s, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) s.push_back(char((v >> shift) & 0xff));
}

void put_chunk(std::string& png, const char* type, const std::string& data) {
    put_u32(png, std::uint32_t(data.size()));
    const std::string typed = std::string(type, 4) + data;
    png += typed;
    put_u32(png, std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
}

// A valid 8-bit grey PNG of side x side black pixels (PNG 1.2: IHDR, one IDAT, IEND),
// with `padding` bytes of an ancillary chunk (readers skip it): a 16384^2 image then
// weighs what a real one of a few colours would, past the file-size plausibility check.
std::string black_png(std::uint32_t side, std::size_t padding = 0) {
    std::string ihdr;
    put_u32(ihdr, side);
    put_u32(ihdr, side);
    ihdr += std::string("\x08\x00\x00\x00\x00", 5);  // 8 bits, grey, deflate, filter 0, no interlace
    z_stream z{};
    EXPECT_EQ(deflateInit(&z, 9), Z_OK);
    const std::string row(side + 1, '\0');  // filter byte 0, then the pixels
    std::string idat, out(1 << 16, '\0');
    for (std::uint32_t y = 0; y < side; ++y) {
        z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(row.data()));
        z.avail_in = uInt(row.size());
        const int flush = y + 1 == side ? Z_FINISH : Z_NO_FLUSH;
        do {
            z.next_out = reinterpret_cast<Bytef*>(out.data());
            z.avail_out = uInt(out.size());
            deflate(&z, flush);
            idat.append(out.data(), out.size() - z.avail_out);
        } while (z.avail_out == 0 || (flush == Z_FINISH && z.avail_in > 0));
    }
    deflateEnd(&z);
    std::string png("\x89PNG\r\n\x1a\n", 8);
    put_chunk(png, "IHDR", ihdr);
    if (padding > 0) put_chunk(png, "faCt", std::string(padding, 'x'));
    put_chunk(png, "IDAT", idat);
    put_chunk(png, "IEND", "");
    return png;
}

TEST(DecodedLimits, HugePngIsRefusedFromItsHeader) {
    test::TempDir d;
    const std::string small = d.write("small.png", black_png(64));
    EXPECT_EQ(read_image(small).width, 64);
    const std::string huge = d.write("huge.png", black_png(16384, 520000));  // 783 KB
    const std::string msg = error_of([&] { read_image(huge); });
    EXPECT_NE(
        msg.find("huge.png: the image claims 16384x16384 pixels, 3072 MiB decoded as float RGB: at most 2048 MiB"),
        std::string::npos)
        << msg;
}

TEST(DecodedLimits, GzipStopsInflatingAtTheLimit) {
    test::TempDir d;
    const std::string path = d.path("zeros.ply.gz");
    gzFile f = gzopen(path.c_str(), "wb9");
    ASSERT_NE(f, nullptr);
    const std::string mib(std::size_t(1) << 20, '\0');
    for (int i = 0; i < 8; ++i) ASSERT_EQ(gzwrite(f, mib.data(), unsigned(mib.size())), int(mib.size()));
    gzclose(f);
    EXPECT_EQ(read_maybe_gzipped(path, "PLY file").size(), std::size_t(8) << 20);
    const std::string msg = error_of([&] { read_maybe_gzipped(path, "PLY file", std::uint64_t(1) << 20); });
    EXPECT_NE(msg.find("PLY file '" + path + "': inflates to more than 1048576 bytes (1 MiB)"), std::string::npos)
        << msg;
    EXPECT_EQ(kMaxInflatedBytes, std::uint64_t(1) << 30);
}

}  // namespace
}  // namespace facet
