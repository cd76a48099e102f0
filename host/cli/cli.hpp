// The facet command line: `facet devices`, `facet render`.
#pragma once

namespace facet {

// Parses the arguments and runs the command; returns the process exit status
// (0 success, 1 error, 2 usage error, 130 interrupted after writing the image so far).
int run_cli(int argc, char** argv);

}  // namespace facet
