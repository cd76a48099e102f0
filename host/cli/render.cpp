// `facet render SCENE`: load, render through the render session (render/session.hpp:
// devices, the progressive driver and its stop rules, the tile mode, MPI ranks), write.
// After every pass: the progress line, the error against a reference and the CSV report;
// snapshots on request (best effort; denoised too with --denoise). On SIGINT, SIGTERM or
// SIGHUP the current pass ends (the first is dropped) and everything is written (exit
// 130); SIGPIPE is ignored (cli/stop_signals.hpp, util/console.hpp). Files and messages: cli/render_parts.hpp.
#include <fmt/format.h>

#include "host/cli/commands.hpp"
#include "host/util/console.hpp"
#include "host/cli/output_locks.hpp"
#include "host/cli/outputs.hpp"
#include "host/cli/progress.hpp"
#include "host/cli/render_parts.hpp"
#include "host/cli/resume_size.hpp"
#include "host/cli/stop_signals.hpp"
#include "host/error.hpp"
#include "host/film/error_metrics.hpp"
#include "host/readers/load_scene.hpp"
#include "host/render/session.hpp"
#include "host/scene/camera_focus.hpp"
#include "host/report/report.hpp"

namespace facet {
namespace {

// After each pass: the reference's error, the report row, the progress line and (on
// request) a snapshot, which is best effort: a failed snapshot is a warning and the
// render goes on.
class PassReporter {
public:
    explicit PassReporter(const RenderJob& job) : job_(job), progress_(job.opt.quiet) {}

    void operator()(const SessionPass& d) {
        PassRecord p = d.record;
        const RenderOptions& opt = job_.opt;
        if (job_.reference) p.reference = compare_images(job_.session.image(), job_.reference->rgb, opt.reference);
        passes_.push_back(p);
        write_report_csv(job_.plan.report, passes_);
        progress_.update(p, d.target_spp, d.remaining_s, d.msamples_per_s, d.last);
        if (opt.snapshot && p.wall_s - last_snapshot_ >= *opt.snapshot && !d.last) {
            last_snapshot_ = p.wall_s;
            try {
                write_image(job_, job_.plan.image, job_.session.image());
                // With --denoise the snapshot is denoised too, and its row gets the denoised error
                if (!job_.plan.denoised.empty() && p.spp >= 2) write_denoised(job_, passes_.back(), {}, false);
            } catch (const Error& e) {
                say(stderr, "facet: warning: snapshot not written ({}); rendering goes on\n", e.what());
            }
        }
    }

    std::vector<PassRecord>& passes() { return passes_; }

private:
    const RenderJob& job_;
    Progress progress_;
    std::vector<PassRecord> passes_;
    double last_snapshot_ = 0.0;
};

// One sample per pixel takes longer than --time, as measured: the render is that pass.
void warn_slow_first_pass(const RenderOptions& opt, double first_pass_s) {
    say(stderr,
        "facet: warning: one sample per pixel takes about {} (past --time {} already, as measured); "
        "rendering one\n",
        fmt_seconds(first_pass_s), *opt.time_limit);
}

}  // namespace

int run_render(const RenderOptions& opt) {
    const auto start = std::chrono::steady_clock::now();
    const SigpipeIgnored sigpipe_ignored;  // `facet render ... | head -1` renders on
    Scene scene = load_scene(opt.scene, opt.camera, opt.strict);
    apply_overrides(opt, scene);
    settle_focus(scene);  // a target nearer than anything in view: focus at the image centre (camera_focus.hpp)
    for (const std::string& w : scene.warnings) say(stderr, "facet: warning: {}\n", w);
    const OutputPlan plan = plan_outputs(opt);
    check_outputs(plan, opt);
    check_render_options(opt, plan);
    const OutputLocks locks = lock_outputs(plan);  // held to the end (output_locks.hpp)
    SessionOptions session_opt = session_options(opt, start);
    if (session_opt.resume)
        take_film_size(*session_opt.resume, opt, scene.settings);  // --width/--height default to the film's
    std::optional<ImageRGB> reference;
    if (!opt.reference.empty()) reference = read_reference(opt.reference, scene.settings.width, scene.settings.height);

    RenderSession session(scene, std::move(session_opt));
    if (session.follow()) return kExitOk;  // an MPI rank other than 0
    RenderJob job{opt, scene, plan, session, aov_layers(opt, session.aovs()), std::move(reference), start};
    FilmOnError film_on_error(job);
    if (!opt.quiet) print_header(job);

    // Held until every file is written: a second Ctrl-C during the writes is counted, not fatal.
    StopSignals signals;
    PassReporter reporter(job);
    SessionHooks hooks;
    hooks.stop_signal = [&] { return signals.first(); };
    hooks.on_pass = [&](const SessionPass& d) { reporter(d); };
    hooks.on_slow_first_pass = [&](double first_pass_s) { warn_slow_first_pass(opt, first_pass_s); };
    hooks.on_rank_lost = [&](const DeviceGroupWatch::Lost& lost) { return write_on_rank_lost(job, lost); };
    const SessionOutcome outcome = session.run(hooks);
    return finish_render(job, outcome, reporter.passes(), film_on_error);
}

}  // namespace facet
