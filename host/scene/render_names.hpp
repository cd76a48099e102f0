// The names of the render settings' closed lists (kernels/shared/render_layout.h:
// FC_STRATEGY_LIST, FC_SAMPLER_LIST), as scene files, the command line and film files spell
// them: each table is generated from its list, in value order.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "kernels/shared/render_layout.h"

namespace facet {

struct SettingName {
    std::string_view name;
    int value;
};

#define FC_SETTING_NAME(value, name) SettingName{name, value},
inline constexpr SettingName kStrategyNames[] = {FC_STRATEGY_LIST(FC_SETTING_NAME)};
inline constexpr SettingName kSamplerNames[] = {FC_SAMPLER_LIST(FC_SETTING_NAME)};
#undef FC_SETTING_NAME

// The name of `value`, or its number when the table has none.
std::string setting_name(std::span<const SettingName> table, int value);

// The value named `name`, if the table has it.
std::optional<int> setting_value(std::span<const SettingName> table, std::string_view name);

// "mis, light or bsdf": the names, for messages.
std::string setting_name_list(std::span<const SettingName> table);

// name -> value, for the command line's transformers.
std::map<std::string, int> setting_map(std::span<const SettingName> table);

}  // namespace facet
