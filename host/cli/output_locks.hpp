// Locks on the files a command writes or continues, so that two facet processes never
// work on one film or output at once: two renders resuming one film in place would each
// save their own samples over the other's, and two renders sharing --out could leave the
// image of one beside the film and report of the other. Each file F is locked through a
// hidden lock file beside it, ".F.lock" (flock(2), exclusive, not waiting), which holds
// the owner's process id for the message and is removed when the lock is released; the
// lock is released by the kernel when the process ends in any way, so a lock file left by
// a killed process does not block the next command.
#pragma once

#include <string>
#include <vector>

#include "host/cli/outputs.hpp"

namespace facet {

class OutputLocks {
public:
    OutputLocks() = default;
    OutputLocks(OutputLocks&& other) noexcept;
    OutputLocks& operator=(OutputLocks&& other) noexcept;
    OutputLocks(const OutputLocks&) = delete;
    OutputLocks& operator=(const OutputLocks&) = delete;
    ~OutputLocks();

    // Locks `path` (its lock file beside it); throws facet::Error starting with `label`
    // and the path when another process holds it, naming that process and the lock file,
    // or when the lock file cannot be made. A path that names a file already locked
    // here (by any spelling) is not locked twice.
    void lock(const std::string& path, const std::string& label);

    std::size_t size() const { return held_.size(); }

private:
    struct Held {
        std::string path;       // the file locked
        std::string lock_path;  // its lock file
        int fd = -1;
    };
    void release() noexcept;
    std::vector<Held> held_;
};

// The lock file of `path`: ".<name>.lock" in the same folder (a name too long for that:
// its first 200 bytes and a hash of the whole).
std::string lock_path_for(const std::string& path);

// Locks the files of a render: the film (--film or the one beside --out; a film resumed
// in place is that film), --out and --report (the PNG, JSON and SVG beside them follow
// their names). An MPI rank other than 0 (by the launcher's environment) locks nothing.
OutputLocks lock_outputs(const OutputPlan& plan);

}  // namespace facet
