#include "host/cl/kernel_source.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// Tables registered besides the renderer's (tests, bench): filled before main() runs.
std::vector<EmbeddedTable>& registered_tables() {
    static std::vector<EmbeddedTable> tables;
    return tables;
}

// Where sources come from: the embedded table, or a directory on disk.
class SourceTree {
public:
    SourceTree() {
        if (const char* dir = std::getenv("FACET_KERNEL_DIR"); dir && *dir) {
            // FACET_KERNEL_DIR names a kernels/ folder; sources are keyed "kernels/...".
            fs::path kernels = fs::weakly_canonical(fs::path(dir));
            if (!fs::is_directory(kernels) || kernels.filename() != "kernels")
                throw Error(fmt::format("FACET_KERNEL_DIR={} is not a folder named kernels", dir));
            disk_root_ = kernels.parent_path();
        } else {
            for (const EmbeddedFile& f : embedded_kernel_files()) embedded_.emplace(f.path, f.content);
            for (EmbeddedTable table : registered_tables())
                for (const EmbeddedFile& f : table()) embedded_.emplace(f.path, f.content);
        }
    }

    bool from_disk() const { return !disk_root_.empty(); }
    std::string origin() const { return from_disk() ? disk_root_.string() : "embedded"; }

    bool find(const std::string& path, std::string& content) const {
        if (from_disk()) {
            std::ifstream in(disk_root_ / path, std::ios::binary);
            if (!in) return false;
            std::ostringstream ss;
            ss << in.rdbuf();
            content = ss.str();
            return true;
        }
        auto it = embedded_.find(path);
        if (it == embedded_.end()) return false;
        content = it->second;
        return true;
    }

private:
    fs::path disk_root_;
    std::map<std::string, std::string> embedded_;
};

std::string normalise(const fs::path& p) { return p.lexically_normal().generic_string(); }

// Parses `#include "x"` (with optional spaces); returns false for any other line.
bool parse_include(const std::string& line, std::string& target) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != '#') return false;
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || line.compare(i, 7, "include") != 0) return false;
    std::size_t open = line.find('"', i + 7);
    if (open == std::string::npos) return false;
    std::size_t close = line.find('"', open + 1);
    if (close == std::string::npos) return false;
    target = line.substr(open + 1, close - open - 1);
    return true;
}

void append_file(const SourceTree& tree, const std::string& path, std::set<std::string>& seen, AssembledSource& out) {
    if (!seen.insert(path).second) return;  // every file is taken in once (#pragma once)
    std::string content;
    if (!tree.find(path, content)) throw Error(fmt::format("kernel source {} not found ({})", path, tree.origin()));
    out.files.push_back(path);
    out.text += fmt::format("#line 1 \"{}\"\n", path);
    std::istringstream in(content);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::string target;
        if (!parse_include(line, target)) {
            out.text += line;
            out.text += '\n';
            continue;
        }
        // One include root: every include names its file from the repository root
        // ("kernels/util/math.cl"), as the host's includes do.
        std::string resolved = normalise(fs::path(target));
        std::string dummy;
        if (resolved.rfind("kernels/", 0) != 0 || !tree.find(resolved, dummy))
            throw Error(
                fmt::format("{}:{}: included file \"{}\" not found ({}); kernel includes name "
                            "their file from the repository root, as \"kernels/util/math.cl\"",
                            path, number, target, tree.origin()));
        append_file(tree, resolved, seen, out);
        out.text += fmt::format("#line {} \"{}\"\n", number + 1, path);
    }
}

}  // namespace

bool register_embedded_kernel_files(EmbeddedTable table) {
    registered_tables().push_back(table);
    return true;
}

AssembledSource assemble_program(const std::string& entry, const std::vector<std::string>& prelude) {
    SourceTree tree;
    AssembledSource out;
    out.origin = tree.origin();
    for (const std::string& line : prelude) out.text += line + "\n";
    std::set<std::string> seen;
    append_file(tree, normalise(entry), seen, out);
    return out;
}

}  // namespace facet
