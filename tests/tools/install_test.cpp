// The installed project: `cmake --install` into a scratch prefix and the Debian
// package. Every installed path wears the project's name (nothing another package
// may own), the programs run from any directory, the documents' links resolve where
// they are installed, the desktop entry's command opens Doom's title screen on
// Freedoom, and lintian finds no error in the package. The Release build's programs
// only: the sanitizer build installs nothing.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d {
namespace {

const std::filesystem::path& build_dir() {
  static const std::filesystem::path build = test::tools_dir().parent_path();
  return build;
}

std::string first_line_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

class Install : public ::testing::Test {
 protected:
  // One install for the suite: `cmake --install` into a scratch prefix.
  static void SetUpTestSuite() {
#ifndef P3D_SANITIZE
    dir_ = test::temp_dir("install");
    prefix_ = dir_ / "prefix";
    std::string o;
    installed_ = test::run("cmake --install '" + build_dir().string() + "' --prefix '" + prefix_.string() + "'", o) == 0;
    install_log_ = o;
#endif
  }
  static void TearDownTestSuite() {
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }
  void SetUp() override {
#ifdef P3D_SANITIZE
    GTEST_SKIP() << "the Release build installs its programs (installing sanitized ones helps no one)";
#endif
    ASSERT_TRUE(installed_) << install_log_;
  }
  static std::string in_prefix(const std::string& path) { return (prefix_ / path).string(); }
  static std::filesystem::path dir_, prefix_;
  static bool installed_;
  static std::string install_log_;
};
std::filesystem::path Install::dir_, Install::prefix_;
bool Install::installed_ = false;
std::string Install::install_log_;

// No file or link another package may own: each installed path is the project's own
// directory or a file named after it, in the places Debian's packages share.
TEST_F(Install, EveryInstalledPathWearsTheProjectsName) {
  const std::regex ours(
      "bin/pseudo3d-[a-z]+|games/pseudo3d|share/(pseudo3d|doc/pseudo3d)(/.*)?|"
      "share/man/man1/pseudo3d-[a-z]+\\.1\\.gz|share/man/man6/pseudo3d\\.6\\.gz|"
      "share/applications/org\\.pseudo3d\\.Pseudo3D\\.desktop|share/metainfo/org\\.pseudo3d\\.Pseudo3D\\.metainfo\\.xml|"
      "share/icons/hicolor/scalable/apps/pseudo3d\\.svg");
  size_t files = 0;
  for (auto it = std::filesystem::recursive_directory_iterator(prefix_); it != std::filesystem::end(it); ++it) {
    if (it->is_directory() && !it->is_symlink()) continue;
    const std::string path = std::filesystem::relative(it->path(), prefix_).string();
    EXPECT_TRUE(std::regex_match(path, ours)) << path << ": not under the project's name";
    ++files;
  }
  EXPECT_GT(files, 50u);
  for (const char* program : {"bin/pseudo3d-mapc", "bin/pseudo3d-capture", "bin/pseudo3d-compare", "bin/pseudo3d-mapgen",
                              "bin/pseudo3d-texgen", "bin/pseudo3d-bench", "share/man/man1/pseudo3d-mapc.1.gz",
                              "share/doc/pseudo3d/copyright", "share/doc/pseudo3d/changelog.gz"})
    EXPECT_TRUE(std::filesystem::exists(in_prefix(program))) << program;
#ifdef P3D_GAME
  EXPECT_TRUE(std::filesystem::exists(in_prefix("games/pseudo3d")));
  EXPECT_TRUE(std::filesystem::exists(in_prefix("share/man/man6/pseudo3d.6.gz")));
#endif
}

// The installed programs run from any directory and find the bundled maps and
// textures in P/share/pseudo3d.
TEST_F(Install, ToolsRunFromAnyDirectory) {
  const std::string bin = in_prefix("bin/"), share = in_prefix("share/pseudo3d/maps/");
  const std::string here = "cd '" + dir_.string() + "' && ";
  std::string o;
  ASSERT_EQ(test::run(here + bin + "pseudo3d-mapc " + share + "outpost.map -o outpost.bsp", o), 0) << o;
  ASSERT_EQ(test::run(here + bin + "pseudo3d-capture outpost.bsp --size 80x50 -o outpost.png", o), 0) << o;
  ASSERT_EQ(test::run(here + bin + "pseudo3d-mapgen rooms --walls 120 --seed 3 -o rooms.map", o), 0) << o;
  ASSERT_EQ(test::run(here + bin + "pseudo3d-mapc rooms.map -o rooms.bsp", o), 0) << o << ": the generated map's textures come from share/";
#ifdef P3D_GAME
  ASSERT_EQ(test::run(here + in_prefix("games/pseudo3d") + " " + share + "outpost.map --play " + share +
                          "outpost.demo --headless --size 80x50 --capture-every 330 --out frames", o), 0) << o;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "frames/stats.csv"));
