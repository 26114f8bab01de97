// The command-line tools end to end: the bad-input corpus (tests/bad/*.map, each
// opening with "# expect: MESSAGE"), damaged compiled levels, bad arguments,
// and byte-for-byte reproducible outputs.
#include <gtest/gtest.h>

#include <cmath>

#include <sys/stat.h>

#include <chrono>

#include <fstream>

#include "engine/image/image.h"
#include "engine/level/io.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d {
namespace {

// Our programs' names: every installed program wears the project's prefix.
std::string program_name(const std::string& name) { return "pseudo3d-" + name; }
std::string tool(const std::string& name) { return (test::tools_dir() / program_name(name)).string(); }

// Runs a command in the source directory (so paths in messages are relative).
int run_in_source(const std::string& command, std::string& output) {
  return test::run("cd '" + test::source_dir().string() + "' && " + command, output);
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

class Tools : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("tools"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string out(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(Tools, BadMapsGiveTheirMessageAndNoOutput) {
  int cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "tests/bad")) {
    if (entry.path().extension() != ".map" && entry.path().extension() != ".grid") continue;
    const std::string text = read_file_text(entry.path());
    ASSERT_EQ(text.rfind("# expect: ", 0), 0u) << entry.path() << " must open with '# expect: MESSAGE'";
    const std::string expected = first_line(text).substr(10);
    std::string output;
    const int status =
        run_in_source(tool("mapc") + " tests/bad/" + entry.path().filename().string() + " -o " + out("x.bsp"), output);
    EXPECT_EQ(status, 1) << entry.path();
    EXPECT_EQ(first_line(output), "pseudo3d-mapc: " + expected) << entry.path() << ": the program's name, then the file's message";
    EXPECT_FALSE(std::filesystem::exists(out("x.bsp"))) << entry.path() << " left a partial output";
    ++cases;
  }
  EXPECT_GE(cases, 10);
  for (const auto& entry : std::filesystem::directory_iterator(dir_))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << "temporary file left: " << entry.path();
}

// Every message opens with the program's name; "did you mean" comes only for an
// option that does not exist, and only with a near miss (subcommands' options too).
TEST_F(Tools, UsageMessagesNameTheProgramAndSuggestOnlyNearMisses) {
  std::string o;
  EXPECT_EQ(run_in_source(tool("mapgen") + " soup --walls 10 --seed 1 --bogus -o " + out("x.map"), o), 2);
  EXPECT_EQ(first_line(o), "pseudo3d-mapgen: The following argument was not expected: --bogus") << o;
  EXPECT_EQ(o.find("did you mean"), std::string::npos) << o;
  EXPECT_EQ(run_in_source(tool("mapgen") + " soup --wals 10 -o " + out("x.map"), o), 2);
  EXPECT_NE(o.find("pseudo3d-mapgen: --wals: did you mean --walls?"), std::string::npos) << o;
  EXPECT_EQ(o.find("-o: did you mean"), std::string::npos) << o;
  for (const char* program : {"mapc", "capture", "compare"}) {
    EXPECT_EQ(run_in_source(tool(program) + " missing.bsp -o " + out("x.png"), o), 2) << program;
    EXPECT_EQ(o.rfind(program_name(program) + ": ", 0), 0u) << o;
  }
  EXPECT_EQ(run_in_source(tool("capture") + " maps/outpost.map -o /proc/none/x.png", o), 1);
  EXPECT_EQ(o.rfind("pseudo3d-capture: ", 0), 0u) << o;
  EXPECT_FALSE(std::filesystem::exists(out("x.map")) || std::filesystem::exists(out("x.png")));
}

// The bundled camera lists and paths stand every camera inside the map: none warns.
TEST_F(Tools, BundledCamerasStandInsideTheirMap) {
  for (const char* cameras : {"maps/outpost.cameras", "maps/outpost.path"}) {
    std::string o;
    ASSERT_EQ(run_in_source(tool("capture") + " maps/outpost.map --cameras " + cameras + " --size 16x10 -o " +
                                out("views"), o), 0) << o;
    EXPECT_EQ(o.find("warning"), std::string::npos) << cameras << ": " << o;
  }
}

TEST_F(Tools, CompileAndCaptureAreReproducible) {
  std::string o;
  ASSERT_EQ(run_in_source(tool("mapc") + " maps/outpost.map -o " + out("a.bsp") + " --stats --check --json " +
                              out("a.json"), o), 0) << o;
  EXPECT_NE(o.find("maps/outpost.map: the BSP invariants hold"), std::string::npos) << o;
  EXPECT_NE(o.find("stats: walls="), std::string::npos) << o;
  EXPECT_NE(o.find(" fragments_per_bound="), std::string::npos) << o;
  EXPECT_NE(o.find("\ntime: parse_seconds="), std::string::npos) << o;
  EXPECT_NE(read_file_text(out("a.json")).find("{\"stats\": {\"walls\": "), std::string::npos);
  ASSERT_EQ(run_in_source(tool("mapc") + " maps/outpost.map -o " + out("b.bsp"), o), 0) << o;
  EXPECT_EQ(read_file_bytes(out("a.bsp")), read_file_bytes(out("b.bsp")));

  const std::string capture = tool("capture") + " " + out("a.bsp") + " --pos 64,96 --angle 30 --size 200x120 ";
  ASSERT_EQ(test::run(capture + "-o " + out("a.png") + " --columns " + out("a.csv") + " --stats --json " + out("a.json"), o),
            0) << o;
  EXPECT_NE(o.find("frame stats: nodes_visited="), std::string::npos) << o;
  EXPECT_NE(o.find(" early_exit=1 "), std::string::npos) << o;
  EXPECT_NE(o.find("\nframe time: ms_per_frame="), std::string::npos) << o;
  const std::string json = read_file_text(out("a.json"));
  EXPECT_NE(json.find("\"stats\": {\"nodes_visited\": "), std::string::npos) << json;
  EXPECT_NE(json.find("\"early_exit\": 1"), std::string::npos) << json;
  ASSERT_EQ(test::run(capture + "-o " + out("b.png"), o), 0) << o;
  EXPECT_EQ(read_file_bytes(out("a.png")), read_file_bytes(out("b.png")));
  const image::Image img = image::load_png(out("a.png"));
  EXPECT_EQ(img.width, 200);
  EXPECT_EQ(img.height, 120);
  const std::string csv = read_file_text(out("a.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 201);
  EXPECT_EQ(first_line(csv), "x,wall,dist");

  // The reference renderer draws the same picture.
  ASSERT_EQ(test::run(capture + "--renderer reference -o " + out("r.png"), o), 0) << o;
  EXPECT_EQ(read_file_bytes(out("a.png")), read_file_bytes(out("r.png")));

  // Every PNG level writes the same picture: level 0 the most bytes, 12 the fewest.
  for (const char* level : {"0", "12"}) {
    ASSERT_EQ(test::run(capture + "--png-level " + level + " -o " + out(std::string("l") + level + ".png"), o), 0) << o;
    EXPECT_EQ(image::load_png(out(std::string("l") + level + ".png")).pixels, img.pixels) << "level " << level;
  }
  EXPECT_GT(std::filesystem::file_size(out("l0.png")), std::filesystem::file_size(out("a.png")));
  EXPECT_LT(std::filesystem::file_size(out("l12.png")), std::filesystem::file_size(out("a.png")));

  // Many cameras in one run.
  write_file_atomically(out("cams"), "one 64 96 30\ntwo 300 192 0 41 70\n");
  std::filesystem::create_directories(out("shots"));
  ASSERT_EQ(test::run(tool("capture") + " " + out("a.bsp") + " --cameras " + out("cams") + " --size 64x40 -o " +
                          out("shots") + " --columns " + out("shots"),
                      o),
            0)
      << o;
  EXPECT_TRUE(std::filesystem::exists(out("shots/one.png")));
  EXPECT_TRUE(std::filesystem::exists(out("shots/two.csv")));
  // PNGs encoded on other threads: the same files for any thread count.
  for (const char* threads : {"1", "3"})
    ASSERT_EQ(test::run(tool("capture") + " " + out("a.bsp") + " --cameras " + out("cams") + " --size 64x40 --threads " +
                            threads + " -o " + out(std::string("t") + threads),
                        o), 0) << o;
  for (const char* name : {"one.png", "two.png"}) {
    EXPECT_EQ(read_file_bytes(out(std::string("t1/") + name)), read_file_bytes(out(std::string("t3/") + name))) << name;
    EXPECT_EQ(read_file_bytes(out(std::string("t1/") + name)), read_file_bytes(out(std::string("shots/") + name))) << name;
  }
}

TEST_F(Tools, DamagedLevelsAreRejected) {
  std::string o;
  ASSERT_EQ(run_in_source(tool("mapc") + " maps/outpost.map -o " + out("good.bsp"), o), 0) << o;
  const std::vector<uint8_t> good = read_file_bytes(out("good.bsp"));
  struct Case {
    std::string name;
    std::vector<uint8_t> bytes;
    std::string message;
  };
  std::vector<uint8_t> flipped = good, version = good;
  flipped[good.size() / 2] ^= 1;
  version[8] = 9;  // the format before leaves held fragments
  const std::vector<Case> cases = {
      {"truncated.bsp", std::vector<uint8_t>(good.begin(), good.begin() + good.size() - 100), "truncated or padded file"},
      {"corrupted.bsp", flipped, "checksum mismatch (the file is corrupted)"},
      {"version.bsp", version, "compiled level version 9 is not supported"},
      {"text.bsp", std::vector<uint8_t>{'h', 'e', 'l', 'l', 'o'}, "not a compiled level"},
      {"empty.bsp", {}, "not a compiled level"},
  };
  for (const Case& c : cases) {
    write_file_atomically(out(c.name), c.bytes);
    const int status = test::run(tool("capture") + " " + out(c.name) + " --pos 0,0 -o " + out("x.png"), o);
    EXPECT_EQ(status, 1) << c.name;
    EXPECT_NE(o.find(out(c.name) + ": " + c.message), std::string::npos) << c.name << ": " << o;
    EXPECT_FALSE(std::filesystem::exists(out("x.png"))) << c.name;
  }
}

// Without --pos, a camera stands at the level's player start, facing its way.
TEST_F(Tools, CameraDefaultsToThePlayerStart) {
  std::string o;
  ASSERT_EQ(run_in_source(tool("mapc") + " maps/outpost.map -o " + out("a.bsp"), o), 0) << o;
  const std::string cap = tool("capture") + " " + out("a.bsp") + " --size 160x100 ";
  ASSERT_EQ(test::run(cap + "-o " + out("default.png"), o), 0) << o;
  ASSERT_EQ(test::run(cap + "--pos 64,96 --angle 30 -o " + out("explicit.png"), o), 0) << o;  // maps/outpost.map's start
  EXPECT_EQ(read_file_bytes(out("default.png")), read_file_bytes(out("explicit.png")));
}

TEST_F(Tools, BadArgumentsAreRefused) {
  std::string o;
  ASSERT_EQ(run_in_source(tool("mapc") + " maps/outpost.map -o " + out("a.bsp"), o), 0) << o;
  const std::string cap = tool("capture") + " " + out("a.bsp") + " ";
  struct Case {
    std::string args, message;
  };
  write_file_atomically(out("bad.cams"), "one 1 2\n");
  const std::vector<Case> cases = {
      {"--pos 1 -o " + out("x.png"), "expected X,Y"},
      {"--pos 1,nan -o " + out("x.png"), "expected X,Y with finite numbers"},
      {"--pos 1,1 --size 0x10 -o " + out("x.png"), "expected WxH"},
      {"--pos 1,1 --size 100 -o " + out("x.png"), "expected WxH"},
      {"--pos 1,1 --fov 200 -o " + out("x.png"), "--fov"},
      {"--pos 1,1 --renderer magic -o " + out("x.png"), "unknown renderer 'magic'"},
      {"--cameras " + out("bad.cams") + " -o " + dir_.string(), "bad.cams:1: expected NAME X Y ANGLE"},
      {"--pos 1,1 --angle inf -o " + out("x.png"), "finite"},
      {"--pos 1e15,0 -o " + out("x.png"), "X,Y must lie within"},
      {"--pos 1,1 --eye 1e300 -o " + out("x.png"), "--eye"},
      {"--pos 1,1 --png-level 13 -o " + out("x.png"), "--png-level"},
  };
  for (const Case& c : cases) {
    const int status = test::run(cap + c.args, o);
    EXPECT_NE(status, 0) << c.args;
    EXPECT_NE(o.find(c.message), std::string::npos) << c.args << ": " << o;
    EXPECT_FALSE(std::filesystem::exists(out("x.png"))) << c.args;
  }
  EXPECT_NE(test::run(tool("mapc") + " /nonexistent.map -o " + out("y.bsp"), o), 0);
  EXPECT_NE(test::run(tool("mapc") + " " + out("a.bsp") + " -o " + out("y.bsp"), o), 0);  // binary, not a map
  EXPECT_FALSE(std::filesystem::exists(out("y.bsp")));
  EXPECT_NE(test::run(tool("mapc") + " --strategy best " + out("a.bsp") + " -o " + out("y.bsp"), o), 0);
  EXPECT_NE(test::run(tool("mapgen") + " maze -o " + out("m.map"), o), 0);
}

// The example in maps/FORMAT.md must stay a valid map.
TEST_F(Tools, FormatExampleCompiles) {
  const std::string doc = read_file_text(test::source_dir() / "maps/FORMAT.md");
  const size_t start = doc.find("```\ntitle Two rooms");
  ASSERT_NE(start, std::string::npos);
  const size_t end = doc.find("```", start + 4);
  write_file_atomically(out("example.map"), doc.substr(start + 4, end - start - 4));
  std::filesystem::create_directory_symlink(test::source_dir() / "maps/textures", dir_ / "textures");
  std::string o;
  ASSERT_EQ(test::run(tool("mapc") + " " + out("example.map") + " -o " + out("example.bsp") + " --check", o), 0) << o;
  ASSERT_EQ(test::run(tool("capture") + " " + out("example.bsp") + " --pos 32,32 --angle 45 --size 64x40 -o " +
                          out("example.png"),
                      o),
            0)
      << o;
}

// compare on the bundled maps: its picture exists and decodes, its JSON lists every renderer.
TEST_F(Tools, CompareDrawsEveryRendererOnTheBundledMaps) {
  struct Case {
    const char* map;
    const char* pos;
    size_t renderers;
  };
  for (const Case& c : {Case{"maps/outpost.map", "64,96", 5}, Case{"maps/bunker.grid", "352,720", 6},
                        Case{"maps/soup.map", "0,0", 5}, Case{"maps/labyrinth.grid", "8416,7104", 6}}) {
    std::string o;
    ASSERT_EQ(run_in_source(tool("compare") + " " + c.map + " --pos " + c.pos + " --size 96x60 --frames 1 -o " +
                                out("c.png") + " --json " + out("c.json") +
                                (std::string(c.map).find("labyrinth") != std::string::npos ? " --renderers bsp,dda,sphere" : ""),
                            o),
              0)
        << c.map << ": " << o;
    const image::Image img = image::load_png(out("c.png"));
    EXPECT_GE(img.width, 96 * 2) << c.map;
    const std::string json = read_file_text(out("c.json"));
    const size_t expected = std::string(c.map).find("labyrinth") != std::string::npos ? 4 : c.renderers;
    size_t names = 0;
    for (size_t at = 0; (at = json.find("\"name\"", at)) != std::string::npos; ++at) ++names;
    EXPECT_EQ(names, expected) << c.map << "\n" << json;
    EXPECT_NE(json.find("\"pixel_diff\": 0,"), std::string::npos) << c.map << json;
    EXPECT_NE(json.find("\"pixels_written\": 5760,"), std::string::npos) << c.map << ": whole numbers as integers\n" << json;
  }
  // Over a path, with medians.
  std::string o;
  ASSERT_EQ(run_in_source(tool("compare") + " maps/outpost.map --renderers bsp,dda --size 32x20 --frames 1 -o " +
                              out("d.png"), o), 0) << o;
  EXPECT_NE(o.find("pseudo3d-compare: maps/outpost.map: the dda renderer cannot draw this level (it needs a .grid tile map); left out"),
            std::string::npos) << o;
  ASSERT_EQ(run_in_source(tool("compare") + " maps/outpost.map --path maps/outpost.cameras --size 64x40 --frames 1 "
                          "--renderers bsp,painter -o " + out("p.png"), o), 0) << o;
  EXPECT_NE(o.find("7 cameras"), std::string::npos) << o;
}

TEST_F(Tools, MapcDrawsTheBspAsSvg) {
  std::string o;
  ASSERT_EQ(run_in_source(tool("mapc") + " maps/outpost.map -o " + out("o.bsp") + " --svg " + out("o.svg") +
                              " --pos 64,96 --angle 30",
                          o),
            0)
      << o;
  const std::string svg = read_file_text(out("o.svg"));
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  for (const char* group : {"leaves", "splitters", "walls", "split-points", "columns", "draw-order", "view-cone"})
    EXPECT_NE(svg.find(std::string("id=\"") + group + "\""), std::string::npos) << group;
  const level::Level level = level::read(out("o.bsp"));
  EXPECT_EQ(size_t(std::count_if(svg.begin(), svg.end(), [](char ch) { return ch == '\n'; })) > level.leaves.size(), true);
}

#ifdef P3D_GAME
// The game under SDL's dummy video driver (no display, no GPU): it plays the
// bundled demo through to the end and exits 0; headless replays are byte-identical;
// bad demos are refused.
TEST_F(Tools, GamePlaysTheBundledDemoWithoutADisplay) {
  std::string o;
  const std::string game = std::string("SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy ") + P3D_GAME;
  ASSERT_EQ(run_in_source(game + " maps/outpost.map --play maps/outpost.demo --timedemo --window 320x200", o), 0) << o;
  EXPECT_NE(o.find("624 tics, 625"), std::string::npos) << o << " (one frame per tic, plus the first)";
  ASSERT_EQ(run_in_source(game + " maps/bunker.grid --renderer dda --resolution 160x100 --quit-after-tics 35 --no-vsync", o), 0)
      << o;
}

// Doom's music as the window plays it, through SDL's disk audio driver: MAP01's track
// sounds, at the music volume asked for (Chocolate's gain: volume x 8 / 127), and not
// at all at volume 0 (MAP01's start is otherwise quiet). Five seconds each: the sound
// font loads meanwhile; the last two are measured.
TEST_F(Tools, TheGamesMusicSoundsAtItsVolume) {
#ifdef P3D_SANITIZE
  GTEST_SKIP() << "the Release build plays it (FluidSynth under the sanitizers is slow to start)";
#endif
  auto rms_of_last_seconds = [&](int volume) {
    const std::string raw = out("music" + std::to_string(volume) + ".raw");
    std::string o;
    const std::string game = "SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE=" + raw + " " + P3D_GAME;
    EXPECT_EQ(run_in_source(game + " --iwad " + test::freedoom_path("freedoom2.wad").string() +
                                " --warp 1 --window 320x200 --music-volume " + std::to_string(volume) +
                                " --quit-after-tics 175",
                            o),
              0)
        << o;
    const std::vector<uint8_t> bytes = read_file_bytes(raw);
    constexpr size_t kLast = 2 * 44100 * 2;  // two seconds of stereo samples
    const size_t samples = bytes.size() / 2;
    EXPECT_GT(samples, kLast) << "the device played five seconds";
    double sum = 0;
    for (size_t i = samples > kLast ? samples - kLast : 0; i < samples; ++i) {
      const double v = int16_t(bytes[2 * i] | bytes[2 * i + 1] << 8);
      sum += v * v;
    }
    return std::sqrt(sum / double(std::min(samples, kLast)));
  };
  const double loud = rms_of_last_seconds(15), half = rms_of_last_seconds(8), off = rms_of_last_seconds(0);
  EXPECT_GT(loud, 500) << "D_RUNNIN plays";
  EXPECT_LT(half, loud * 0.8) << "volume 8 is 64/120 of 15's gain";
  EXPECT_GT(half, loud * 0.25);
  EXPECT_LT(off, 5) << "volume 0 is silent";
}

// Without a display the game says so and exits 1 at once, rather than running unseen.
TEST_F(Tools, GameWithoutADisplayFailsAtOnce) {
  std::string o;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run_in_source("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " + std::string(P3D_GAME) +
                              " maps/outpost.map", o), 1) << o;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  EXPECT_NE(o.find("pseudo3d: no display to open a window on (DISPLAY and WAYLAND_DISPLAY are unset); to render "
                   "without a display: game LEVEL --headless --play DEMO"), std::string::npos) << o;
}

TEST_F(Tools, HeadlessReplayWritesTheSameFramesEveryTime) {
  std::string o;
  for (const char* run : {"a", "b"})
    ASSERT_EQ(run_in_source(std::string(P3D_GAME) + " maps/outpost.map --play maps/outpost.demo --headless "
                            "--capture-every 150 --resolution 160x100 --out " + out(run), o), 0) << o;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out("a"))) {
    EXPECT_EQ(read_file_bytes(entry.path()), read_file_bytes(out("b") + "/" + entry.path().filename().string()));
    ++files;
  }
  EXPECT_EQ(files, 6 + 1) << "frames at tics 0, 150, 300, 450, 600, the last (624) and stats.csv";
  EXPECT_NE(o.find("replayed 624 of 624 tics (exit: none)"), std::string::npos) << o;

  std::vector<uint8_t> demo = read_file_bytes(test::source_dir() / "maps/outpost.demo");
  demo[demo.size() / 2] ^= 1;
  write_file_atomically(out("bad.demo"), demo);
  EXPECT_EQ(run_in_source(std::string(P3D_GAME) + " maps/outpost.map --play " + out("bad.demo") + " --headless --out " +
                              out("c"), o), 1);
  EXPECT_NE(o.find("checksum mismatch"), std::string::npos) << o;
  EXPECT_EQ(run_in_source(std::string(P3D_GAME) + " maps/soup.map --play maps/outpost.demo --headless --out " + out("c"), o), 1);
  EXPECT_NE(o.find("recorded on a different level"), std::string::npos) << o;
  EXPECT_EQ(run_in_source(std::string(P3D_GAME) + " maps/outpost.map --headless", o), 2);
  EXPECT_FALSE(std::filesystem::exists(out("c")));
}

// Doom's own demos: a WAD's DEMOn lump picks its map and skill and plays headless.
TEST_F(Tools, HeadlessPlaysAWadsDemoLump) {
  const std::string game = std::string(P3D_GAME) + " --iwad " + test::freedoom_path("freedoom2.wad").string();
  std::string o;
  ASSERT_EQ(run_in_source(game + " --play demo1 --headless --size 160x100 --capture-every 700 --out " + out("d"), o), 0)
      << o;
  EXPECT_NE(o.find("replayed 1415 of 1415 tics"), std::string::npos) << o;
  EXPECT_TRUE(std::filesystem::exists(out("d") + "/frame00002.png"));
  EXPECT_EQ(run_in_source(game + " --play demo9 --headless --out " + out("e"), o), 2);
  EXPECT_NE(o.find("demo9: no such file, and the WADs have no lump DEMO9"), std::string::npos) << o;
  EXPECT_EQ(run_in_source(std::string(P3D_GAME) + " maps/outpost.map --play demo1 --headless --out " + out("e"), o), 2);
  EXPECT_NE(o.find("demo1: no such file"), std::string::npos) << o;
  EXPECT_EQ(run_in_source(game + " --play demo1 --dump-things " + out("things.txt"), o), 2);
  EXPECT_NE(o.find("--dump-things need --headless --play"), std::string::npos) << o;
  EXPECT_FALSE(std::filesystem::exists(out("e")));
  EXPECT_FALSE(std::filesystem::exists(out("things.txt")));
}
#endif

// WAD maps end to end: Doom's command-line habits, determinism, LINEDEF numbers in
// --columns, a summary of every map, and clear errors for broken WADs and usage.
TEST_F(Tools, WadMapsCompileCaptureAndFailCleanly) {
  const std::string iwad = test::freedoom_path("freedoom2.wad").string();
  std::string o;
  ASSERT_EQ(test::run(tool("mapc") + " --iwad " + iwad + " --map map02 -o " + out("a.bsp") + " --check", o), 0) << o;
  ASSERT_EQ(test::run(tool("mapc") + " --iwad " + iwad + " --map MAP02 -o " + out("b.bsp"), o), 0) << o;
  EXPECT_EQ(read_file_bytes(out("a.bsp")), read_file_bytes(out("b.bsp")));

  // The compiled level needs nothing else; --columns names LINEDEFs, and the reference agrees.
  const std::string cap = tool("capture") + " " + out("a.bsp") + " --size 120x80 ";
  ASSERT_EQ(test::run(cap + "-o " + out("a.png") + " --columns " + out("a.csv"), o), 0) << o;
  ASSERT_EQ(test::run(cap + "--renderer reference -o " + out("r.png") + " --columns " + out("r.csv"), o), 0) << o;
  EXPECT_EQ(read_file_bytes(out("a.png")), read_file_bytes(out("r.png")));
  EXPECT_EQ(read_file_text(out("a.csv")), read_file_text(out("r.csv")));
  const level::Level level = level::read(out("a.bsp"));
  int max_linedef = -1;
  for (const level::Wall& w : level.walls) max_linedef = std::max(max_linedef, w.source);
  const std::string csv = read_file_text(out("a.csv"));
  int columns = 0;
  for (size_t at = csv.find('\n') + 1; at < csv.size(); at = csv.find('\n', at) + 1, ++columns) {
    const int wall = std::stoi(csv.substr(csv.find(',', at) + 1));
    EXPECT_GE(wall, 0);
    EXPECT_LE(wall, max_linedef);
  }
  EXPECT_EQ(columns, 120);

  // capture straight from the WAD, from the player start.
  ASSERT_EQ(test::run(tool("capture") + " --iwad " + iwad + " --map MAP02 --size 120x80 -o " + out("w.png"), o), 0) << o;
  EXPECT_EQ(read_file_bytes(out("w.png")), read_file_bytes(out("a.png")));

  // A WAD level's frames stay 8-bit: a paletted PNG (IHDR's colour type 3), the same
  // picture as the renderer's colours.
  const std::vector<uint8_t> png = read_file_bytes(out("a.png"));
  ASSERT_GT(png.size(), 25u);
  EXPECT_EQ(png[25], 3);
  render::Frame frame(120, 80);
  render::make_renderer("bsp")->render(level, render::camera_at(level, level.player_start, level.player_angle), frame);
  EXPECT_EQ(image::load_png(out("a.png")).pixels, frame.pixels);

  // A broken WAD: a clear message, exit 1, nothing written.
  std::vector<uint8_t> broken = read_file_bytes(iwad);
  broken.resize(broken.size() / 2);
  write_file_atomically(out("broken.wad"), broken);
  EXPECT_EQ(test::run(tool("mapc") + " --iwad " + out("broken.wad") + " --map MAP01 -o " + out("x.bsp"), o), 1);
  EXPECT_NE(o.find("broken.wad: the directory of"), std::string::npos) << o;
  EXPECT_EQ(test::run(tool("mapc") + " --iwad " + iwad + " --map MAP99 -o " + out("x.bsp"), o), 1);
  EXPECT_NE(o.find("freedoom2.wad: no map MAP99 (maps: MAP01"), std::string::npos) << o;
  EXPECT_FALSE(std::filesystem::exists(out("x.bsp")));
  // Usage.
  EXPECT_EQ(test::run(tool("mapc") + " --file " + iwad + " -o " + out("x.bsp"), o), 2);
  EXPECT_NE(o.find("PWADs need the IWAD they build on: add --iwad"), std::string::npos) << o;
  EXPECT_EQ(run_in_source(tool("mapc") + " maps/outpost.map --map MAP01 -o " + out("x.bsp"), o), 2);
  EXPECT_NE(o.find("--map: names a map in WADs: use it with --iwad"), std::string::npos) << o;
  EXPECT_FALSE(std::filesystem::exists(out("x.bsp")));
}

TEST_F(Tools, MapcCompilesEveryMapOfAWad) {
  const std::string iwad = test::freedoom_path("freedoom1.wad").string();
  std::string o;
  ASSERT_EQ(test::run(tool("mapc") + " --iwad " + iwad + " --all --check -o " + out("maps"), o), 0) << o;
  EXPECT_NE(o.find("36 maps compiled into"), std::string::npos) << o;
  EXPECT_NE(o.find("E1M1   Outer Prison"), std::string::npos) << o;
  EXPECT_TRUE(std::filesystem::exists(out("maps/E4M9.bsp")));
  // The art the maps share is made once: each map is still what it is compiled alone.
  for (const char* map : {"E1M1", "E2M5", "E4M9"}) {
    ASSERT_EQ(test::run(tool("mapc") + " --iwad " + iwad + " --map " + map + " -o " + out(map) + ".bsp", o), 0) << o;
    EXPECT_EQ(read_file_bytes(out(map) + ".bsp"), read_file_bytes(out("maps/") + map + ".bsp")) << map;
  }
}

#ifdef P3D_GAME
TEST_F(Tools, GameWarpsToAWadMap) {
  std::string o;
  const std::string game = std::string("SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy ") + P3D_GAME;
  ASSERT_EQ(test::run(game + " --iwad " + test::freedoom_path("freedoom1.wad").string() +
                          " --warp 2 --resolution 160x100 --quit-after-tics 10 --no-vsync", o), 0) << o;
  EXPECT_EQ(run_in_source(game + " maps/outpost.map --warp 2", o), 2);
  EXPECT_NE(o.find("--warp: picks a map in WADs: use it with --iwad"), std::string::npos) << o;
}

// The bundled demo walks freedoom2's MAP01 through its doors to the exit switch:
// replayed headless twice, it reports the exit and writes the same files.
TEST_F(Tools, BundledFreedoomDemoReachesTheExit) {
  const std::string iwad = test::freedoom_path("freedoom2.wad").string();
  std::string o;
  for (const char* run : {"a", "b"}) {
    ASSERT_EQ(run_in_source(std::string(P3D_GAME) + " --iwad " + iwad + " --map MAP01 --play maps/freedoom2_map01.demo " +
                                "--headless --capture-every 100 --resolution 160x100 --json --out " + out(run), o), 0) << o;
    EXPECT_NE(o.find("(exit: normal)"), std::string::npos) << o;
  }
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out("a"))) {
    EXPECT_EQ(read_file_bytes(entry.path()), read_file_bytes(out("b") + "/" + entry.path().filename().string()));
    ++files;
  }
  EXPECT_GT(files, 5);
  const std::string csv = read_file_text(out("a") + "/stats.csv");
  EXPECT_NE(csv.rfind(",normal\n"), std::string::npos) << "the last row reports the exit";
  const std::string json = read_file_text(out("a") + "/stats.json");
  EXPECT_NE(json.find("\"stats\": {\"nodes_visited\": "), std::string::npos) << json;
  EXPECT_NE(json.rfind("\"exit\": \"normal\"}"), std::string::npos) << json;
  // The route records the same demo again, byte for byte.
  ASSERT_EQ(run_in_source(std::string(P3D_GAME) + " --iwad " + iwad + " --map MAP01 --headless --autopilot " +
                              "maps/freedoom2_map01.route --record " + out("again.demo"), o), 0) << o;
  EXPECT_EQ(read_file_bytes(out("again.demo")), read_file_bytes(test::source_dir() / "maps/freedoom2_map01.demo"));
}
#endif

