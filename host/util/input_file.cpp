#include "host/util/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <new>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

// An open descriptor, closed on every path out.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

[[noreturn]] void fail(const char* what, const std::string& path, const std::string& reason) {
    throw Error(fmt::format("{} '{}': {}", what, path, reason));
}

// Opens and checks the file; O_NONBLOCK so that opening a FIFO cannot hang.
std::uint64_t open_checked(const std::string& path, const char* what, std::uint64_t max_bytes, Fd& f) {
    f.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (f.fd < 0) {
        const int e = errno;
        if (e == ENOENT) fail(what, path, "no such file");
        fail(what, path, fmt::format("cannot open: {}", std::strerror(e)));
    }
    struct stat st {};
    if (::fstat(f.fd, &st) != 0) fail(what, path, fmt::format("cannot read: {}", std::strerror(errno)));
    if (S_ISDIR(st.st_mode)) fail(what, path, "is a directory, not a file");
    if (!S_ISREG(st.st_mode))
        fail(what, path, "is not a regular file (a device, pipe or socket): facet reads only regular files");
    const std::uint64_t size = std::uint64_t(st.st_size);
    if (size > max_bytes) fail(what, path, fmt::format("is {} bytes, more than the {} facet reads", size, max_bytes));
    return size;
}

}  // namespace

std::uint64_t check_input_file(const std::string& path, const char* what, std::uint64_t max_bytes) {
    Fd f;
    return open_checked(path, what, max_bytes, f);
}

std::string read_input_file(const std::string& path, const char* what, std::uint64_t max_bytes) {
    Fd f;
    const std::uint64_t size = open_checked(path, what, max_bytes, f);
    std::string text;
    try {
        text.resize(std::size_t(size));
    } catch (const std::bad_alloc&) {
        fail(what, path, fmt::format("not enough memory to read its {} bytes", size));
    }
    // Read what fstat promised and no more (the file may grow while being read).
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::read(f.fd, text.data() + done, text.size() - done);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n < 0) fail(what, path, fmt::format("read error: {}", std::strerror(errno)));
        if (n == 0) break;  // shrank while being read
        done += std::size_t(n);
    }
    text.resize(done);
    return text;
}

}  // namespace facet
