#include "game/key_script.h"

#include <cstdio>
#include <sstream>

#include "engine/front/keys.h"
#include "engine/image/image.h"
#include "engine/play/sound.h"
#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::game {

std::vector<ScriptStep> parse_key_script(const std::string& text, const std::string& where) {
  std::vector<ScriptStep> steps;
  std::istringstream in(text);
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string tic_text, verb;
    if (!(words >> tic_text)) continue;
    const std::string at = where + ":" + std::to_string(line_number) + ": ";
    ScriptStep step;
    step.line = line_number;
    try {
      size_t used = 0;
      const unsigned long long tic = std::stoull(tic_text, &used);
      if (used != tic_text.size() || tic > (1ull << 32)) throw std::invalid_argument("");
      step.tic = tic;
    } catch (const std::exception&) {
      throw Error(at + "'" + tic_text + "' is not a tic number");
    }
    if (!steps.empty() && step.tic < steps.back().tic) throw Error(at + "tic " + tic_text + " comes before the last step's");
    if (!(words >> verb)) throw Error(at + "a tic needs a step: key, hold, release, type, shot or end");
    std::string rest;
    std::getline(words, rest);
    rest.erase(0, rest.find_first_not_of(' '));
    if (verb == "key" || verb == "hold" || verb == "release") {
      const auto key = front::key_from_name(rest);
      if (!key) throw Error(at + "unknown key '" + rest + "'");
      step.kind = verb == "key" ? ScriptStep::Kind::kKey : verb == "hold" ? ScriptStep::Kind::kHold : ScriptStep::Kind::kRelease;
      step.key = *key;
    } else if (verb == "type") {
      step.kind = ScriptStep::Kind::kType;
      step.text = rest;
    } else if (verb == "shot") {
      if (rest.empty() || rest.find('/') != std::string::npos || rest.find("..") != std::string::npos)
        throw Error(at + "a shot needs a plain file name (no directory)");
      step.kind = ScriptStep::Kind::kShot;
      step.text = rest;
    } else if (verb == "end") {
      step.kind = ScriptStep::Kind::kEnd;
    } else {
      throw Error(at + "unknown step '" + verb + "' (key, hold, release, type, shot or end)");
    }
    steps.push_back(std::move(step));
  }
  return steps;
}

ScriptResult run_key_script(FrontEnd& front, const std::vector<ScriptStep>& steps, const std::filesystem::path& out_dir,
                            int width, int height) {
  std::filesystem::create_directories(out_dir);
  ScriptResult result;
  render::Frame frame(width, height);
  play::Track last_music{play::Music::kNone, false};
  size_t next = 0;
  front.draw(frame, 1.0, {});
  for (uint64_t tic = 0;; ++tic) {
    for (; next < steps.size() && steps[next].tic == tic; ++next) {
      const ScriptStep& s = steps[next];
      switch (s.kind) {
        case ScriptStep::Kind::kKey:
          front.key_down(s.key);
          front.key_up(s.key);
          break;
        case ScriptStep::Kind::kHold: front.key_down(s.key); break;
        case ScriptStep::Kind::kRelease: front.key_up(s.key); break;
        case ScriptStep::Kind::kType:
          for (char c : s.text) {
            const int key = c == ' ' ? int(front::kKeySpace) : std::tolower(static_cast<unsigned char>(c));
            front.key_down(key);
            front.key_up(key);
          }
          break;
        case ScriptStep::Kind::kShot:
          front.draw(frame, 1.0, {});  // with what the keys of this tic changed
          image::save_png(frame, out_dir / s.text);
          ++result.shots;
          break;
        case ScriptStep::Kind::kEnd: break;
      }
      if (s.kind == ScriptStep::Kind::kEnd) {
        result.tics = tic;
        write_file_atomically(out_dir / "log.txt", result.log);
        return result;
      }
    }
    if (next == steps.size() || front.quit_requested()) {
      result.tics = tic;
      break;
    }
    front.tic();
    front.draw(frame, 1.0, {});  // a frame a tic, as the window draws: Doom's melt starts from the last
    for (const Session::PlacedSound& s : front.take_sounds())
      result.log += std::to_string(tic + 1) + " sound " + play::sound_lump_name(s.sound).substr(2) + "\n";
    if (front.music() != last_music) {  // as a player hears it: a change of track (S_ChangeMusic)
      last_music = front.music();
      result.log += std::to_string(tic + 1) + " music " +
                    (last_music.music == play::Music::kNone ? "-" : play::music_lump_name(last_music.music)) +
                    (last_music.looping ? " loop" : " once") + "\n";
    }
  }
  write_file_atomically(out_dir / "log.txt", result.log);
  return result;
}

}  // namespace p3d::game
