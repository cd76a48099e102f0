#include "host/cli/cli.hpp"

int main(int argc, char** argv) { return facet::run_cli(argc, argv); }
