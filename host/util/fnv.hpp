// FNV-1a, 64 bits (Fowler, Noll and Vo): the film's payload checksum and the scene identity.
#pragma once

#include <cstddef>
#include <cstdint>

namespace facet {

struct Fnv1a {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const unsigned char* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) {
            h ^= b[i];
            h *= 1099511628211ull;
        }
    }
};

}  // namespace facet
