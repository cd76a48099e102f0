// The render's signal handling. While a StopSignals lives, SIGINT, SIGTERM and SIGHUP
// (the terminal closed) request a stop, which the progressive driver honours between
// launches. Keep it alive until every file is written: a second Ctrl-C during the
// final writes is then counted, not fatal. While a SigpipeIgnored lives (the whole
// command, from its first line of output), SIGPIPE is ignored: util/console.hpp then
// stops printing to a closed stream and the render goes on. Both destructors restore
// the previous dispositions.
#pragma once

#include <csignal>

namespace facet {

class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    // The first stop signal received (0: none).
    int first() const;
    // How many stop signals were received.
    int count() const;

private:
    struct sigaction old_int_ {
    }, old_term_{}, old_hup_{};
};

class SigpipeIgnored {
public:
    SigpipeIgnored();
    ~SigpipeIgnored();
    SigpipeIgnored(const SigpipeIgnored&) = delete;
    SigpipeIgnored& operator=(const SigpipeIgnored&) = delete;

private:
    struct sigaction old_ {};
};

}  // namespace facet
