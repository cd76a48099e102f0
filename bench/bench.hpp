// Sections of facet_bench (bench/bench_main.cpp runs them in one process).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cl/runtime.hpp"

namespace facet {

// BSDF eval+pdf and sample throughput of every named model; prints a table.
nlohmann::json bench_bsdfs(ClContext& ctx, bool quick);

// Equal-time error of BSDF sampling, environment sampling and MIS under stiff maps.
nlohmann::json bench_ibl(ClContext& ctx, const std::string& assets, bool quick);

// Specialised against generic programs: build time cold and warm, binary size, speed.
nlohmann::json bench_specialisation(ClContext& ctx, const std::string& assets, bool quick);

}  // namespace facet