// Tools behave alike, as programs people know: typos get a "did you mean", files are
// recognised by content, outputs default under out/ with their folders created, a
// camera in the void is warned about, and formats follow the names asked for.
TEST_F(Tools, BehaveLikeProgramsPeopleKnow) {
  std::string o;
  const std::string outpost = (test::source_dir() / "maps/outpost.map").string();
  EXPECT_EQ(test::run(tool("capture") + " " + outpost + " --sise 10x10", o), 2);
  EXPECT_NE(o.find("pseudo3d-capture: --sise: did you mean --size?"), std::string::npos) << o;
  EXPECT_EQ(run_in_source(tool("mapc") + " maps/textures/brick.png -o " + out("x.bsp"), o), 1);
  EXPECT_NE(o.find("maps/textures/brick.png: a PNG image, not a level"), std::string::npos) << o;
  ASSERT_EQ(run_in_source(tool("mapc") + " maps/outpost.map -o " + out("o.bsp"), o), 0) << o;
  std::filesystem::copy_file(out("o.bsp"), out("o.map"));  // a compiled level with the wrong name
  EXPECT_EQ(test::run(tool("mapc") + " " + out("o.map") + " -o " + out("y.bsp"), o), 1);
  EXPECT_NE(o.find("a compiled level (.bsp) already"), std::string::npos) << o;
  ASSERT_EQ(test::run(tool("capture") + " " + out("o.map") + " --size 32x20 -o " + out("o.png"), o), 0) << o
      << "read by its content";
  EXPECT_EQ(test::run(tool("capture") + " " + outpost + " -o " + out("x.jpg"), o), 2);
  EXPECT_NE(o.find("--output: writes .png files: name it"), std::string::npos) << o;
  EXPECT_EQ(test::run(tool("mapgen") + " maze -o " + out("m.map"), o), 2);
  EXPECT_NE(o.find("maze writes a .grid tile map: name it"), std::string::npos) << o;

  // Defaults under out/ of the working directory, folders created; data found from anywhere.
  ASSERT_EQ(test::run("cd " + dir_.string() + " && " + tool("mapc") + " " + outpost, o), 0) << o;
  EXPECT_TRUE(std::filesystem::exists(out("out/outpost.bsp"))) << o;
  ASSERT_EQ(test::run("cd " + dir_.string() + " && " + tool("capture") + " out/outpost.bsp --size 32x20", o), 0) << o;
  EXPECT_TRUE(std::filesystem::exists(out("out/outpost.png"))) << o;
  ASSERT_EQ(test::run(tool("capture") + " " + outpost + " --cameras " + test::source_dir().string() +
                          "/tests/golden/outpost.cameras --size 32x20 -o " + out("new/dir"), o), 0) << o;
  EXPECT_TRUE(std::filesystem::exists(out("new/dir/start.png")));
  ASSERT_EQ(test::run("cd " + dir_.string() + " && " + tool("mapgen") + " rooms --walls 100 -o r.map && " + tool("mapc") +
                          " r.map -o r.bsp",
                      o), 0) << o << "mapgen finds the bundled textures from any directory";

  ASSERT_EQ(test::run(tool("capture") + " " + outpost + " --pos 9000,9000 --size 32x20 -o " + out("void.png"), o), 0) << o;
  EXPECT_NE(o.find("pseudo3d-capture: warning: camera at (9000, 9000) is outside every sector"), std::string::npos) << o;
}

