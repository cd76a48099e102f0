#include "host/cl/kernel_source.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

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

// Whether `line` is the preprocessor directive `name` ("endif", "ifndef", ...).
bool is_directive(const std::string& line, std::string_view name) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != '#') return false;
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || line.compare(i, name.size(), name) != 0) return false;
    const std::size_t after = i + name.size();
    return after == line.size() || line[after] == ' ' || line[after] == '\t' || line[after] == '/';
}

// Whether `content` opens with an include guard: "#ifndef X" then "#define X" as its first
// two directives (comments and blank lines before them are fine).
bool has_include_guard(const std::string& content) {
    std::istringstream in(content);
    std::string line, guard;
    bool in_comment = false;
    while (std::getline(in, line)) {
        std::size_t i = line.find_first_not_of(" \t");
        if (in_comment) {
            if (line.find("*/") != std::string::npos) in_comment = false;
            continue;
        }
        if (i == std::string::npos || line.compare(i, 2, "//") == 0) continue;
        if (line.compare(i, 2, "/*") == 0) {
            in_comment = line.find("*/", i + 2) == std::string::npos;
            continue;
        }
        std::istringstream words(line);
        std::string directive, name;
        words >> directive >> name;
        if (guard.empty()) {
            if (directive != "#ifndef" || name.empty()) return false;
            guard = name;
        } else {
            return directive == "#define" && name == guard;
        }
    }
    return false;
}

// Inlines `path` with its includes, at every include, as the preprocessor would read them:
// an include inside a disabled #if block is inlined too and dropped by the compiler, and
// an included file's guard (required) makes its second inlining empty. A file already
// being inlined higher up (an include cycle) is not inlined again: its guard is defined by
// then, so the preprocessor would read nothing. #line directives follow every inlined file
// and every #else, #elif and #endif, so each line keeps its own file and number whichever
// blocks the compiler skips (a skipped block's #line directives are not read).
void append_file(const SourceTree& tree, const std::string& path, std::vector<std::string>& active,
                 AssembledSource& out) {
    if (std::find(active.begin(), active.end(), path) != active.end()) return;
    std::string content;
    if (!tree.find(path, content)) throw Error(fmt::format("kernel source {} not found ({})", path, tree.origin()));
    if (!active.empty() && !has_include_guard(content))
        throw Error(
            fmt::format("kernel source {} has no include guard (#ifndef NAME, #define NAME as its first "
                        "directives); included files need one ({})",
                        path, tree.origin()));
    if (std::find(out.files.begin(), out.files.end(), path) == out.files.end()) out.files.push_back(path);
    active.push_back(path);
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
            if (is_directive(line, "endif") || is_directive(line, "else") || is_directive(line, "elif"))
                out.text += fmt::format("#line {} \"{}\"\n", number + 1, path);
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
        append_file(tree, resolved, active, out);
        out.text += fmt::format("#line {} \"{}\"\n", number + 1, path);
    }
    active.pop_back();
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
    std::vector<std::string> active;
    append_file(tree, normalise(entry), active, out);
    return out;
}

}  // namespace facet
