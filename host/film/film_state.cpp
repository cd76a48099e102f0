#include "host/film/film_state.hpp"

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "host/error.hpp"
#include "host/util/fnv.hpp"
#include "host/util/safe_write.hpp"
#include "host/film/film_layout.hpp"
#include "host/film/film_validate.hpp"

namespace facet {
namespace {

static_assert(std::endian::native == std::endian::little, "the film format is little-endian (docs/film-format.md)");

constexpr char kMagic[8] = {'F', 'A', 'C', 'E', 'T', 'F', 'L', 'M'};
// 1: no "samples", indices [0, spp); 1 and 2: RGBA sums only, no second moments
constexpr std::uint32_t kVersion = 3;
constexpr std::uint32_t kMaxHeaderBytes = 1 << 20;
constexpr int kMaxSide = 16384;

std::uint64_t payload_hash(const std::vector<float>& sums) {
    Fnv1a f;
    f.bytes(sums.data(), sums.size() * sizeof(float));
    return f.h;
}

std::uint32_t u32_at(const char* p) {
    std::uint32_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

std::uint64_t parse_hex(const std::string& s) {
    std::size_t used = 0;
    std::uint64_t v = std::stoull(s, &used, 16);
    if (used != s.size()) throw std::invalid_argument(s);
    return v;
}

}  // namespace

void write_film(const std::string& path, const FilmState& film) {
    const std::size_t floats = film_floats(std::size_t(film.width) * std::size_t(film.height));
    if (sample_count(film.samples) != film.spp || first_overlap(film.samples))
        throw Error(
            fmt::format("{}: a film of {} spp cannot hold the samples {}", path, film.spp, describe(film.samples)));
    if (film.width < 1 || film.height < 1 || film.sums.size() != floats)
        throw Error(fmt::format("{}: a film of {}x{} pixels with {} values is inconsistent", path, film.width,
                                film.height, film.sums.size()));
    nlohmann::json h;
    h["format"] = "facet film";
    h["scene"] = film.scene_path;
    h["scene_hash"] = fmt::format("{:016x}", film.scene_hash);
    h["width"] = film.width;
    h["height"] = film.height;
    h["seed"] = film.seed;
    h["max_depth"] = film.max_depth;
    h["rr_depth"] = film.rr_depth;
    h["strategy"] = film.strategy;
    h["sampler"] = film.sampler;
    h["spp"] = film.spp;
    nlohmann::json ranges = nlohmann::json::array();
    for (const SampleRange& r : normalized(film.samples)) ranges.push_back({r.begin, r.end});
    h["samples"] = ranges;
    h["render_seconds"] = film.render_seconds;
    h["second_moments"] = film.second_moments;
    h["payload_floats"] = floats;
    h["payload_fnv1a64"] = fmt::format("{:016x}", payload_hash(film.sums));
    const std::string header = h.dump(1) + "\n";
    std::string bytes(kMagic, sizeof kMagic);
    const std::uint32_t words[2] = {kVersion, std::uint32_t(header.size())};
    bytes.append(reinterpret_cast<const char*>(words), sizeof words);
    bytes += header;
    bytes.append(reinterpret_cast<const char*>(film.sums.data()), floats * sizeof(float));
    write_bytes_safely(path, "film", bytes);
}

FilmState read_film(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(fmt::format("{}: no such film", path));
    if (!fs::is_regular_file(path, ec)) throw Error(fmt::format("{}: not a regular file, so not a film", path));
    const std::uintmax_t size = fs::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    if (ec || !in) throw Error(fmt::format("{}: cannot open the film", path));
    char head[16];
    if (size < sizeof head || !in.read(head, sizeof head) || std::memcmp(head, kMagic, sizeof kMagic) != 0)
        throw Error(fmt::format("{}: not a facet film (docs/film-format.md)", path));
    const std::uint32_t version = u32_at(head + 8);
    if (version < 1 || version > kVersion)
        throw Error(
            fmt::format("{}: film format version {}, but this facet reads versions 1 to {}", path, version, kVersion));
    const std::uint32_t header_bytes = u32_at(head + 12);
    if (header_bytes > kMaxHeaderBytes || sizeof head + header_bytes > size)
        throw Error(fmt::format("{}: the film's header claims {} bytes, but the file has {}: truncated or corrupt",
                                path, header_bytes, size));
    std::string header(header_bytes, '\0');
    in.read(header.data(), header_bytes);
    FilmState film;
    std::uint64_t floats = 0, checksum = 0;
    try {
        nlohmann::json h = nlohmann::json::parse(header);
        film.scene_path = h.at("scene").get<std::string>();
        film.scene_hash = parse_hex(h.at("scene_hash").get<std::string>());
        film.width = h.at("width").get<int>();
        film.height = h.at("height").get<int>();
        film.seed = h.at("seed").get<std::uint32_t>();
        film.max_depth = h.at("max_depth").get<int>();
        film.rr_depth = h.at("rr_depth").get<int>();
        film.strategy = h.at("strategy").get<int>();
        film.sampler = h.at("sampler").get<int>();
        film.spp = h.at("spp").get<std::uint64_t>();
        if (version == 1) film.samples = {{0, film.spp}};
        else
            for (const nlohmann::json& r : h.at("samples"))
                film.samples.push_back({r.at(0).get<std::uint64_t>(), r.at(1).get<std::uint64_t>()});
        film.render_seconds = h.at("render_seconds").get<double>();
        film.second_moments = version >= 3 && h.at("second_moments").get<bool>();
        floats = h.at("payload_floats").get<std::uint64_t>();
        checksum = parse_hex(h.at("payload_fnv1a64").get<std::string>());
    } catch (const std::exception& e) {
        throw Error(fmt::format("{}: the film's header is malformed: {}", path, e.what()));
    }
    if (film.width < 1 || film.height < 1 || film.width > kMaxSide || film.height > kMaxSide)
        throw Error(fmt::format("{}: the film claims {}x{} pixels", path, film.width, film.height));
    for (const SampleRange& r : film.samples)
        if (r.end < r.begin || r.end > (std::uint64_t(1) << 32))  // indices below 2^32
            throw Error(fmt::format("{}: the film claims the sample range {}-{}", path, r.begin, r.end));
    if (first_overlap(film.samples))
        throw Error(fmt::format("{}: the film's sample ranges overlap ({}): corrupt", path, describe(film.samples)));
    if (sample_count(film.samples) != film.spp)
        throw Error(fmt::format("{}: the film claims {} spp but holds the samples {}: corrupt", path, film.spp,
                                describe(film.samples)));
    film.samples = normalized(film.samples);
    // Versions 1 and 2 hold the RGBA sums alone; their second moments are read as zeros
    const std::size_t pixels = std::size_t(film.width) * std::size_t(film.height);
    const std::uint64_t want = version >= 3 ? film_floats(pixels) : film_rgba_floats(pixels);
    if (floats != want || size - sizeof head - header_bytes != want * sizeof(float))
        throw Error(
            fmt::format("{}: the film of {}x{} pixels should hold {} bytes of samples, but has {}: "
                        "truncated or corrupt",
                        path, film.width, film.height, want * sizeof(float), size - sizeof head - header_bytes));
    film.sums.resize(want);
    if (!in.read(reinterpret_cast<char*>(film.sums.data()), std::streamsize(want * sizeof(float))))
        throw Error(fmt::format("{}: cannot read the film's samples", path));
    if (payload_hash(film.sums) != checksum)
        throw Error(fmt::format("{}: the film's samples do not match its checksum: corrupt", path));
    film.sums.resize(film_floats(pixels), 0.0f);
    validate_film_payload(film, path);
    return film;
}

}  // namespace facet
