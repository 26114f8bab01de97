#include "game/music_player.h"

#include <fluidsynth.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <string_view>

namespace p3d::game {

namespace {

constexpr size_t kChunk = 1024;             // frames synthesized at a time, at most
constexpr uint64_t kShortestLoopUs = 5000;  // an empty song loops no faster (Chocolate's OPL player's guard)

// FluidSynth prints its messages on the terminal; here they are kept from it, the
// last error saved for the reason a sound font failed to load.
std::mutex log_mutex;
std::string last_fluid_error;

void keep_fluid_message(int level, const char* message, void*) {
  if (level > FLUID_ERR || !message) return;
  const std::lock_guard lock(log_mutex);
  last_fluid_error = message;
}

void quiet_fluidsynth() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int level = FLUID_PANIC; level < LAST_LOG_LEVEL; ++level)
      fluid_set_log_function(level, keep_fluid_message, nullptr);
  });
}

std::string fluid_error() {
  const std::lock_guard lock(log_mutex);
  return last_fluid_error;
}

// A SoundFont 2 file starts "RIFF", its length, "sfbk". Anything else is refused
// before FluidSynth sees it (its other loaders complain on the terminal).
bool is_soundfont(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char head[12] = {};
  return in.read(head, sizeof head) && std::memcmp(head, "RIFF", 4) == 0 && std::memcmp(head + 8, "sfbk", 4) == 0;
}

// The font is read through callbacks of ours, so that a player destroyed while its
// font loads stops the reading between two chunks. FluidSynth is given the path behind
// a prefix its own loaders cannot open: only ours reads it, and a reading stopped is
// not begun again by the next loader.
constexpr std::string_view kFontPrefix = "p3d-soundfont:";
constexpr size_t kFontChunk = size_t(4) << 20;
thread_local const std::atomic<bool>* loading_stopped = nullptr;  // the loading thread's player's

struct FontFile {
  std::FILE* file;
  const std::atomic<bool>* stopped;
};

void* open_font(const char* name) {
  const std::string_view n = name;
  if (n.substr(0, kFontPrefix.size()) != kFontPrefix) return nullptr;
  std::FILE* file = std::fopen(name + kFontPrefix.size(), "rb");
  return file ? new FontFile{file, loading_stopped} : nullptr;
}

int read_font(void* buffer, fluid_long_long_t count, void* handle) {
  auto* f = static_cast<FontFile*>(handle);
  auto* out = static_cast<char*>(buffer);
  while (count > 0) {
    if (f->stopped && f->stopped->load(std::memory_order_relaxed)) return FLUID_FAILED;
    const size_t n = size_t(std::min<fluid_long_long_t>(count, fluid_long_long_t(kFontChunk)));
    if (std::fread(out, 1, n, f->file) != n) return FLUID_FAILED;
    out += n;
    count -= fluid_long_long_t(n);
  }
  return FLUID_OK;
}

int seek_font(void* handle, fluid_long_long_t offset, int origin) {
  return fseeko(static_cast<FontFile*>(handle)->file, off_t(offset), origin) == 0 ? FLUID_OK : FLUID_FAILED;
}

fluid_long_long_t tell_font(void* handle) { return fluid_long_long_t(ftello(static_cast<FontFile*>(handle)->file)); }

int close_font(void* handle) {
  auto* f = static_cast<FontFile*>(handle);
  std::fclose(f->file);
  delete f;
  return FLUID_OK;
}

bool is_file(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);  // follows links (default-GM.sf2)
}

}  // namespace

std::optional<std::filesystem::path> find_soundfont(const std::string& given, std::string& why) {
  if (!given.empty()) {
    if (is_file(given)) return std::filesystem::path(given);
    why = "no sound font " + given;
    return std::nullopt;
  }
  if (const char* list = std::getenv("SDL_SOUNDFONTS")) {
    std::string paths = list;
    for (size_t start = 0; start <= paths.size();) {
      const size_t end = std::min(paths.find_first_of(":;", start), paths.size());
      const std::string path = paths.substr(start, end - start);
      if (!path.empty() && is_file(path)) return std::filesystem::path(path);
      start = end + 1;
    }
  }
  for (const char* path : {"/usr/share/sounds/sf2/default-GM.sf2", "/usr/share/sounds/sf2/FluidR3_GM.sf2",
                           "/usr/share/soundfonts/default.sf2", "/usr/share/soundfonts/FluidR3_GM.sf2"})
    if (is_file(path)) return std::filesystem::path(path);
  why = "no sound font found (install fluid-soundfont-gm, or give --soundfont FILE.sf2 or SDL_SOUNDFONTS)";
  return std::nullopt;
}

