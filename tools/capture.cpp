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
#include "tools/large_pages.h"

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

// What one camera makes: its PNG and, when asked for, its columns.
struct Shot {
  render::Camera camera;
  std::filesystem::path png_path, csv_path;  // csv_path empty: no --columns
  int png_level = image::kPngDefaultLevel;
  std::vector<uint8_t> png;
  std::string csv;
};

// One camera rendered (on the renderer's threads) and encoded; its frame's statistics.
render::RenderStats make_shot(render::Renderer& renderer, const level::Level& level, const level::State& state,
                              render::Frame& frame, Shot& shot) {
  render::Probe probe;
  probe.want_columns = !shot.csv_path.empty();
  const render::RenderStats stats = renderer.render(level, state, shot.camera, frame, &probe);
  shot.png = frame.png(shot.png_level);
  if (probe.want_columns) shot.csv = columns_csv(level, probe.columns);
  return stats;
}

// Whole frames rendered and encoded on worker threads, each with its own renderer and
// frame, handed back in camera order, so the outputs do not depend on the thread count.
// The cores share the frames' work evenly: a frame's strips drawn on every thread beside
// encoder threads competed with them for the cores (on two threads at 3840x2160, 1.43
// times one thread's speed, where whole frames give 1.65-1.9). At most 8 x threads
// shots wait: a slow frame at the head of the line holds back only the frames queued
// behind it (with 2 x threads, the other workers ran dry behind it: 100 random views of
// MAP01 at 1920x1080 on two threads took 1.50 times one thread's speed, with 8 x 1.78).
class ShotWorkers {
 public:
  ShotWorkers(int threads, const level::Level& level, const level::State& state, const std::string& renderer,
              const render::RendererOptions& options, int width, int height)
      : threads_(threads) {
    render::RendererOptions one = options;
    one.threads = 1;
    for (int i = 0; i < threads_; ++i) {
      std::shared_ptr<render::Renderer> r = render::make_renderer(renderer, one);  // a name capture has checked
      r->prepare(level);
      workers_.emplace_back([=, this, &level, &state] {
        large_pages_for_this_thread();  // its frame and buffers fault in 2 MB at a time, as the main thread's
        render::Frame frame = render::Frame::without_pixels(width, height);
        frame.keep_indices = true;
        work(*r, level, state, frame);
      });
    }
  }
  ~ShotWorkers() {
    {
      const std::lock_guard lock(mutex_);
      stop_ = true;
    }
    work_ready_.notify_all();
    for (std::thread& t : workers_) t.join();
  }
  ShotWorkers(const ShotWorkers&) = delete;
  ShotWorkers& operator=(const ShotWorkers&) = delete;

  // Queues a shot; calls done(shot) for the oldest ones, in order, to make room.
  template <typename Done>
  void add(Shot shot, Done&& done) {
    while (pending_.size() >= size_t(8 * threads_)) finish_oldest(done);
    auto job = std::make_unique<Job>();
    job->shot = std::move(shot);
    {
      const std::lock_guard lock(mutex_);
      queue_.push_back(job.get());
    }
    work_ready_.notify_one();
    pending_.push_back(std::move(job));
  }
  template <typename Done>
  void finish(Done&& done) {
    while (!pending_.empty()) finish_oldest(done);
  }

 private:
  struct Job {
    Shot shot;
    std::exception_ptr error;
    bool done = false;
  };

  void work(render::Renderer& renderer, const level::Level& level, const level::State& state, render::Frame& frame) {
    for (;;) {
      Job* job = nullptr;
      {
        std::unique_lock lock(mutex_);
        work_ready_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping, and nothing left
        job = queue_.front();
        queue_.pop_front();
      }
      std::exception_ptr error;
      try {
        make_shot(renderer, level, state, frame, job->shot);
      } catch (...) {
        error = std::current_exception();
      }
      {
        const std::lock_guard lock(mutex_);
        job->error = error, job->done = true;
      }
      job_done_.notify_all();
    }
  }
  template <typename Done>
  void finish_oldest(Done&& done) {
    Job& job = *pending_.front();
    {
      std::unique_lock lock(mutex_);
      job_done_.wait(lock, [&] { return job.done; });
    }
    if (job.error) std::rethrow_exception(job.error);
    done(job.shot);
    pending_.pop_front();
  }

  int threads_;
  std::deque<std::unique_ptr<Job>> pending_;  // camera order; the main thread's
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
  int skill = level::kDefaultSkill, png_level = image::kPngDefaultLevel;
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
  app.add_option("--png-level", png_level,
                 "PNG compression, 0-12: 0 stores the pixels (the fastest, 4 to 12 times the bytes), 1 deflates "
                 "runs and literals, 2-12 search for matches (3 to 430 times as slow; 12: 9-26% smaller)")
      ->check(cli::Range(image::kPngStored, image::kPngMaxLevel))
      ->capture_default_str();
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
    const level::State state = level::start_state(level, skill);
    const bool many = !cameras.empty();
    auto shot_of = [&](const render::CameraSpec& spec) {
      cli::warn_if_outside("pseudo3d-capture", level, spec);
      Shot shot{render::camera_at(level, spec.pos, spec.angle, spec.eye, spec.fov), output, {}, png_level, {}, {}};
      if (many) shot.png_path = std::filesystem::path(output) / (spec.name + ".png");
      if (!columns.empty())
        shot.csv_path = many ? std::filesystem::path(columns) / (spec.name + ".csv") : std::filesystem::path(columns);
      return shot;
    };
    std::vector<std::string> json_frames;
    Outputs outputs;  // every frame, all or nothing
    auto write = [&](Shot& shot) {
      outputs.write_now(shot.png_path, shot.png);  // on disk while the next frames render, not held to the end
      if (!shot.csv_path.empty()) outputs.add(shot.csv_path, std::move(shot.csv));
    };
    if (many && !stats && ropt.threads > 1) {  // frames shared out whole
      ShotWorkers workers(ropt.threads, level, state, renderer_name, ropt, width, height);
      for (const render::CameraSpec& spec : shots) workers.add(shot_of(spec), write);
      workers.finish(write);
    } else {  // each frame's strips on every thread (--stats times them so)
      renderer->prepare(level);
      render::Frame frame = render::Frame::without_pixels(width, height);
      frame.keep_indices = true;
      for (const render::CameraSpec& spec : shots) {
        Shot shot = shot_of(spec);
        const render::RenderStats s = make_shot(*renderer, level, state, frame, shot);
        write(shot);
        if (!stats) continue;
        std::vector<double> times;  // the median of five renders: one frame is too noisy to report
        for (int i = 0; i < 5; ++i) {
          const auto start = std::chrono::steady_clock::now();
          renderer->render(level, state, shot.camera, frame);
          times.push_back(cli::seconds_since(start) * 1000);
        }
        std::nth_element(times.begin(), times.begin() + 2, times.end());
        const double ms = times[2];
        const std::string name = spec.name.empty() ? "frame" : spec.name;
        std::printf("%s stats: %s\n%s time: ms_per_frame=%s\n", name.c_str(), statdump(render::stat_fields(s)).c_str(),
                    name.c_str(), stat_number(std::round(ms * 1000) / 1000).c_str());
        json_frames.push_back("{\"name\": " + json_string(name) + ", \"stats\": " + stats_json(render::stat_fields(s)) +
                              ", \"time\": " + stats_json({{"ms_per_frame", std::round(ms * 1000) / 1000}}) + "}");
      }
    }
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