TEST_F(Tools, BenchWritesItsTablesAsJson) {
#ifdef P3D_SANITIZE
  GTEST_SKIP() << "the Release build runs the benchmark's sections (the sanitizers check the code they run elsewhere)";
#endif
  std::string o;
  ASSERT_EQ(test::run(tool("bench") + " grids --size 32x20 --repeat 1 --budget 0.01 --json " + out("b.json"), o), 0) << o;
  const std::string json = read_file_text(out("b.json"));
  EXPECT_EQ(json.rfind("{\"sections\": [", 0), 0u) << json;
  EXPECT_NE(json.find("\"title\": \"Grid ray casting"), std::string::npos) << json;
  EXPECT_NE(json.find("\"dda_ms_frame\": "), std::string::npos) << json;
}

TEST_F(Tools, BenchDrawsItsScalingTableAsCharts) {
  std::string o;
  ASSERT_EQ(test::run(tool("bench") + " scaling --sizes 100,300 --renderers bsp,reference --size 32x20 --repeat 1 "
                          "--budget 0.01 --plots " + out("plots"), o), 0) << o;
  for (const char* kind : {"rooms", "soup"}) {
    const std::string svg = read_file_text(out(std::string("plots/scaling-") + kind + ".svg"));
    EXPECT_NE(svg.find(std::string("ms/frame against map size: ") + kind), std::string::npos) << svg;
    size_t lines = 0;
    for (size_t at = 0; (at = svg.find("<polyline", at)) != std::string::npos; ++at) ++lines;
    EXPECT_EQ(lines, 2u) << "a line per renderer";
    EXPECT_NE(svg.find(">reference<"), std::string::npos) << svg;
  }
  EXPECT_FALSE(std::filesystem::exists(out("plots/threads.svg"))) << "only the tables this run printed";
}