struct MusicPlayer::Synth {
  fluid_settings_t* settings = nullptr;
  fluid_synth_t* synth = nullptr;
  ~Synth() {
    if (synth) delete_fluid_synth(synth);
    if (settings) delete_fluid_settings(settings);
  }
};

MusicPlayer::MusicPlayer(const MusicOptions& options) : rate_(options.rate), left_(kChunk), right_(kChunk) {
  quiet_fluidsynth();
  if (options.soundfont.empty()) {
    problem_ = "no sound font";
    state_.store(kFailed, std::memory_order_release);
  } else if (options.wait_for_soundfont) {
    load(options);
  } else {
    loader_ = std::thread([this, options] { load(options); });
  }
}

MusicPlayer::~MusicPlayer() {
  stop_loading_.store(true, std::memory_order_relaxed);  // a font still loading stops within a chunk
  if (loader_.joinable()) loader_.join();
}

// The synthesizer as Chocolate's FluidSynth music module sets it up (i_flmusic.c's
// defaults: GS bank select, 256 voices, its chorus and reverb), at full gain: the
// volume is applied as the samples are added.
void MusicPlayer::load(const MusicOptions& options) {
  auto s = std::make_unique<Synth>();
  s->settings = new_fluid_settings();
  if (s->settings) {
    fluid_settings_setnum(s->settings, "synth.sample-rate", double(options.rate));
    fluid_settings_setstr(s->settings, "synth.midi-bank-select", "gs");
    fluid_settings_setint(s->settings, "synth.polyphony", 256);
    fluid_settings_setnum(s->settings, "synth.gain", 1.0);
    fluid_settings_setint(s->settings, "synth.chorus.active", 1);
    fluid_settings_setnum(s->settings, "synth.chorus.level", 0.35);
    fluid_settings_setnum(s->settings, "synth.chorus.depth", 5.0);
    fluid_settings_setint(s->settings, "synth.chorus.nr", 3);
    fluid_settings_setnum(s->settings, "synth.chorus.speed", 0.3);
    fluid_settings_setint(s->settings, "synth.reverb.active", 1);
    fluid_settings_setnum(s->settings, "synth.reverb.room-size", 0.6);
    fluid_settings_setnum(s->settings, "synth.reverb.damp", 0.4);
    fluid_settings_setnum(s->settings, "synth.reverb.width", 4.0);
    fluid_settings_setnum(s->settings, "synth.reverb.level", 0.15);
    fluid_settings_setint(s->settings, "synth.dynamic-sample-loading", options.samples_on_demand ? 1 : 0);
    s->synth = new_fluid_synth(s->settings);
  }
  if (!s->synth) {
    problem_ = "FluidSynth did not start: " + fluid_error();
    state_.store(kFailed, std::memory_order_release);
    return;
  }
  if (!is_soundfont(options.soundfont)) {
    problem_ = options.soundfont.string() + ": not loaded: not a SoundFont 2 file (RIFF sfbk)";
    state_.store(kFailed, std::memory_order_release);
    return;
  }
  fluid_sfloader_t* loader = new_fluid_defsfloader(s->settings);  // the synthesizer's from now on
  fluid_sfloader_set_callbacks(loader, open_font, read_font, seek_font, tell_font, close_font);
  fluid_synth_add_sfloader(s->synth, loader);
  loading_stopped = &stop_loading_;
  const int font = fluid_synth_sfload(s->synth, (std::string(kFontPrefix) + options.soundfont.string()).c_str(), 1);
  loading_stopped = nullptr;
  if (font == FLUID_FAILED) {
    problem_ = options.soundfont.string() + ": not loaded: " +
               (stop_loading_.load(std::memory_order_relaxed) ? std::string("the player went first") : fluid_error());
    state_.store(kFailed, std::memory_order_release);
    return;
  }
  synth_ = std::move(s);
  state_.store(kReady, std::memory_order_release);
}

