// capture: headless frames of a compiled level as PNG, with per-column hits
// (--columns) and per-frame statistics (--stats). Same inputs, same bytes.
#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "engine/image/image.h"
#include "engine/bsp/load.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "tools/cli.h"

using namespace p3d;

namespace {

// The wall column is the wall's source number: its statement in a .map, its LINEDEF in a WAD.
std::string columns_csv(const level::Level& level, const render::ColumnHits& hits) {
  std::string out = "x,wall,dist\n";
  char line[96];
  for (size_t x = 0; x < hits.size(); ++x) {
    const int wall = hits[x].wall < 0 ? -1 : level.walls[size_t(hits[x].wall)].source;
    std::snprintf(line, sizeof line, "%zu,%d,%.9g\n", x, wall, wall < 0 ? 0.0 : hits[x].dist);
    out += line;
  }
  return out;
}

// PNGs encoded on worker threads while the next frames render; kept in camera order, so
// the outputs do not depend on the thread count. At most 2 x threads frames wait. The
// workers live as long as the encoder, so each keeps its buffers and compressor from
// frame to frame, and the frames' copies are recycled: a thread started for each frame
// began them afresh (at 1920x1080 on two threads, 172,000 page faults and a third of
// the time in memset and memcpy, slower than one thread).
class PngEncoder {
 public:
  explicit PngEncoder(int threads) : threads_(threads) {
    if (threads_ > 1)
      for (int i = 0; i < threads_; ++i) workers_.emplace_back([this] { work(); });
  }
  ~PngEncoder() {
    {
      const std::lock_guard lock(mutex_);
      stop_ = true;
    }
    work_ready_.notify_all();
    for (std::thread& t : workers_) t.join();
  }
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  void add(const std::filesystem::path& path, const render::Frame& frame, Outputs& outputs) {
    if (threads_ <= 1) return outputs.write_now(path, encode(frame));
    while (pending_.size() >= size_t(2 * threads_)) finish_oldest(outputs);
    std::unique_ptr<Job> job = take_spare();
    job->path = path;
    render::Frame& copy = job->frame;  // what the PNG needs: the indices or the colours, into kept buffers
    copy.width = frame.width, copy.height = frame.height;
    copy.indices.assign(frame.indices.begin(), frame.indices.end());
    copy.palette.assign(frame.palette.begin(), frame.palette.end());
    if (frame.indexed()) copy.pixels.clear();
    else copy.pixels.assign(frame.pixels.begin(), frame.pixels.end());
    {
      const std::lock_guard lock(mutex_);
      queue_.push_back(job.get());
    }
    work_ready_.notify_one();
    pending_.push_back(std::move(job));
  }
  void finish(Outputs& outputs) {
    while (!pending_.empty()) finish_oldest(outputs);
  }

 private:
  struct Job {
    std::filesystem::path path;
    render::Frame frame;
    std::vector<uint8_t> bytes;
    std::exception_ptr error;
    bool done = false;
  };

  // A frame of a paletted level stays 8-bit: a paletted PNG, a quarter of the bytes to filter.
  static std::vector<uint8_t> encode(const render::Frame& frame) {
    return frame.indexed() ? image::encode_png(frame.width, frame.height, frame.indices, frame.palette)
                           : image::encode_png(frame);
  }
  void work() {
    for (;;) {
      Job* job = nullptr;
      {
        std::unique_lock lock(mutex_);
        work_ready_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping, and nothing left
        job = queue_.front();
        queue_.pop_front();
      }
      std::vector<uint8_t> bytes;
      std::exception_ptr error;
      try {
        bytes = encode(job->frame);
      } catch (...) {
        error = std::current_exception();
      }
      {
        const std::lock_guard lock(mutex_);
        job->bytes = std::move(bytes), job->error = error, job->done = true;
      }
      job_done_.notify_all();
    }
  }
  void finish_oldest(Outputs& outputs) {
    Job& job = *pending_.front();
    {
      std::unique_lock lock(mutex_);
      job_done_.wait(lock, [&] { return job.done; });
    }
    if (job.error) std::rethrow_exception(job.error);
    outputs.write_now(job.path, job.bytes);  // on disk while the next frames render, not held to the end
    job.bytes.clear(), job.done = false;
    spares_.push_back(std::move(pending_.front()));
    pending_.pop_front();
  }
  std::unique_ptr<Job> take_spare() {
    if (spares_.empty()) return std::make_unique<Job>();
    std::unique_ptr<Job> job = std::move(spares_.back());
    spares_.pop_back();
    return job;
  }

