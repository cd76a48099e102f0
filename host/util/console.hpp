// Printing that survives its audience leaving. While facet renders SIGPIPE is ignored,
// so a write to a closed pipe (`facet render ... | head -1`) fails with EPIPE instead
// of killing the process: the stream is then marked closed, later prints to it are
// dropped, and the render goes on to write its files.
#pragma once

#include <cstdio>
#include <string_view>

#include <fmt/format.h>

namespace facet {

// Writes and flushes `text` unless `stream` failed before.
void print_to(std::FILE* stream, std::string_view text);

// Whether a write to `stream` has failed.
bool stream_closed(std::FILE* stream);

template <typename... Args>
void say(std::FILE* stream, fmt::format_string<Args...> f, Args&&... args) {
    if (!stream_closed(stream)) print_to(stream, fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace facet