// Every program that opens a .map takes --textures-anywhere to let its pictures leave
// the map's directory (tests/bad/outside_texture.map is refused without it).
TEST_F(Tools, TexturesAnywhereIsAnExplicitChoice) {
  std::string o;
  for (const std::string program : {"mapc", "capture"})
    EXPECT_EQ(run_in_source(tool(program) + " tests/bad/outside_texture.map --textures-anywhere -o " + out("t." +
                                (program == "mapc" ? std::string("bsp") : std::string("png"))), o), 0) << program << o;
  EXPECT_EQ(run_in_source(tool("capture") + " tests/bad/outside_texture.map -o " + out("u.png"), o), 1) << o;
  EXPECT_NE(o.find("lies outside the map's directory"), std::string::npos) << o;
}

// NaN compares false with every bound, so CLI11's ranges let it through: ours refuse it.
TEST_F(Tools, NotANumberIsRefusedEverywhere) {
  std::string o;
  const std::string outpost = (test::source_dir() / "maps/outpost.map").string();
  for (const std::string option : {"--fov nan", "--relaxation nan", "--epsilon inf", "--eye nan", "--angle nan", "--fov -inf"}) {
    EXPECT_EQ(test::run(tool("capture") + " " + outpost + " " + option + " -o " + out("n.png"), o), 2) << option << o;
    EXPECT_NE(o.find(option.substr(0, option.find(' ')) + ": must be a finite number"), std::string::npos) << option << o;
    EXPECT_EQ(test::run(tool("compare") + " " + outpost + " " + option + " -o " + out("n.png"), o), 2) << option << o;
  }
  EXPECT_EQ(test::run(tool("mapc") + " " + outpost + " --svg " + out("a.svg") + " --angle nan -o " + out("a.bsp"), o), 2) << o;
  EXPECT_EQ(test::run(tool("mapc") + " " + outpost + " --split-weight nan -o " + out("a.bsp"), o), 2) << o;
  EXPECT_EQ(test::run(tool("bench") + " render --budget nan", o), 2) << o;
#ifdef P3D_GAME
  EXPECT_EQ(test::run(std::string(P3D_GAME) + " " + outpost + " --fov nan", o), 2) << o;
  EXPECT_EQ(test::run(std::string(P3D_GAME) + " " + outpost + " --sensitivity inf", o), 2) << o;
#endif
  EXPECT_FALSE(std::filesystem::exists(out("n.png")));
  EXPECT_FALSE(std::filesystem::exists(out("a.bsp")));
}