  int threads_;
  std::deque<std::unique_ptr<Job>> pending_;  // camera order; the main thread's
  std::vector<std::unique_ptr<Job>> spares_;  // encoded and written: buffers to reuse
  std::mutex mutex_;                          // guards queue_, stop_ and each job's results
  std::condition_variable work_ready_, job_done_;
  std::deque<Job*> queue_;                    // jobs no worker has taken yet
  bool stop_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"pseudo3d-capture: render views of a level (.bsp, .map, .grid or a WAD's map) to PNG files", "pseudo3d-capture"};
  cli::LevelArgs level_args;
  std::string output, pos_text, size_text = "640x400", renderer_name = "bsp", columns, cameras, json;
  std::optional<double> angle;
  double eye = render::kEyeHeight, fov = 90;
  bool stats = false, all_warnings = false;
  int skill = level::kDefaultSkill;
  render::RendererOptions ropt;
  cli::add_level_options(app, level_args);
  app.add_option("--pos", pos_text, "camera position X,Y (map units; default: the player start)");
  app.add_option("--angle", angle, "view angle, degrees counter-clockwise from east (default: the player's)")
      ->check(cli::finite());
  app.add_option("--eye", eye, "eye height above the floor")->check(cli::finite())->capture_default_str();
  app.add_option("--fov", fov, "horizontal field of view, degrees")->check(cli::finite_range(1.0, 179.0))->capture_default_str();
  app.add_option("--size", size_text, "resolution WxH")->capture_default_str();
  app.add_option("--renderer", renderer_name, "renderer: " + [] {
    std::string names;
    for (const auto& n : render::renderer_names()) names += (names.empty() ? "" : ", ") + n;
    return names;
  }())->capture_default_str();
  app.add_option("-o,--output", output, "PNG to write (a directory with --cameras); default: out/<level>.png (out/<level>/)");
  app.add_option("--columns", columns, "CSV of x,wall,dist per column (a directory with --cameras)");
  app.add_option("--cameras", cameras, "file of cameras: NAME X Y ANGLE [EYE [FOV]] per line")->check(cli::existing_file());
  app.add_flag("--stats", stats, "print per-frame statistics (a statdump line) and time per frame (apart)");
  app.add_option("--json", json, "with --stats: also write them as JSON, with the same names");
  app.add_flag("--all-warnings", all_warnings, "list every warning about a WAD map's quirks");
  cli::add_skill_option(app, skill);
  cli::add_renderer_options(app, ropt);