void MusicPlayer::play(wad::MidiSong song, bool looping) {
  song_ = std::move(song);
  has_song_ = true;
  looping_ = looping;
  paused_ = false;
  restart_ = true;
}

void MusicPlayer::stop() {
  has_song_ = false;
  paused_ = false;
  restart_ = true;
}

void MusicPlayer::pause() { paused_ = has_song_; }
void MusicPlayer::resume() { paused_ = false; }
void MusicPlayer::set_volume(int volume) { volume_ = std::clamp(volume, 0, kMaxVolume); }

uint64_t MusicPlayer::sample_of(uint64_t time_us) const { return time_us * uint64_t(rate_) / 1000000; }

// A song started or stopped since the last mix: the synthesizer silenced and reset,
// its programs too, as Chocolate's module does between songs.
void MusicPlayer::start_if_asked() {
  if (!restart_) return;
  restart_ = false;
  fluid_synth_program_reset(synth_->synth);
  fluid_synth_system_reset(synth_->synth);
  next_ = 0;
  position_ = 0;
  song_over_ = false;
}

// Where the song ends: its last track's end (a looping song no sooner than 5 ms in).
uint64_t MusicPlayer::end_sample() const {
  return sample_of(looping_ ? std::max(song_.length_us, kShortestLoopUs) : song_.length_us);
}

// The messages due by now; at the song's end, the synthesizer reset (FluidSynth's
// player resets it between songs) and the song started again or done with.
void MusicPlayer::send_due_messages() {
  fluid_synth_t* s = synth_->synth;
  const std::vector<wad::MidiMessage>& messages = song_.messages;
  for (;;) {
    for (; next_ < messages.size() && sample_of(messages[next_].time_us) <= position_; ++next_) {
      const wad::MidiMessage& m = messages[next_];
      const int channel = m.status & 0x0F;
      switch (m.status >> 4) {
        case 0x8: fluid_synth_noteoff(s, channel, m.a); break;
        case 0x9: fluid_synth_noteon(s, channel, m.a, m.b); break;  // velocity 0: a note off
        case 0xA: fluid_synth_key_pressure(s, channel, m.a, m.b); break;
        case 0xB: fluid_synth_cc(s, channel, m.a, m.b); break;
        case 0xC: fluid_synth_program_change(s, channel, m.a); break;
        case 0xD: fluid_synth_channel_pressure(s, channel, m.a); break;
        case 0xE: fluid_synth_pitch_bend(s, channel, m.b << 7 | m.a); break;
        default: break;
      }
    }
    if (next_ < messages.size() || position_ < end_sample()) return;
    fluid_synth_system_reset(s);
    if (!looping_) {
      song_over_ = true;
      return;
    }
    next_ = 0;
    position_ = 0;
  }
}

void MusicPlayer::mix(std::span<int16_t> stereo) {
  if (!ready()) return;
  start_if_asked();
  const size_t frames = stereo.size() / 2;
  for (size_t done = 0; done < frames;) {
    // Nothing sounds once a song is over or stopped: the synthesizer was reset.
    if (paused_ || !has_song_ || song_over_) return;
    send_due_messages();
    if (song_over_) return;
    // Up to the next message, or the song's end.
    const uint64_t until = next_ < song_.messages.size() ? sample_of(song_.messages[next_].time_us) : end_sample();
    const size_t chunk = size_t(std::min<uint64_t>(std::min(frames - done, kChunk), until - position_));
    render(stereo.subspan(2 * done), chunk);
    done += chunk;
    position_ += chunk;
  }
}

void MusicPlayer::render(std::span<int16_t> stereo, size_t frames) {
  fluid_synth_write_float(synth_->synth, int(frames), left_.data(), 0, 1, right_.data(), 0, 1);
  rendered_ += frames;
  if (volume_ > 0) {
    // Chocolate's gain: volume * 8 of 127, on FluidSynth's floating-point samples.
    const float gain = float(volume_ * 8) / 127.0f * 32768.0f;
    const auto add = [gain](int16_t& out, float sample) {
      const int music = int(std::lrint(std::clamp(sample * gain, -65536.0f, 65536.0f)));
      out = int16_t(std::clamp(out + music, -32768, 32767));
    };
    for (size_t i = 0; i < frames; ++i) {
      add(stereo[2 * i], left_[i]);
      add(stereo[2 * i + 1], right_[i]);
    }
  }
}

}  // namespace p3d::game
