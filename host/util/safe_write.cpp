#include "host/util/safe_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::string reason(int err) { return std::strerror(err); }

std::size_t name_max(const fs::path& dir) {
    long n = ::pathconf(dir.empty() ? "." : dir.c_str(), _PC_NAME_MAX);
    return n > 0 ? std::size_t(n) : std::size_t(NAME_MAX);
}

fs::path folder_of(const fs::path& p) { return p.has_parent_path() ? p.parent_path() : fs::path("."); }

// The file a write of `path` replaces: a symbolic link is followed, so that the link
// stays and the file it names gets the new contents.
fs::path resolve_target(const std::string& path) {
    fs::path p(path);
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(p, ec))) {
        fs::path real = fs::weakly_canonical(p, ec);
        if (!ec) return real;
    }
    return p;
}

void create_folder(const std::string& path, const fs::path& folder) {
    std::error_code ec;
    if (folder.empty() || fs::is_directory(folder, ec)) return;
    fs::create_directories(folder, ec);
    if (ec) throw Error(fmt::format("{}: cannot create the folder {}: {}", path, folder.string(), ec.message()));
}

// Refuses targets that a rename must not replace: folders and special files (a device
// such as /dev/full would be replaced by a regular file, as root).
void check_target_kind(const std::string& path, const std::string& prefix) {
    std::error_code ec;
    fs::file_status st = fs::status(path, ec);
    if (!path.empty() && path.back() == '/')
        throw Error(fmt::format("{}{}: names a folder; give a file name", prefix, path));
    if (!fs::exists(st)) return;
    if (fs::is_directory(st)) throw Error(fmt::format("{}{}: is a folder; give a file name", prefix, path));
    if (!fs::is_regular_file(st))
        throw Error(
            fmt::format("{}{}: is not a regular file (a device, pipe or socket); outputs are written "
                        "to a new file renamed over the old one, so give a file name",
                        prefix, path));
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

// fsync of a file or folder; folders on file systems without it (EINVAL) are skipped.
int sync_path(const fs::path& p, bool folder) {
    int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0));
    if (fd < 0) return errno;
    int err = ::fsync(fd) == 0 ? 0 : errno;
    if (folder && (err == EINVAL || err == ENOTSUP)) err = 0;
    if (::close(fd) != 0 && err == 0) err = errno;
    return err;
}

void write_all(int fd, std::string_view bytes) {
    const char* at = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        ssize_t n = ::write(fd, at, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw std::system_error(errno, std::generic_category());
        }
        if (n == 0) throw std::system_error(EIO, std::generic_category());
        at += n;
        left -= std::size_t(n);
    }
}

}  // namespace

std::string temporary_path_for(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    fs::path target(path);
    fs::path folder = folder_of(target);
    std::string ext = target.extension().string();
    std::string stem = target.stem().string();
    std::string tag = fmt::format(".tmp-{}-{}", ::getpid(), counter++);
    const std::size_t limit = name_max(folder);
    // "." + stem + tag + ext, the stem shortened (then the extension) to fit NAME_MAX.
    if (1 + tag.size() + ext.size() > limit) ext.resize(limit > 1 + tag.size() ? limit - 1 - tag.size() : 0);
    const std::size_t room = limit - 1 - tag.size() - ext.size();
    if (stem.size() > room) stem.resize(room);
    return (folder / ("." + stem + tag + ext)).string();
}

void write_file_safely(const std::string& path, const std::string& what,
                       const std::function<void(const std::string& tmp)>& write,
                       const std::function<void(const std::string& tmp)>& verify) {
    check_target_kind(path, "");
    const fs::path target = resolve_target(path);
    const fs::path folder = folder_of(target);
    create_folder(path, target.has_parent_path() ? target.parent_path() : fs::path());
    const std::string tmp = temporary_path_for(target.string());
    auto fail = [&](const std::string& message) {
        ::unlink(tmp.c_str());
        std::string m = message;
        replace_all(m, tmp, path);
        throw Error(m);
    };
    try {
        write(tmp);
        if (int err = sync_path(tmp, false)) fail(fmt::format("{}: cannot write the {}: {}", path, what, reason(err)));
        if (verify) verify(tmp);
    } catch (const Error& e) {
        fail(e.what());
    } catch (const std::system_error& e) {
        fail(fmt::format("{}: cannot write the {}: {}", path, what, reason(e.code().value())));
    }
    if (::rename(tmp.c_str(), target.c_str()) != 0) {
        const int err = errno;  // before unlink() can change it
        fail(fmt::format("{}: cannot put the new {} in place: {}", path, what, reason(err)));
    }
    // The rename is durable once the folder is synced; the new file is complete either way.
    if (int err = sync_path(folder, true))
        throw Error(fmt::format("{}: the {} was written, but syncing its folder failed: {}", path, what, reason(err)));
}

void write_bytes_safely(const std::string& path, const std::string& what, std::string_view bytes) {
    write_file_safely(path, what, [&](const std::string& tmp) {
        int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) throw std::system_error(errno, std::generic_category());
        try {
            write_all(fd, bytes);
        } catch (...) {
            ::close(fd);
            throw;
        }
        if (::close(fd) != 0) throw std::system_error(errno, std::generic_category());
    });
}

void check_output_path(const std::string& path, const std::string& option) {
    const std::string prefix = option + " ";
    if (path.empty()) throw Error(fmt::format("{}: an empty file name", option));
    check_target_kind(path, prefix);
    const fs::path target = resolve_target(path);
    const fs::path folder = folder_of(target);
    const std::string name = target.filename().string();
    if (name.empty() || name == "." || name == "..")
        throw Error(fmt::format("{}{}: names a folder; give a file name", prefix, path));
    try {
        create_folder(path, target.has_parent_path() ? target.parent_path() : fs::path());
    } catch (const Error& e) {
        throw Error(prefix + e.what());
    }
    if (name.size() > name_max(folder))
        throw Error(fmt::format("{}{}: the file name has {} bytes, more than the {} its file system allows", prefix,
                                path, name.size(), name_max(folder)));
    // A probe: a temporary created, one byte written, synced and removed.
    const std::string probe = temporary_path_for(target.string());
    int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int err = errno;
        throw Error(fmt::format("{}{}: cannot write in {}: {}", prefix, path, folder.string(), reason(err)));
    }
    int err = 0;
    try {
        write_all(fd, "\n");
        if (::fsync(fd) != 0) err = errno;
    } catch (const std::system_error& e) {
        err = e.code().value();
    }
    if (::close(fd) != 0 && err == 0) err = errno;
    ::unlink(probe.c_str());
    if (err) throw Error(fmt::format("{}{}: cannot write in {}: {}", prefix, path, folder.string(), reason(err)));
}

}  // namespace facet
