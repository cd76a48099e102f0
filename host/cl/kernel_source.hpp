// Kernel sources: embedded in the binary at build time (cmake/embed_kernels.cmake),
// or read from disk when FACET_KERNEL_DIR names a kernels/ folder (for development:
// edit a .cl file and rerun without rebuilding). assemble_program() resolves
// #include "..." itself, inlining the file at every include (included files carry include
// guards, which leave all but the first one the preprocessor reads empty, so an include in a
// disabled #if block takes nothing away from later ones), and the OpenCL compiler sees one
// self-contained source whose #line directives name the real files.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace facet {

struct EmbeddedFile {
    const char* path;  // relative to the repository root, e.g. "kernels/trace/bvh_traverse.cl"
    const char* content;
};

// The renderer's kernels (kernels/ less kernels/test and kernels/bench), embedded in facet_core.
const std::vector<EmbeddedFile>& embedded_kernel_files();

// Adds another embedded table to the lookup: the tests' kernels (kernels/test, linked into
// facet_tests only) and the bench's (kernels/bench, into facet_bench only), whose generated
// sources call this from a static initializer, so the shipped facet holds neither. Returns true.
using EmbeddedTable = const std::vector<EmbeddedFile>& (*)();
bool register_embedded_kernel_files(EmbeddedTable table);

struct AssembledSource {
    std::string text;                // the whole program
    std::vector<std::string> files;  // every file it took in, in order
    std::string origin;              // "embedded" or the directory read from
};

// Assembles the program rooted at `entry` (a path such as "kernels/integrator/path.cl"),
// after the given preprocessor lines (e.g. "#define FC_FEATURE_X 1"). Throws
// facet::Error naming the file and line of an include that cannot be found, or an included
// file without an include guard.
AssembledSource assemble_program(const std::string& entry, const std::vector<std::string>& prelude = {});

}  // namespace facet