#endif
}

// Every program says the project's version (VERSION), as the changelog's newest entry
// and the AppStream metadata's newest release do.
TEST_F(Install, ProgramsChangelogAndMetadataSayOneVersion) {
  const std::string version = first_line_of(test::source_dir() / "VERSION");
  ASSERT_TRUE(std::regex_match(version, std::regex("[0-9]+\\.[0-9]+(\\.[0-9]+)?"))) << version;
  std::string o;
  for (const char* program : {"pseudo3d-mapc", "pseudo3d-capture", "pseudo3d-compare", "pseudo3d-mapgen",
                              "pseudo3d-texgen", "pseudo3d-bench"}) {
    ASSERT_EQ(test::run(in_prefix("bin/") + program + " --version", o), 0) << o;
    EXPECT_EQ(o, std::string(program) + " " + version + "\n");
  }
  EXPECT_EQ(first_line_of(test::source_dir() / "packaging/changelog"), "pseudo3d (" + version + ") unstable; urgency=medium");
  const std::string metainfo = read_file_text(test::source_dir() / "packaging/org.pseudo3d.Pseudo3D.metainfo.xml");
  EXPECT_NE(metainfo.find("<release version=\"" + version + "\""), std::string::npos);
}

// The README and the documents keep their layout where they are installed: each link
// to a document or a picture resolves there (links into the source code excepted).
TEST_F(Install, InstalledDocumentsLinksResolve) {
  const std::filesystem::path docs = in_prefix("share/doc/pseudo3d");
  const std::regex link("\\]\\(([^)#:]+)(#[^)]*)?\\)");
  size_t checked = 0;
  for (auto it = std::filesystem::recursive_directory_iterator(docs); it != std::filesystem::end(it); ++it) {
    if (it->path().extension() != ".md") continue;
    const std::string text = read_file_text(it->path());
    for (std::sregex_iterator m(text.begin(), text.end(), link), end; m != end; ++m) {
      const std::filesystem::path target = (*m)[1].str();
      const std::string ext = target.extension().string();
      if (ext == ".cpp" || ext == ".h" || ext == ".sh" || ext == ".c" || ext == ".py") continue;
      EXPECT_TRUE(std::filesystem::exists(it->path().parent_path() / target))
          << std::filesystem::relative(it->path(), docs) << " links " << target;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20u);
}

#ifdef P3D_GAME
// The desktop entry's command, with no option, on a machine with Freedoom where Debian
// puts it: Doom's title screen opens on the IWAD it finds (SDL's dummy video driver; an
// interrupt closes the game as a window's close button would).
TEST_F(Install, TheDesktopEntryOpensDoomsTitleScreen) {
  const std::string entry = read_file_text(in_prefix("share/applications/org.pseudo3d.Pseudo3D.desktop"));
  std::smatch exec;
  ASSERT_TRUE(std::regex_search(entry, exec, std::regex("\nExec=([^\n]*)\n"))) << entry;
  EXPECT_TRUE(entry.find("\nIcon=pseudo3d\n") != std::string::npos) << entry;
  std::string o;
  if (test::run("ls /usr/share/games/doom/freedoom2.wad /usr/share/games/doom/freedoom1.wad", o) != 0)
    GTEST_SKIP() << "Freedoom is not installed";
  const std::filesystem::path home = dir_ / "home";
  std::filesystem::create_directories(home);
  const std::string env = "env -u DOOMWADDIR -u DOOMWADPATH HOME='" + home.string() + "' XDG_CONFIG_HOME='" +
                          (home / "config").string() + "' XDG_DATA_HOME='" + (home / "data").string() +
                          "' SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy PATH='" + in_prefix("games") + ":" +
                          std::getenv("PATH") + "' ";
  EXPECT_EQ(test::run(env + "timeout --preserve-status -s INT 3 " + exec[1].str(), o), 0) << o;
  EXPECT_TRUE(std::regex_search(o, std::regex("pseudo3d: /usr/share/games/doom/freedoom[12]\\.wad: Doom's title screen")))
      << o;
  EXPECT_NE(read_file_text(home / "config/pseudo3d/settings.cfg").find("last_wad = /usr/share/games/doom/freedoom"),
            std::string::npos) << "the WAD it found is remembered";
}
#endif

// cpack -G DEB: a Debian package of the programs, their manual pages and the bundled
// maps, its dependencies found from the libraries the programs link; lintian (when
// installed) reports no error.
TEST_F(Install, DebianPackageHoldsTheProgramsAndLintianFindsNoError) {
  std::string o;
  if (test::run("command -v dpkg-deb && command -v dpkg-shlibdeps", o) != 0) GTEST_SKIP() << "not a Debian machine";
  const std::filesystem::path deb_dir = dir_ / "deb";
  ASSERT_EQ(test::run("cd '" + dir_.string() + "' && cpack -G DEB --config '" + (build_dir() / "CPackConfig.cmake").string() +
                          "' -B '" + deb_dir.string() + "'", o), 0) << o;
  std::string deb;
  for (const auto& entry : std::filesystem::directory_iterator(deb_dir))
    if (entry.path().extension() == ".deb") deb = entry.path().string();
  ASSERT_FALSE(deb.empty()) << o;
  ASSERT_EQ(test::run("dpkg-deb -I '" + deb + "'", o), 0) << o;
  EXPECT_NE(o.find("Package: pseudo3d"), std::string::npos) << o;
  EXPECT_NE(o.find("Version: " + first_line_of(test::source_dir() / "VERSION")), std::string::npos) << o;
  EXPECT_NE(o.find("libdeflate0"), std::string::npos) << o;
  EXPECT_NE(o.find("Recommends: freedoom"), std::string::npos) << o;
#ifdef P3D_GAME
  EXPECT_NE(o.find("libsdl2"), std::string::npos) << o;
#endif
  ASSERT_EQ(test::run("dpkg-deb -c '" + deb + "'", o), 0) << o;
  for (const char* file : {"./usr/bin/pseudo3d-mapc", "./usr/bin/pseudo3d-capture", "./usr/share/man/man1/pseudo3d-mapc.1.gz",
                           "./usr/share/pseudo3d/maps/outpost.map", "./usr/share/pseudo3d/maps/textures/brick.png"})
    EXPECT_NE(o.find(file), std::string::npos) << file;
  ASSERT_EQ(test::run("dpkg-deb -x '" + deb + "' '" + (dir_ / "unpacked").string() + "' && file '" +
                          (dir_ / "unpacked/usr/bin/pseudo3d-mapc").string() + "'", o), 0) << o;
  EXPECT_NE(o.find(", stripped"), std::string::npos) << o;
  if (test::run("command -v lintian", o) != 0) GTEST_SKIP() << "lintian is not installed";
  test::run("lintian --tag-display-limit 0 '" + deb + "' 2>&1", o);
  EXPECT_EQ(std::regex_search(o, std::regex("(^|\n)E: ")), false) << o;
}

}  // namespace
}  // namespace p3d
