// What the progressive driver (render/progressive.hpp) renders on: one device's film
// (Renderer), or several devices and MPI ranks, each taking its share of the rows
// (DeviceGroup).
#pragma once

#include <cstdint>

namespace facet {

class PassTarget {
public:
    virtual ~PassTarget() = default;
    virtual std::uint32_t target_width() const = 0;
    virtual std::uint32_t target_height() const = 0;
    // Samples per pixel finished (whole passes).
    virtual std::uint64_t finished_spp() const = 0;
    // Adds `count` samples, with indices from finished_spp(), to every pixel of rows
    // [row_begin, row_begin + row_count), and waits until they are done.
    virtual void launch(std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count) = 0;
    // Counts a pass of `count` samples launched over every row, which took `seconds`.
    virtual void end_pass(std::uint32_t count, double seconds) = 0;
    // Drops every sample accumulated (an unfinished first pass).
    virtual void reset() = 0;
};

}  // namespace facet
