#include "host/readers/assimp_io.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>

#include <assimp/IOStream.hpp>
#include <fmt/format.h>

#include "host/util/input_file.hpp"

namespace facet {
namespace {

// A file's bytes, read whole by read_input_file, as a read-only stream.
class BytesStream : public Assimp::IOStream {
public:
    explicit BytesStream(std::string bytes) : bytes_(std::move(bytes)) {}

    size_t Read(void* buffer, size_t size, size_t count) override {
        if (size == 0 || count == 0 || at_ >= bytes_.size()) return 0;
        const size_t items = std::min(count, (bytes_.size() - at_) / size);
        std::memcpy(buffer, bytes_.data() + at_, items * size);
        at_ += items * size;
        return items;
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        size_t to = 0;
        if (origin == aiOrigin_SET) to = offset;
        else if (origin == aiOrigin_CUR) to = at_ + offset;
        else if (origin == aiOrigin_END) to = bytes_.size() - std::min(offset, bytes_.size());
        else return aiReturn_FAILURE;
        if (to > bytes_.size()) return aiReturn_FAILURE;
        at_ = to;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return at_; }
    size_t FileSize() const override { return bytes_.size(); }
    void Flush() override {}

private:
    std::string bytes_;
    size_t at_ = 0;
};

}  // namespace

AssimpFiles::AssimpFiles(const std::string& folder) {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::weakly_canonical(folder.empty() ? "." : folder, ec);
    folder_ = ec ? std::filesystem::absolute(folder.empty() ? "." : folder).lexically_normal().string() : dir.string();
    if (folder_.empty() || folder_.back() != '/') folder_ += '/';
}

std::string AssimpFiles::inside(const char* path) const {
    if (!path || !*path) return "";
    std::error_code ec;
    const std::string p = std::filesystem::weakly_canonical(path, ec).string();
    if (ec || p.compare(0, folder_.size(), folder_) != 0) return "";
    return p;
}

bool AssimpFiles::Exists(const char* path) const {
    const std::string p = inside(path);
    struct stat st {};
    return !p.empty() && ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

Assimp::IOStream* AssimpFiles::Open(const char* path, const char* mode) {
    if (mode && (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+'))) {
        refusal_ = fmt::format("facet does not write '{}'", path ? path : "");
        return nullptr;
    }
    const std::string p = inside(path);
    if (p.empty()) {
        refusal_ = fmt::format("'{}' is outside the model's folder {}", path ? path : "", folder_);
        return nullptr;
    }
    try {
        return new BytesStream(read_input_file(p, "file", kMaxAssimpFileBytes));
    } catch (const std::exception& e) {  // facet::Error, or no memory for the bytes
        refusal_ = e.what();
        return nullptr;
    }
}

void AssimpFiles::Close(Assimp::IOStream* stream) { delete stream; }

}  // namespace facet
