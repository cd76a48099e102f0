#include "host/image/image_channels.hpp"

#include <algorithm>
#include <memory>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

std::unique_ptr<OIIO::ImageInput> open(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw Error(fmt::format("{}: cannot read image: {}", path, OIIO::geterror()));
    return in;
}

// The index of each name among the file's channels; -1 where it has none.
std::vector<int> channel_indices(const OIIO::ImageSpec& spec, const std::vector<std::string>& names) {
    std::vector<int> at;
    for (const std::string& name : names) {
        const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
        at.push_back(it == spec.channelnames.end() ? -1 : int(it - spec.channelnames.begin()));
    }
    return at;
}

}  // namespace

bool has_channels(const std::string& path, const std::vector<std::string>& names) {
    const std::vector<int> at = channel_indices(open(path)->spec(), names);
    return std::none_of(at.begin(), at.end(), [](int i) { return i < 0; });
}

std::vector<float> read_channels(const std::string& path, const std::vector<std::string>& names) {
    std::unique_ptr<OIIO::ImageInput> in = open(path);
    const OIIO::ImageSpec& spec = in->spec();
    const std::vector<int> at = channel_indices(spec, names);
    for (std::size_t k = 0; k < names.size(); ++k)
        if (at[k] < 0) throw Error(fmt::format("{}: has no channel {}", path, names[k]));
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<float> out(pixels * names.size()), one(pixels);
    for (std::size_t k = 0; k < names.size(); ++k) {
        if (!in->read_image(0, 0, at[k], at[k] + 1, OIIO::TypeDesc::FLOAT, one.data()))
            throw Error(fmt::format("{}: cannot read channel {}: {}", path, names[k], in->geterror()));
        for (std::size_t i = 0; i < pixels; ++i) out[i * names.size() + k] = one[i];
    }
    return out;
}

}  // namespace facet
