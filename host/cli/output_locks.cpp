#include "host/cli/output_locks.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <utility>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The process id an owner wrote into its lock file, 0 when unreadable.
long owner_of(int fd) {
    char buf[32] = {};
    if (::pread(fd, buf, sizeof buf - 1, 0) <= 0) return 0;
    return std::strtol(buf, nullptr, 10);
}

}  // namespace

std::string lock_path_for(const std::string& path) {
    const fs::path p(path);
    const std::string file = p.filename().string();
    std::string name = ".";
    if (file.size() + 6 <= 255) name += file;
    else {  // within NAME_MAX: a prefix and a hash of the whole name
        name += file.substr(0, 200);
        name += fmt::format("-{:016x}", std::hash<std::string>{}(file));
    }
    name += ".lock";
    return (p.parent_path() / name).string();
}

OutputLocks::OutputLocks(OutputLocks&& other) noexcept : held_(std::move(other.held_)) { other.held_.clear(); }

OutputLocks& OutputLocks::operator=(OutputLocks&& other) noexcept {
    if (this != &other) {
        release();
        held_ = std::move(other.held_);
        other.held_.clear();
    }
    return *this;
}

OutputLocks::~OutputLocks() { release(); }

void OutputLocks::release() noexcept {
    // Unlinked while still locked: a process that opened it meanwhile finds, once it holds
    // the lock, that the name no longer leads to its file, and starts again (lock()).
    for (const Held& h : held_) {
        ::unlink(h.lock_path.c_str());
        ::close(h.fd);
    }
    held_.clear();
}

void OutputLocks::lock(const std::string& path, const std::string& label) {
    for (const Held& h : held_)
        if (same_file(h.path, path)) return;
    const std::string lock_file = lock_path_for(path);
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd = ::open(lock_file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0)
            throw Error(
                fmt::format("{} {}: cannot create its lock file {}: {}", label, path, lock_file, std::strerror(errno)));
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int err = errno;
            const long owner = owner_of(fd);
            ::close(fd);
            if (err == EWOULDBLOCK)
                throw Error(fmt::format(
                    "{} {}: in use by another facet{} (lock {}): two commands on one film or "
                    "output would lose samples; wait for it to end or choose other names",
                    label, path, owner > 0 ? fmt::format(" (process {})", owner) : std::string(), lock_file));
            throw Error(fmt::format("{} {}: cannot lock {}: {}", label, path, lock_file, std::strerror(err)));
        }
        // The lock file may have been removed by its last owner between our open and flock.
        struct stat held {
        }, named{};
        if (::fstat(fd, &held) != 0 || ::stat(lock_file.c_str(), &named) != 0 || held.st_ino != named.st_ino ||
            held.st_dev != named.st_dev) {
            ::close(fd);
            continue;
        }
        const std::string pid = std::to_string(::getpid()) + "\n";
        if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != ssize_t(pid.size())) {
            // The id is for messages only; the lock holds without it.
        }
        held_.push_back({path, lock_file, fd});
        return;
    }
    throw Error(fmt::format("{} {}: cannot lock {}: it keeps being replaced", label, path, lock_file));
}

OutputLocks lock_outputs(const OutputPlan& plan) {
    OutputLocks locks;
    // Under an MPI launcher only rank 0 writes: the others lock nothing. Read from the
    // launcher's environment, as Ranks::where() does, so that MPI is not started here (a
    // rank that fails before the job starts must exit at once for mpirun to end the job).
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
        if (const char* rank = std::getenv(name)) {
            if (std::string(rank) != "0") return locks;
            break;
        }
    locks.lock(plan.image, "--out");
    locks.lock(plan.report, "--report");
    if (!plan.denoised.empty()) locks.lock(plan.denoised, "the denoised image beside --out");
    locks.lock(plan.film, plan.film_requested ? "--film" : "the film beside --out");
    return locks;
}

}  // namespace facet
