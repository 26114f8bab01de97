// compare: one level and camera (or a camera path) through every applicable
// renderer. Writes a picture with the frames side by side, each labelled, and
// under each its difference from the reference and its overdraw; prints a table
// (and --json) of time, pixels, overdraw, traversal and ray statistics, and how
// far each renderer's pixels and per-column hits are from the reference.
#include <algorithm>
#include <cmath>
#include <map>

#include "engine/bsp/load.h"
#include "engine/image/font.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "tools/cli.h"

using namespace p3d;
using Clock = std::chrono::steady_clock;

namespace {

struct Result {  // one renderer, one camera
  double ms = 0;
  render::RenderStats stats;
  double pixel_diff = 0, column_diff = 0;
};

struct Row {  // one renderer over all cameras
  std::string name;
  std::vector<Result> results;
  render::Frame frame;  // of the first camera
  image::Image diff, overdraw;
  double overdraw_max = 0;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// Columns whose closing wall or distance differ from the reference (an exact tie
// between two walls at the same distance counts as agreement).
double column_difference(const render::ColumnHits& a, const render::ColumnHits& ref) {
  size_t differ = 0;
  for (size_t x = 0; x < ref.size(); ++x) {
    const bool same = a[x].wall == ref[x].wall && (a[x].wall < 0 || a[x].dist == ref[x].dist);
    const bool tie = a[x].wall >= 0 && ref[x].wall >= 0 && std::fabs(a[x].dist - ref[x].dist) <= 1e-9 * ref[x].dist;
    differ += !(same || tie);
  }
  return ref.empty() ? 0 : double(differ) / ref.size();
}

// Median time of `frames` renders (after the probed one).
double time_frames(render::Renderer& r, const level::Level& level, const level::State& state,
                   const render::Camera& camera, render::Frame& frame, int frames) {
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    const auto start = Clock::now();
    r.render(level, state, camera, frame);
    ms.push_back(cli::seconds_since(start) * 1000);
  }
  return median(ms);
}

std::string number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// The picture: per renderer a column of [label, frame, label, diff, label, overdraw].
image::Image compose(const std::vector<Row>& rows, int w, int h) {
  const int scale = w >= 480 ? 2 : 1, bar = image::kGlyphHeight * scale + 6, gap = 4;
  image::Image out(int(rows.size()) * (w + gap) - gap, 3 * (bar + h), image::rgba(32, 32, 40));
  const uint32_t white = image::rgba(240, 240, 240), grey = image::rgba(170, 170, 180);
  for (size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    const int x = int(i) * (w + gap);
    std::vector<double> ms;
    for (const Result& r : row.results) ms.push_back(r.ms);
    const Result& first = row.results.front();
    const double overdraw = double(first.stats.pixels_written) / (double(w) * h);
    image::draw_text(out, x + 3, 3, row.name + "  " + number(median(ms), 3) + " ms", white, scale);
    image::blit(out, row.frame, x, bar);
    image::draw_text(out, x + 3, bar + h + 3,
                     row.name == "reference" ? "the reference" : "vs reference: " + number(100 * first.pixel_diff, 2) + "% px",
                     grey, scale);
    image::blit(out, row.diff, x, 2 * bar + h);
    image::draw_text(out, x + 3, 2 * (bar + h) + 3,
                     "overdraw " + number(overdraw, 2) + "x (max " + number(row.overdraw_max, 0) + ")", grey, scale);
    image::blit(out, row.overdraw, x, 3 * bar + 2 * h);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"pseudo3d-compare: one level and camera through every renderer, side by side", "pseudo3d-compare"};
  cli::LevelArgs level_args;
  std::string pos_text, path_file, size_text = "320x200", output, json;
  std::vector<std::string> names;
  std::optional<double> angle;
  double eye = render::kEyeHeight, fov = 90;
  int frames = 5, skill = level::kDefaultSkill;
  render::RendererOptions ropt;
  cli::add_level_options(app, level_args);
  cli::add_skill_option(app, skill);
  app.add_option("--pos", pos_text, "camera position X,Y (default: the player start)");
  app.add_option("--angle", angle, "view angle, degrees counter-clockwise from east (default: the player's)")
      ->check(cli::finite());
  app.add_option("--eye", eye, "eye height above the floor")->check(cli::finite())->capture_default_str();
  app.add_option("--fov", fov, "horizontal field of view")->check(cli::finite_range(1.0, 179.0))->capture_default_str();
  app.add_option("--path", path_file, "camera path (NAME X Y ANGLE [EYE [FOV]] per line): report medians")
      ->check(cli::existing_file());
  app.add_option("--size", size_text, "resolution WxH")->capture_default_str();
  app.add_option("--renderers", names, "renderers to compare (default: every one that can draw the level)")
      ->delimiter(',');
  app.add_option("--frames", frames, "timed frames per camera (median)")->check(cli::Range(1, 1000))->capture_default_str();
  cli::add_renderer_options(app, ropt);
  app.add_option("-o,--output", output, "PNG to write (default: out/<level>_compare.png)");
  app.add_option("--json", json, "also write the table as JSON");

  return cli::run(app, argc, argv, [&] {
    int w = 0, h = 0;
    cli::parse_size(size_text, w, h);
    const bsp::LevelSource source = cli::level_source(level_args);
    if (output.empty()) output = cli::default_output(source, "_compare.png");
    cli::output_file(output, ".png", "--output");
    if (!json.empty()) cli::output_file(json, ".json", "--json");
    std::vector<render::CameraSpec> specs;
    if (!path_file.empty()) {
      if (!pos_text.empty()) throw cli::ValidationError("--pos", "use either --pos or --path");
      specs = render::read_camera_list(path_file);
    } else {
      if (angle && !std::isfinite(*angle)) throw cli::ValidationError("--angle", "must be finite");
      cli::check_eye(eye);
    }
    const bool asked = !names.empty();
    if (names.empty()) names = render::renderer_names();
    names.erase(std::remove(names.begin(), names.end(), "reference"), names.end());
    names.push_back("reference");  // the baseline, drawn last

    const bsp::OpenedLevel opened = bsp::open_level(source);
    cli::report_warnings(opened, false);
    const level::Level& level = opened.level;
    const level::State state = level::start_state(level, skill);
    if (path_file.empty()) {  // one camera: where asked, else at the player start
      const geom::Vec2 pos = pos_text.empty() ? level.player_start : cli::parse_point(pos_text, "--pos");
      specs.push_back({"camera", pos, angle.value_or(pos_text.empty() ? level.player_angle : 0.0), eye, fov});
    }
    const std::string& map_path = opened.name;
    std::vector<std::unique_ptr<render::Renderer>> renderers;
    std::vector<Row> rows;
    for (const std::string& name : names) {
      auto r = render::make_renderer(name, ropt);
      if (!r) throw cli::ValidationError("--renderers", "unknown renderer '" + name + "'");
      if (!r->supports(level)) {
        if (asked) std::fprintf(stderr, "pseudo3d-compare: %s: the %s renderer cannot draw this level (it needs %s); left out\n",
                                opened.name.c_str(), name.c_str(), std::string(r->needs()).c_str());
        continue;
      }
      r->prepare(level);
      renderers.push_back(std::move(r));
      rows.push_back({name, {}, {}, {}, {}, 0});
    }
    const size_t ref = rows.size() - 1;

    for (size_t c = 0; c < specs.size(); ++c) {
      cli::warn_if_outside("pseudo3d-compare", level, specs[c]);
      const render::Camera camera = render::camera_at(level, specs[c].pos, specs[c].angle, specs[c].eye, specs[c].fov);
      std::vector<render::Frame> frames_out(rows.size(), render::Frame(w, h));
      std::vector<render::Probe> probes(rows.size());
      for (size_t i = 0; i < rows.size(); ++i) {
        probes[i].want_columns = probes[i].want_writes = true;
        Result res;
        res.stats = renderers[i]->render(level, state, camera, frames_out[i], &probes[i]);
        render::Frame scratch(w, h);
        res.ms = time_frames(*renderers[i], level, state, camera, scratch, frames);
        rows[i].results.push_back(res);
      }
      for (size_t i = 0; i < rows.size(); ++i) {
        Result& res = rows[i].results.back();
        res.pixel_diff = image::compare(frames_out[i], frames_out[ref]).fraction(frames_out[i]);
        res.column_diff = column_difference(probes[i].columns, probes[ref].columns);
        if (c == 0) {
          const int max_writes = *std::max_element(probes[i].writes.begin(), probes[i].writes.end());
          rows[i].frame = frames_out[i];
          rows[i].diff = image::difference_heat_map(frames_out[i], frames_out[ref]);
          rows[i].overdraw = image::count_heat_map(w, h, probes[i].writes, std::max(4, max_writes));
          rows[i].overdraw_max = max_writes;
        }
      }
    }
    Outputs outputs;  // the picture and the JSON, all or nothing
    outputs.add(output, image::encode_png(compose(rows, w, h)));

    // The table: medians over the cameras.
    std::printf("%s, %dx%d, %zu camera%s\n", map_path.c_str(), w, h, specs.size(), specs.size() == 1 ? "" : "s");
    std::printf("%-13s %10s %12s %9s %8s %8s %6s %10s %9s %9s %9s\n", "renderer", "ms/frame", "pixels", "overdraw",
                "nodes", "culled", "rays", "mean steps", "max steps", "px diff", "col diff");
    std::string j = "{\"level\": " + json_string(map_path) + ", \"width\": " + std::to_string(w) +
                    ", \"height\": " + std::to_string(h) + ", \"cameras\": " + std::to_string(specs.size()) +
                    ", \"renderers\": [\n";
    for (size_t i = 0; i < rows.size(); ++i) {
      std::map<std::string, std::vector<double>> m;
      for (const Result& r : rows[i].results) {
        m["ms_per_frame"].push_back(r.ms);
        m["overdraw"].push_back(double(r.stats.pixels_written) / (double(w) * h));
        m["mean_steps"].push_back(r.stats.rays ? double(r.stats.steps) / double(r.stats.rays) : 0);
        m["pixel_diff"].push_back(r.pixel_diff);
        m["column_diff"].push_back(r.column_diff);
        for (const Stat& f : render::stat_fields(r.stats)) m[f.name].push_back(f.value);
      }
      auto md = [&](const std::string& k) { return median(m[k]); };
      std::printf("%-13s %10.3f %12.0f %8.2fx %8.0f %8.0f %6.0f %10.1f %9.0f %8.3f%% %8.3f%%\n", rows[i].name.c_str(),
                  md("ms_per_frame"), md("pixels_written"), md("overdraw"), md("nodes_visited"), md("subtrees_culled"),
                  md("rays"), md("mean_steps"), md("max_steps"), 100 * md("pixel_diff"), 100 * md("column_diff"));
      // Medians over the cameras, by statdump's names; timings apart.
      Stats medians;
      for (const Stat& f : render::stat_fields({})) medians.push_back({f.name, md(f.name)});
      for (const char* k : {"overdraw", "mean_steps", "pixel_diff", "column_diff"}) medians.push_back({k, md(k)});
      j += "  {\"name\": " + json_string(rows[i].name) + ", \"median\": " + stats_json(medians) +
           ", \"time\": " + stats_json({{"ms_per_frame", std::round(md("ms_per_frame") * 1000) / 1000}}) +
           (i + 1 < rows.size() ? "},\n" : "}\n");
    }
    j += "]}\n";
    if (!json.empty()) outputs.add(json, j);
    outputs.commit();
    std::printf("wrote %s\n", output.c_str());
    return 0;
  });
}