// A command's outputs are all written or none: a later one failing leaves nothing of
// the earlier ones; a device, FIFO or symlink is never replaced by a regular file.
TEST_F(Tools, OutputsAreAllOrNothingAndNeverReplaceDevices) {
  std::string o;
  const std::string outpost = (test::source_dir() / "maps/outpost.map").string();
  std::filesystem::create_directory(out("taken.svg"));  // the SVG cannot be written there
  EXPECT_EQ(test::run(tool("mapc") + " " + outpost + " -o " + out("a.bsp") + " --svg " + out("taken.svg"), o), 1) << o;
  EXPECT_NE(o.find("taken.svg: not a regular file (a directory); refusing to replace it"), std::string::npos) << o;
  EXPECT_FALSE(std::filesystem::exists(out("a.bsp"))) << "the .bsp came first but was not kept";
  std::filesystem::create_directory(out("taken.json"));
  EXPECT_EQ(test::run(tool("capture") + " " + outpost + " --size 16x10 --stats -o " + out("a.png") + " --json " +
                          out("taken.json"), o), 1) << o;
  EXPECT_FALSE(std::filesystem::exists(out("a.png")));
  std::filesystem::create_symlink("/dev/null", out("link.png"));
  EXPECT_EQ(test::run(tool("capture") + " " + outpost + " --size 16x10 -o " + out("link.png"), o), 1) << o;
  EXPECT_NE(o.find("link.png: not a regular file (a symbolic link); refusing to replace it"), std::string::npos) << o;
  EXPECT_TRUE(std::filesystem::is_symlink(out("link.png")));
  for (const auto& entry : std::filesystem::directory_iterator(dir_))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << "temporary file left: " << entry.path();
  // Reading: only regular files.
  EXPECT_EQ(test::run(tool("mapc") + " /dev/zero -o " + out("z.bsp"), o), 1) << o;
  EXPECT_NE(o.find("/dev/zero: not a regular file"), std::string::npos) << o;
  ASSERT_EQ(::mkfifo(out("fifo.map").c_str(), 0600), 0);
  EXPECT_EQ(test::run("timeout 10 " + tool("mapc") + " " + out("fifo.map") + " -o " + out("f.bsp"), o), 1) << o
      << "a FIFO is refused, not read for ever";
  EXPECT_EQ(test::run("timeout 10 " + tool("capture") + " " + outpost + " --cameras " + out("fifo.map"), o), 1) << o;
  EXPECT_NE(o.find("fifo.map: not a regular file"), std::string::npos) << o;
}

