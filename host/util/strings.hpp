// String helpers shared by the host: case folding and the messages that list names.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace facet {

// ASCII lower case.
inline std::string lower(std::string_view s) {
    std::string r(s);
    std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return r;
}

// "a, b, c", each name given by `name(item)`.
template <typename Range, typename Name>
std::string name_list(const Range& items, Name name) {
    std::string out;
    for (const auto& item : items) {
        if (!out.empty()) out.append(", ");
        out.append(name(item));
    }
    return out;
}
template <typename Range>
std::string name_list(const Range& items) {
    return name_list(items, [](const auto& n) { return std::string(n); });
}

// "unknown <what> '<value>' (known: <known>)", `known` e.g. from name_list().
inline std::string unknown_name(std::string_view what, std::string_view value, std::string_view known) {
    return fmt::format("unknown {} '{}' (known: {})", what, value, known);
}

}  // namespace facet
