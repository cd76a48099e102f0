// The files `facet render` writes, named and checked before the first sample: the
// linear image (--out), the tone-mapped PNG beside it, the report (--report: CSV, with
// .json and .svg beside it) and the film (--film, else beside --out on interrupt or
// failure). No two may be the same file, none may overwrite an input, and each must be
// writable (a file, not a folder or device, in a folder where a temporary can be made).
#pragma once

#include <string>

#include "host/cli/commands.hpp"

namespace facet {

struct OutputPlan {
    std::string image;            // --out: linear floats (.exr; or .hdr, .tif, .pfm)
    std::string png;              // the tone-mapped sRGB PNG beside it
    std::string report;           // CSV
    std::string report_json;      // summary beside the CSV
    std::string report_svg;       // plot beside the CSV
    std::string film;             // --film, else beside --out, never over an older film
    std::string denoised;         // --denoise: NAME.denoised.EXT beside --out ("" without)
    std::string denoised_png;     // its PNG
    bool film_requested = false;  // --film given: written at every end, not only on interrupt or failure
};

// The outputs of a render with these options (defaults: out/<scene>.exr and the rest
// beside it). Without --film the film goes beside --out as <stem>.film, or, when a file
// of that name exists and is not the film resumed, the first free <stem>-N.film.
OutputPlan plan_outputs(const RenderOptions& opt);

// Throws facet::Error naming the option, the path and the problem: an image format that
// cannot hold the linear image or that OpenImageIO cannot write, two outputs naming one
// file, an output naming an input (scene, --reference, --resume except as --film), an
// output that cannot be written (safe_write.hpp: check_output_path).
void check_outputs(const OutputPlan& plan, const RenderOptions& opt);

// Whether two paths name one file: the same absolute, normalised spelling with symbolic
// links of existing parts resolved, or one existing file (hard links).
bool same_file(const std::string& a, const std::string& b);

// Where an output that could not be written goes instead: the temporary folder
// ($TMPDIR, else /tmp), a name unique to this process ("facet-rescue-<pid>-<name>").
std::string rescue_path(const std::string& path);

}  // namespace facet
