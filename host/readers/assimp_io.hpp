// The files Assimp opens itself (the model, and what it names: Collada's and FBX's
// companions), opened through facet's input checks (host/util/input_file.hpp): regular
// files only, of bounded size, inside the model's folder, read whole into memory; writes
// are refused. So a FIFO cannot hang the importer and a "../../" name cannot reach out.
#pragma once

#include <cstdint>
#include <string>

#include <assimp/IOSystem.hpp>

namespace facet {

// The largest file Assimp may open through AssimpFiles: 2 GiB.
constexpr std::uint64_t kMaxAssimpFileBytes = std::uint64_t(2) << 30;

class AssimpFiles : public Assimp::IOSystem {
public:
    // Files under `folder` (the model's) only.
    explicit AssimpFiles(const std::string& folder);

    bool Exists(const char* path) const override;
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* path, const char* mode = "rb") override;
    void Close(Assimp::IOStream* stream) override;

    // Why the last refused Open was refused ("" when none was): for the error message.
    const std::string& refusal() const { return refusal_; }

private:
    std::string folder_;  // canonical
    std::string refusal_;
    // The canonical path of `path` when it lies under folder_, else "".
    std::string inside(const char* path) const;
};

}  // namespace facet
