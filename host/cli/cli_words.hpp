// The command line in words: help that names each option's value and says its choices
// and default in the description (no validator internals), refusals that list the
// choices, and "did you mean" for names one or two edits from a known one.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace facet {

// "a", "a or b", "a, b or c".
std::string or_list(const std::vector<std::string>& names);

// The name among `names` closest to `word` by edit distance, if within 2 edits
// (and closer than the word is long); empty otherwise.
std::string closest_name(const std::string& word, const std::vector<std::string>& names);

// The help formatter of every command: the usage line first ("Usage: facet render
// [OPTIONS] scene"), then the description; an option shows its value's placeholder
// (its option_text, else N, X or TEXT from its type) and nothing of its validators.
std::shared_ptr<CLI::Formatter> plain_formatter();

// A validator for an option whose value is one of `choices` (name, value): turns the
// name into the value for the option to read ("filmic" -> "1"); any other text is
// refused as "<text> is not <what>: one of a, b or c" with the closest name suggested.
// Values are integers (or enums with integer values); names are matched exactly.
CLI::Validator choice(const std::string& what, const std::vector<std::pair<std::string, long long>>& choices);

// As choice(), for a text option whose value is one of `names` itself (e.g. each of --aov's).
CLI::Validator one_of(const std::string& what, const std::vector<std::string>& names);

// A number from lo to hi (both included), refused as "Value 40 is not between -30 and 30".
CLI::Validator between(double lo, double hi);

// For a value CLI11 could not convert ("Could not convert: --spp = abc"): the option and
// what it takes, "--spp: abc is not an integer"; empty when `e` names no option of `app`'s
// parsed command.
std::string conversion_words(const CLI::App& app, const CLI::ConversionError& e);

}  // namespace facet
