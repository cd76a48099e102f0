// The one exception type facet throws for problems a user can act on: its message
// is printed as is, so it names the file, the option or the OpenCL call concerned.
#pragma once

#include <stdexcept>
#include <string>

namespace facet {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace facet