  return cli::run(app, argc, argv, [&] {
    int width = 0, height = 0;
    cli::parse_size(size_text, width, height);
    auto renderer = render::make_renderer(renderer_name, ropt);
    if (!renderer) throw cli::ValidationError("--renderer", "unknown renderer '" + renderer_name + "'");

    const bsp::LevelSource source = cli::level_source(level_args);
    if (output.empty()) output = cli::default_output(source, cameras.empty() ? ".png" : "/");
    if (cameras.empty()) {
      cli::output_file(output, ".png", "--output");
      if (!columns.empty()) cli::output_file(columns, ".csv", "--columns");
    } else {
      cli::output_dir(output);
      if (!columns.empty()) cli::output_dir(columns, "--columns");
    }
    if (!json.empty()) cli::output_file(json, ".json", "--json");
    std::vector<render::CameraSpec> shots;
    if (!json.empty() && !stats) throw cli::ValidationError("--json", "writes the --stats: add --stats");
    if (!cameras.empty()) {
      if (!pos_text.empty()) throw cli::ValidationError("--pos", "use either --pos or --cameras");
      shots = render::read_camera_list(cameras);
    } else {
      if (angle && !std::isfinite(*angle)) throw cli::ValidationError("--angle", "must be finite");
      cli::check_eye(eye);
    }

    const bsp::OpenedLevel opened = bsp::open_level(source);
    cli::report_warnings(opened, all_warnings);
    const level::Level& level = opened.level;
    if (cameras.empty()) {  // one camera: where asked, else at the player start
      const geom::Vec2 pos = pos_text.empty() ? level.player_start : cli::parse_point(pos_text, "--pos");
      shots.push_back({"", pos, angle.value_or(pos_text.empty() ? level.player_angle : 0.0), eye, fov});
    }
    if (!renderer->supports(level))
      throw Error(opened.name + ": the " + renderer_name + " renderer cannot draw this level (it needs " +
                  std::string(renderer->needs()) + ")");
    renderer->prepare(level);
    const level::State state = level::start_state(level, skill);
    render::Frame frame(width, height);
    frame.keep_indices = true;
    render::Probe probe;
    probe.want_columns = !columns.empty();
    std::vector<std::string> json_frames;
    Outputs outputs;  // every frame, all or nothing
    PngEncoder encoder(ropt.threads);
    for (const render::CameraSpec& shot : shots) {
      cli::warn_if_outside("pseudo3d-capture", level, shot);
      const render::Camera camera = render::camera_at(level, shot.pos, shot.angle, shot.eye, shot.fov);
      const auto start = std::chrono::steady_clock::now();
      const render::RenderStats s = renderer->render(level, state, camera, frame, &probe);
      double ms = cli::seconds_since(start) * 1000;

      const bool many = !cameras.empty();
      encoder.add(many ? std::filesystem::path(output) / (shot.name + ".png") : std::filesystem::path(output), frame,
                  outputs);
      if (!columns.empty())
        outputs.add(many ? std::filesystem::path(columns) / (shot.name + ".csv") : std::filesystem::path(columns),
                    columns_csv(level, probe.columns));
      if (stats) {
        std::vector<double> times{ms};  // median of a few more frames: one frame is too noisy to report
        for (int i = 0; i < 4; ++i) {
          const auto again = std::chrono::steady_clock::now();
          renderer->render(level, state, camera, frame);
          times.push_back(cli::seconds_since(again) * 1000);
        }
        std::nth_element(times.begin(), times.begin() + 2, times.end());
        ms = times[2];
        const std::string name = shot.name.empty() ? "frame" : shot.name;
        std::printf("%s stats: %s\n%s time: ms_per_frame=%s\n", name.c_str(), statdump(render::stat_fields(s)).c_str(),
                    name.c_str(), stat_number(std::round(ms * 1000) / 1000).c_str());
        json_frames.push_back("{\"name\": " + json_string(name) + ", \"stats\": " + stats_json(render::stat_fields(s)) +
                              ", \"time\": " + stats_json({{"ms_per_frame", std::round(ms * 1000) / 1000}}) + "}");
      }
    }
    encoder.finish(outputs);
    if (!json.empty()) {
      std::string j = "{\"level\": " + json_string(opened.name) + ", \"renderer\": " + json_string(renderer_name) +
                      ", \"frames\": [\n";
      for (size_t i = 0; i < json_frames.size(); ++i) j += "  " + json_frames[i] + (i + 1 < json_frames.size() ? ",\n" : "\n");
      outputs.add(json, j + "]}\n");
    }
    outputs.commit();
    std::printf("wrote %s (%zu frame%s, %dx%d, %s)\n", output.c_str(), shots.size(), shots.size() == 1 ? "" : "s", width,
                height, renderer_name.c_str());
    return 0;
  });
}
