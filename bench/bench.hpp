// Sections of facet_bench (bench/bench_main.cpp runs them in one process).
#pragma once

#include <nlohmann/json.hpp>

#include "cl/runtime.hpp"

namespace facet {

// BSDF eval+pdf and sample throughput of every named model; prints a table.
nlohmann::json bench_bsdfs(ClContext& ctx, bool quick);

}  // namespace facet
