// The parts of `facet render` (cli/render.cpp) around the render session
// (render/session.hpp): the command line applied to the scene, the files written and the
// messages printed. The session decides what is rendered and when it stops; these say
// it and write it.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/outputs.hpp"
#include "host/image/image_io.hpp"
#include "host/film/sample_ranges.hpp"
#include "host/render/session.hpp"
#include "host/report/report.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// One render command: what every write and message reads.
struct RenderJob {
    const RenderOptions& opt;
    const Scene& scene;
    const OutputPlan& plan;
    const RenderSession& session;
    std::vector<ImageLayer> layers;     // the --aov layers of the EXR
    std::optional<ImageRGB> reference;  // --reference
    std::chrono::steady_clock::time_point start;
    double since_start() const;
};

// cli/render_scene.cpp: the options that replace the scene's settings and camera, and
// the checks of option combinations; throws facet::Error naming the option.
void apply_overrides(const RenderOptions& opt, Scene& scene);
void check_render_options(const RenderOptions& opt, const OutputPlan& plan);
// The session's options from the command line (reads the --resume film).
SessionOptions session_options(const RenderOptions& opt, std::chrono::steady_clock::time_point start);
// The --aov layers of the EXR, in the order asked.
std::vector<ImageLayer> aov_layers(const RenderOptions& opt, const std::optional<AovImages>& aovs);

// cli/render_files.cpp. The image (EXR metadata included) and its PNG when `with_png`.
void write_image(const RenderJob& job, const std::string& out, const std::vector<float>& rgb, bool with_png = true,
                 const ImageMetadata& extra = {});
// The final image, its PNG, and the film when asked (--film), interrupted or when the
// image fails (and the session has one). An image or film that cannot be written where
// asked goes to a rescue path (cli/outputs.hpp), said on stderr, and false is returned.
bool write_final(const RenderJob& job, const std::vector<float>& rgb, bool interrupted,
                 const ImageMetadata& extra = {});
// --denoise: the denoised image and its PNG (plan.denoised), with the denoiser named in
// its metadata and on stdout, and its error (estimated; against --reference when given)
// in `row`, the report's last row. Returns the denoiser that ran; empty, with the message
// printed, when it could not be made or written (the noisy image is written already).
// `announce`: say it on stdout (not for snapshots).
std::string write_denoised(const RenderJob& job, PassRecord& row, const ImageMetadata& extra = {},
                           bool announce = true);
// At rank 0, when the job lost a rank: the image and film of the last pass end, the
// samples missing and how to add them; the exit status.
int write_on_rank_lost(const RenderJob& job, const DeviceGroupWatch::Lost& lost);

// Saves the film when an error ends the render before its final write (a failed pass,
// report or snapshot): the samples finished so far are not lost.
class FilmOnError {
public:
    explicit FilmOnError(const RenderJob& job);
    void disarm() { armed_ = false; }  // the final write has saved what there is to save
    ~FilmOnError();
    FilmOnError(const FilmOnError&) = delete;
    FilmOnError& operator=(const FilmOnError&) = delete;

private:
    const RenderJob& job_;
    int exceptions_;
    bool armed_ = true;
};

// cli/render_messages.cpp. The devices, scene, kernels, resumed film and camera.
void print_header(const RenderJob& job);
// After the session: the final image and film (write_final; `film_on_error` then
// disarmed), the report's summary and files, the messages of the end; the exit status.
int finish_render(const RenderJob& job, const SessionOutcome& outcome, std::vector<PassRecord>& passes,
                  FilmOnError& film_on_error);

}  // namespace facet
