#include "host/cli/outputs.hpp"

#include <unistd.h>

#include <filesystem>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/util/safe_write.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

struct Named {
    std::string label;  // how the message names it: "--out", "the PNG beside --out"
    std::string path;
};

// One spelling per file: absolute, normalised, symbolic links of existing parts resolved.
fs::path key(const std::string& path) {
    std::error_code ec;
    fs::path abs = fs::absolute(path, ec);
    if (ec) return fs::path(path).lexically_normal();
    fs::path canon = fs::weakly_canonical(abs, ec);
    return ec ? abs.lexically_normal() : canon;
}

// The film beside --out when --film is not given: <image stem>.film, unless a file of
// that name exists and is not the film being resumed, then the first free name of
// <stem>-2.film, <stem>-3.film, ...: an older film (perhaps one facet said to resume
// from) is never replaced by a render that was not asked to continue it.
std::string implicit_film(const std::string& image, const std::string& resume) {
    const std::string first = replace_extension(image, ".film");
    std::error_code ec;
    auto free = [&](const std::string& p) {
        return !fs::exists(fs::symlink_status(p, ec)) || (!resume.empty() && same_file(p, resume));
    };
    if (free(first)) return first;
    const fs::path img(image);
    for (int n = 2; n <= 1000; ++n) {
        const std::string candidate = (img.parent_path() / fmt::format("{}-{}.film", img.stem().string(), n)).string();
        if (free(candidate)) return candidate;
    }
    throw Error(fmt::format(
        "--out {}: the films {} and {}-2.film to {}-1000.film beside it all exist: remove "
        "those no longer needed, or name this render's film with --film",
        image, first, (img.parent_path() / img.stem()).string(), (img.parent_path() / img.stem()).string()));
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
    if (key(a) == key(b)) return true;
    std::error_code ec;
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec;  // hard links
}

OutputPlan plan_outputs(const RenderOptions& opt) {
    OutputPlan plan;
    plan.image = opt.out.empty() ? (fs::path("out") / fs::path(opt.scene).stem()).string() + ".exr" : opt.out;
    plan.png = replace_extension(plan.image, ".png");
    plan.report = opt.report.empty() ? replace_extension(plan.image, ".csv") : opt.report;
    plan.report_json = replace_extension(plan.report, ".json");
    plan.report_svg = replace_extension(plan.report, ".svg");
    plan.film_requested = !opt.film.empty();
    plan.film = plan.film_requested ? opt.film : implicit_film(plan.image, opt.resume);
    if (opt.denoise != "none") {
        const fs::path img(plan.image);
        plan.denoised = (img.parent_path() / img.stem()).string() + ".denoised" + img.extension().string();
        plan.denoised_png = replace_extension(plan.denoised, ".png");
    }
    return plan;
}

void check_outputs(const OutputPlan& plan, const RenderOptions& opt) {
    // A folder or device first: "no extension" would be a poor answer for /dev/full.
    check_output_path(plan.image, "--out");
    std::string why;
    if (!can_write_float_image(plan.image, &why)) throw Error(fmt::format("--out {}: {}", plan.image, why));
    const std::string film_label = plan.film_requested ? "--film" : "the film beside --out";
    std::vector<Named> outputs = {{"--out", plan.image},
                                  {"the PNG beside --out", plan.png},
                                  {"--report", plan.report},
                                  {"the .json summary beside --report", plan.report_json},
                                  {"the .svg plot beside --report", plan.report_svg}};
    if (!plan.denoised.empty()) {
        outputs.push_back({"the denoised image beside --out", plan.denoised});
        outputs.push_back({"the denoised PNG beside --out", plan.denoised_png});
    }
    outputs.push_back({film_label, plan.film});  // last (the --resume exception below)
    std::vector<Named> inputs = {{"the scene", opt.scene}};
    if (!opt.reference.empty()) inputs.push_back({"--reference", opt.reference});
    if (!opt.resume.empty()) inputs.push_back({"--resume", opt.resume});
    for (const Named& out : outputs)
        for (const Named& in : inputs) {
            // Continuing a film and saving it back under the same name is the point of --resume.
            if (in.label == "--resume" && &out == &outputs.back()) continue;
            if (same_file(out.path, in.path))
                throw Error(fmt::format("{} {}: would overwrite {} ({})", out.label, out.path, in.label, in.path));
        }
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (same_file(outputs[i].path, outputs[j].path))
                throw Error(fmt::format("{} {}: is the same file as {} ({}): each output needs its own name",
                                        outputs[i].label, outputs[i].path, outputs[j].label, outputs[j].path));
    for (const Named& out : outputs)
        if (&out != &outputs.back() || plan.film_requested) check_output_path(out.path, out.label);
}

std::string rescue_path(const std::string& path) {
    std::error_code ec;
    fs::path dir = fs::temp_directory_path(ec);
    if (ec) dir = "/tmp";
    return (dir / fmt::format("facet-rescue-{}-{}", ::getpid(), fs::path(path).filename().string())).string();
}

}  // namespace facet
