#include "host/util/console.hpp"

#include <atomic>

namespace facet {
namespace {

std::atomic<bool> g_stdout_closed{false}, g_stderr_closed{false}, g_other_closed{false};

std::atomic<bool>& closed_flag(std::FILE* stream) {
    if (stream == stdout) return g_stdout_closed;
    if (stream == stderr) return g_stderr_closed;
    return g_other_closed;
}

}  // namespace

bool stream_closed(std::FILE* stream) { return closed_flag(stream).load(); }

void print_to(std::FILE* stream, std::string_view text) {
    std::atomic<bool>& closed = closed_flag(stream);
    if (closed.load()) return;
    const bool ok = std::fwrite(text.data(), 1, text.size(), stream) == text.size() && std::fflush(stream) == 0;
    if (!ok) {
        closed.store(true);
        std::clearerr(stream);
    }
}

}  // namespace facet
