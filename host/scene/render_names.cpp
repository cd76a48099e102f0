#include "host/scene/render_names.hpp"

namespace facet {

std::string setting_name(std::span<const SettingName> table, int value) {
    for (const SettingName& n : table)
        if (n.value == value) return std::string(n.name);
    return std::to_string(value);
}

std::optional<int> setting_value(std::span<const SettingName> table, std::string_view name) {
    for (const SettingName& n : table)
        if (n.name == name) return n.value;
    return std::nullopt;
}

std::string setting_name_list(std::span<const SettingName> table) {
    std::string out;
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (i > 0) out += i + 1 == table.size() ? " or " : ", ";
        out += table[i].name;
    }
    return out;
}

std::map<std::string, int> setting_map(std::span<const SettingName> table) {
    std::map<std::string, int> out;
    for (const SettingName& n : table) out.emplace(n.name, n.value);
    return out;
}

}  // namespace facet
