// String helpers shared by the host: case folding and the messages that list names.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

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

// Levenshtein distance (insertions, deletions, substitutions), for "did you mean".
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

}  // namespace facet
