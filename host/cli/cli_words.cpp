#include "host/cli/cli_words.hpp"

#include <cstdlib>
#include <sstream>

#include <fmt/format.h>

#include "host/util/strings.hpp"

namespace facet {
namespace {

class PlainFormatter : public CLI::Formatter {
public:
    std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
        if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
        std::stringstream out;
        out << make_usage(app, name) << make_description(app) << make_positionals(app) << make_groups(app, mode)
            << make_subcommands(app, mode) << '\n'
            << make_footer(app);
        return out.str();
    }

    std::string make_usage(const CLI::App* app, std::string name) const override {
        // A subcommand's usage names the program too: "Usage: facet render [OPTIONS] scene".
        for (const CLI::App* p = app->get_parent(); p != nullptr; p = p->get_parent())
            if (!p->get_name().empty() && name.rfind(p->get_name(), 0) != 0) name = p->get_name() + " " + name;
        const std::string usage = CLI::Formatter::make_usage(app, name);
        return usage + (app->get_description().empty() ? "" : "\n");
    }

    // The placeholder of the value, never the validators' descriptions.
    std::string make_option_opts(const CLI::Option* opt) const override {
        if (opt->get_positional() || opt->get_type_size() == 0) return "";
        if (!opt->get_option_text().empty()) return " " + opt->get_option_text();
        std::string type = opt->get_type_name();
        if (type.empty()) return "";  // a flag such as --help
        type = type.substr(0, type.find(':'));
        const std::string placeholder = type == "INT" || type == "UINT" ? "N" : type == "FLOAT" ? "X" : "TEXT";
        if (opt->get_expected_min() > 1) {
            std::string list;
            for (int i = 0; i < opt->get_expected_min(); ++i) list += (i ? "," : "") + placeholder;
            return " " + list;
        }
        return " " + placeholder;
    }
};

}  // namespace

std::string or_list(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return out;
}

std::string closest_name(const std::string& word, const std::vector<std::string>& names) {
    std::string best;
    std::size_t best_distance = std::min<std::size_t>(3, word.size());
    for (const std::string& name : names) {
        const std::size_t d = edit_distance(lower(word), name);
        if (d < best_distance) best_distance = d, best = name;
    }
    return best;
}

std::shared_ptr<CLI::Formatter> plain_formatter() { return std::make_shared<PlainFormatter>(); }

CLI::Validator choice(const std::string& what, const std::vector<std::pair<std::string, long long>>& choices) {
    std::vector<std::string> names;
    for (const auto& c : choices) names.push_back(c.first);
    return CLI::Validator(
        [what, choices, names](std::string& text) {
            for (const auto& c : choices)
                if (c.first == text) {
                    text = std::to_string(c.second);
                    return std::string();
                }
            const std::string near = closest_name(text, names);
            return fmt::format("{} is not {}: one of {}{}", text, what, or_list(names),
                               near.empty() ? "" : fmt::format(" (did you mean {}?)", near));
        },
        "");
}

CLI::Validator one_of(const std::string& what, const std::vector<std::string>& names) {
    return CLI::Validator(
        [what, names](std::string& text) {
            for (const std::string& n : names)
                if (n == text) return std::string();
            const std::string near = closest_name(text, names);
            return fmt::format("{} is not {}: one of {}{}", text, what, or_list(names),
                               near.empty() ? "" : fmt::format(" (did you mean {}?)", near));
        },
        "");
}

CLI::Validator between(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0') return std::string();  // left to the conversion's message
            return v >= lo && v <= hi ? std::string() : fmt::format("Value {} is not between {} and {}", text, lo, hi);
        },
        "");
}

std::string conversion_words(const CLI::App& app, const CLI::ConversionError& e) {
    const std::string what = e.what();
    const std::string head = "Could not convert: ";
    const std::size_t eq = what.find(" = ");
    if (what.rfind(head, 0) != 0 || eq == std::string::npos) return "";
    const std::string name = what.substr(head.size(), eq - head.size()), value = what.substr(eq + 3);
    const CLI::App* cmd = &app;
    for (const CLI::App* sub : app.get_subcommands()) cmd = sub;  // the one parsed
    for (const CLI::Option* o : cmd->get_options()) {
        if (o->get_name() != name && "--" + o->get_single_name() != name) continue;
        std::string type = o->get_type_name();
        type = type.substr(0, type.find(':'));
        const char* kind = type == "UINT" ? "a whole number >= 0" : type == "INT" ? "a whole number" : "a number";
        return fmt::format("{}: {} is not {}", name, value, kind);
    }
    return "";
}

}  // namespace facet
