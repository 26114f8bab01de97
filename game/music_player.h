// Doom's music through FluidSynth: a song (engine/wad/midi.h) played into interleaved
// stereo at the audio device's rate, added to the sound effects in the same buffer,
// with Chocolate Doom's FluidSynth settings (i_flmusic.c) and Doom's music volume.
// No SDL here: the window's audio callback calls mix() after SoundMixer::mix, and
// every other call is made with the device locked, as for the SoundMixer. The sound
// font loads on a thread of its own; until it has, music is silent and waits.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "engine/wad/midi.h"

namespace p3d::game {

// The sound font to play with: `given` (an option) when not empty, else the first
// file of $SDL_SOUNDFONTS (SDL_mixer's list, ':' or ';' between paths), else where
// Debian's fluid-soundfont-gm puts it (/usr/share/sounds/sf2/default-GM.sf2, the
// alternatives link, or FluidR3_GM.sf2, or under /usr/share/soundfonts/). nullopt,
// with the reason in `why`, when there is none.
std::optional<std::filesystem::path> find_soundfont(const std::string& given, std::string& why);

struct MusicOptions {
  int rate = 44100;                 // the audio device's samples a second
  std::filesystem::path soundfont;  // find_soundfont's
  bool wait_for_soundfont = false;  // load it before the constructor returns (tests, tools)
  bool samples_on_demand = false;   // FluidSynth's dynamic sample loading: ready in a fifth of a second
                                    // rather than a second or more, but reads the font's samples from
                                    // disk as songs need them, on the audio thread (tests)
};

class MusicPlayer {
 public:
  static constexpr int kMaxVolume = 15;      // Doom's music volume scale (snd_MusicVolume)
  static constexpr int kDefaultVolume = 8;   // Doom's default.cfg

  explicit MusicPlayer(const MusicOptions& options);
  ~MusicPlayer();  // a sound font still loading stops (within a few milliseconds)
  MusicPlayer(const MusicPlayer&) = delete;
  MusicPlayer& operator=(const MusicPlayer&) = delete;

  // ---- the sound font
  bool ready() const { return state_.load(std::memory_order_acquire) == kReady; }
  bool failed() const { return state_.load(std::memory_order_acquire) == kFailed; }
  // Why there is no music once failed(): the font's path and FluidSynth's complaint.
  std::string problem() const { return failed() ? problem_ : std::string(); }

  // ---- control (the device locked)
  // Starts a song from its beginning in place of any other (S_ChangeMusic); `looping`:
  // again from the start at its end, else once. Until the font has loaded, it waits.
  void play(wad::MidiSong song, bool looping);
  void stop();    // S_StopMusic: silent at once (the synthesizer reset, as Chocolate's is)
  void pause();   // S_PauseSound: the song and its notes hold where they are
  void resume();  // S_ResumeSound
  // Doom's music volume, 0 (silent) .. 15; 8 by default. Chocolate plays at
  // volume * 8 / 127 of FluidSynth's full gain.
  void set_volume(int volume);
  int volume() const { return volume_; }
  bool playing() const { return has_song_ && !song_over_; }  // a song on, paused or not
  bool paused() const { return paused_; }

  // ---- the audio thread
  // Adds the music's next samples to `stereo` (interleaved left, right; the sound
  // effects already there), clamped to 16 bits. Nothing while the font loads.
  void mix(std::span<int16_t> stereo);
  uint64_t samples_rendered() const { return rendered_; }  // frames synthesized, for measurements

 private:
  enum State { kLoading, kReady, kFailed };
  struct Synth;  // FluidSynth's settings and synthesizer

  void load(const MusicOptions& options);
  void start_if_asked();
  void send_due_messages();
  uint64_t sample_of(uint64_t time_us) const;
  uint64_t end_sample() const;
  void render(std::span<int16_t> stereo, size_t frames);

  const int rate_;
  std::unique_ptr<Synth> synth_;  // made by the loading thread; touched by mix() alone once ready
  std::atomic<int> state_{kLoading};
  std::atomic<bool> stop_loading_{false};  // the player is going: the font's reading stops
  std::string problem_;
  std::thread loader_;

  // The song, set under the device's lock, played by mix().
  wad::MidiSong song_;
  bool has_song_ = false, looping_ = false, song_over_ = false, paused_ = false;
  bool restart_ = false, release_ = false;  // asked for since the last mix()
  int volume_ = kDefaultVolume;
  size_t next_ = 0;           // the next message of song_
  uint64_t position_ = 0;     // samples played since the song (or its loop) started
  uint64_t rendered_ = 0;
  std::vector<float> left_, right_;  // FluidSynth's output before the volume, at most kChunk frames
};

}  // namespace p3d::game