TEST_F(Tools, GeneratedMapsCompile) {
  std::string o;
  ASSERT_EQ(run_in_source(tool("mapgen") + " rooms --walls 500 --seed 3 -o " + out("r.map"), o), 0) << o;
  ASSERT_EQ(run_in_source(tool("mapc") + " " + out("r.map") + " -o " + out("r.bsp") + " --check", o), 0) << o;
  for (const char* kind : {"maze", "caves", "arena"}) {
    ASSERT_EQ(run_in_source(tool("mapgen") + " " + kind + " --grid 40x30 -o " + out("g.grid"), o), 0) << o;
    ASSERT_EQ(run_in_source(tool("mapc") + " " + out("g.grid") + " -o " + out("g.bsp") + " --check", o), 0) << kind << o;
    ASSERT_EQ(test::run(tool("capture") + " " + out("g.bsp") + " --cameras " + test::source_dir().string() +
                            "/tests/golden/outpost.cameras --renderer dda --size 32x20 -o " + dir_.string(),
                        o),
              0)
        << o;
  }
  ASSERT_EQ(run_in_source(tool("mapgen") + " soup --walls 500 -o " + out("s.map"), o), 0) << o;
  for (const char* strategy : {"first", "random", "freesplit", "greedy"})
    ASSERT_EQ(run_in_source(tool("mapc") + " " + out("s.map") + " -o " + out("s.bsp") + " --check --strategy " + strategy, o),
              0)
        << strategy << ": " << o;
}

}  // namespace
}  // namespace p3d
