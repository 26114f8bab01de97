#include "game/sdl_platform.h"

#include <SDL.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "engine/front/gamma.h"
#include "engine/front/keys.h"
#include "engine/image/image.h"
#include "engine/util/file.h"
#include "game/music_player.h"
#include "game/sound_mixer.h"

namespace p3d::game {

namespace {

constexpr double kTicSeconds = 1.0 / kTicRate;

double now_seconds() { return double(SDL_GetPerformanceCounter()) / double(SDL_GetPerformanceFrequency()); }

// SDL's key as Doom's key code (front/keys.h); 0 for keys Doom does not know.
int doom_key(SDL_Keycode k) {
  using namespace front;
  switch (k) {
    case SDLK_RETURN: case SDLK_KP_ENTER: return kKeyEnter;
    case SDLK_ESCAPE: return kKeyEscape;
    case SDLK_BACKSPACE: return kKeyBackspace;
    case SDLK_TAB: return kKeyTab;
    case SDLK_UP: return kKeyUp;
    case SDLK_DOWN: return kKeyDown;
    case SDLK_LEFT: return kKeyLeft;
    case SDLK_RIGHT: return kKeyRight;
    case SDLK_LCTRL: case SDLK_RCTRL: return kKeyRCtrl;
    case SDLK_LSHIFT: case SDLK_RSHIFT: return kKeyRShift;
    case SDLK_LALT: case SDLK_RALT: return kKeyRAlt;
    case SDLK_PAUSE: return kKeyPause;
    case SDLK_PRINTSCREEN: return kKeyPrintScreen;
    case SDLK_CAPSLOCK: return kKeyCapsLock;
    case SDLK_NUMLOCKCLEAR: return kKeyNumLock;
    case SDLK_SCROLLLOCK: return kKeyScrollLock;
    case SDLK_HOME: return kKeyHome;
    case SDLK_END: return kKeyEnd;
    case SDLK_PAGEUP: return kKeyPageUp;
    case SDLK_PAGEDOWN: return kKeyPageDown;
    case SDLK_INSERT: return kKeyInsert;
    case SDLK_DELETE: return kKeyDelete;
    case SDLK_KP_PLUS: case SDLK_PLUS: return kKeyEquals;
    case SDLK_KP_MINUS: return kKeyMinus;
    case SDLK_F11: return kKeyF11;
    case SDLK_F12: return kKeyF12;
    default: break;
  }
  if (k >= SDLK_F1 && k <= SDLK_F10) return kKeyF1 + int(k - SDLK_F1);
  if (k > 0 && k < 0x7f) return int(k);  // printable keys are their (lower-case) ASCII, as Doom's
  return 0;
}

// The next free out/screenshots/screenshotNNNN.png.
std::filesystem::path screenshot_path() {
  const std::filesystem::path dir = "out/screenshots";
  std::filesystem::create_directories(dir);
  for (int n = 0;; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "screenshot%04d.png", n);
    if (!std::filesystem::exists(dir / name)) return dir / name;
  }
}

// Without a display SDL falls back to an invisible offscreen driver and the game
// would run unseen for ever: refuse instead, unless a driver was asked for by name
// (SDL_VIDEODRIVER=dummy runs the game in tests).
const char* why_no_display() {
  if (std::getenv("SDL_VIDEODRIVER")) return nullptr;
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) return "DISPLAY and WAYLAND_DISPLAY are unset";
  return nullptr;
}

bool offscreen_driver() {
  const char* driver = SDL_GetCurrentVideoDriver();
  return !std::getenv("SDL_VIDEODRIVER") && driver &&
         (std::string_view(driver) == "offscreen" || std::string_view(driver) == "dummy");
}

constexpr const char* kHeadlessHint =
    "to render without a display: game LEVEL --headless --play DEMO --out DIR (or --autopilot ROUTE, --script KEYS)";

class Window {
 public:
  Window(FrontEnd& front, Settings& settings, const WindowOptions& options)
      : front_(front), settings_(settings), o_(options) {}
  ~Window() {
    if (audio_) SDL_CloseAudioDevice(audio_);  // stops the callback before the mixer goes
    if (texture_) SDL_DestroyTexture(texture_);
    if (renderer_) SDL_DestroyRenderer(renderer_);
    if (window_) SDL_DestroyWindow(window_);
    SDL_Quit();
  }

  int run() {
    if (const char* why = why_no_display()) {
      std::fprintf(stderr, "pseudo3d: no display to open a window on (%s); %s\n", why, kHeadlessHint);
      return 1;
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return fail("cannot start SDL video");
    if (offscreen_driver()) {
      std::fprintf(stderr, "pseudo3d: SDL found no display, only its offscreen driver; %s\n", kHeadlessHint);
      return 1;
    }
    if (o_.sound) open_audio();
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "nearest");  // a fixed low resolution stays crisp
    window_ = SDL_CreateWindow(window_title().c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                               settings_.window_width, settings_.window_height,
                               SDL_WINDOW_RESIZABLE | (settings_.fullscreen ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0));
    if (!window_) return fail("cannot open a window");
    renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED | (o_.vsync ? SDL_RENDERER_PRESENTVSYNC : 0));
    if (!renderer_) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
    if (!renderer_) return fail("cannot create a renderer");
    if (!resize()) return 1;
    if (o_.autopilot) autopilot_.emplace(*o_.autopilot);
    if (Session* s = front_.session()) {
      if (o_.play) {  // the demo's start and keys, as recorded
        if (o_.play->custom_start) s->spawn(o_.play->start, o_.play->angle);
        s->set_keys(o_.play->keys);
      }
      if (!o_.record.empty()) s->start_recording(o_.record.extension() == ".lmp", o_.long_tics);
      if (o_.map_reload) s->watch_files();
    }
    apply_volumes();

    double last = now_seconds(), accumulator = 0;
    const double start = last;
    uint64_t frames = 0;
    while (running_) {
      poll_events();
      follow_mouse();
      const double t0 = now_seconds();
      accumulator = std::min(accumulator + (t0 - last), 0.25);  // after a stall, do not race to catch up
      if (o_.timedemo) accumulator = kTicSeconds;              // exactly one tic per frame
      summed_.frame_ms += (t0 - last) * 1000;
      last = t0;
      if (o_.netplay && front_.in_level()) {  // the lockstep keeps its own clock
        net_tics();
        accumulator = 0;
      }
      while (accumulator >= kTicSeconds && running_) {
        run_tic();
        accumulator -= kTicSeconds;
      }
      after_tics();
      const double t1 = now_seconds();
      if (Session* s = front_.session()) s->reload_if_saved(t1);
      const double alpha = front_.waiting() ? 1.0 : accumulator / kTicSeconds;
      front_.draw(frame_, alpha, times_);
      if (front_.screenshot_requested()) screenshot();
      const double t2 = now_seconds();
      present();
      const double t3 = now_seconds();
      summed_.sim_ms += (t1 - t0) * 1000;
      summed_.render_ms += (t2 - t1) * 1000;
      summed_.present_ms += (t3 - t2) * 1000;
      ++summed_frames_;
      if (t3 - summed_start_ >= 0.5) show_averages(t3);
      ++frames;
    }
    const Session* s = front_.session();
    if (o_.play && s)
      std::printf("%llu tics, %llu frames in %.2f s: %.1f fps\n", (unsigned long long)played_,  // the demo's, every level's
                  (unsigned long long)frames, now_seconds() - start, frames / std::max(1e-9, now_seconds() - start));
    if (!o_.record.empty() && s) {
      write_file_atomically(o_.record, s->encode_recording(o_.record));
      std::printf("recorded %zu tics to %s\n", s->recording().tics.size(), o_.record.c_str());
    }
    keep_window_settings();
    return 0;
  }

 private:
  int fail(const char* what) {
    std::fprintf(stderr, "pseudo3d: %s: %s\n", what, SDL_GetError());
    return 1;
  }

  std::string window_title() const {
    const Session* s = front_.session();
    return s && !front_.has_menus() ? "pseudo3d: " + s->title() : "pseudo3d";
  }

  // ---- sound: the mixer on SDL's audio thread; without a device the game is silent
  void open_audio() {
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
      std::fprintf(stderr, "pseudo3d: no sound (%s)\n", SDL_GetError());
      return;
    }
    SDL_AudioSpec want{}, have{};
    want.freq = 44100;
    want.format = AUDIO_S16SYS;
    want.channels = 2;
    want.samples = 512;
    want.callback = [](void* self, Uint8* bytes, int length) {
      auto* w = static_cast<Window*>(self);
      const std::span<int16_t> stereo(reinterpret_cast<int16_t*>(bytes), size_t(length) / sizeof(int16_t));
      w->mixer_->mix(stereo);
      if (w->music_) w->music_->mix(stereo);  // added to the effects
    };
    want.userdata = this;
    mixer_.emplace(want.freq, [this](play::Sound s) { return front_.sound_clip(s); });
    if (o_.music) open_music(want.freq);
    audio_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (!audio_) {
      std::fprintf(stderr, "pseudo3d: no sound (%s)\n", SDL_GetError());
      return;
    }
    SDL_PauseAudioDevice(audio_, 0);
  }

  void apply_volumes() {
    if (!audio_) return;
    SDL_LockAudioDevice(audio_);
    mixer_->set_volume(settings_.menu.sfx_volume * 8);  // Doom's S_SetSfxVolume
    if (music_) music_->set_volume(settings_.menu.music_volume);
    SDL_UnlockAudioDevice(audio_);
  }

  // ---- music: the player made before the device starts calling it; its sound font
  // loads on a thread of its own meanwhile
  void open_music(int rate) {
    std::string why;
    const std::optional<std::filesystem::path> font = find_soundfont(o_.soundfont, why);
    if (!font) {
      std::fprintf(stderr, "pseudo3d: no music: %s\n", why.c_str());
      return;
    }
    music_ = std::make_unique<MusicPlayer>(MusicOptions{rate, *font});
    music_->set_volume(settings_.menu.music_volume);
  }

  // Once a frame: the track Doom plays now (the map's, the intermission's) started when
  // it changes, read from the WADs outside the device's lock.
  void update_music() {
    if (!music_ || !audio_) return;
    if (music_->failed()) {
      std::fprintf(stderr, "pseudo3d: no music: %s\n", music_->problem().c_str());
      SDL_LockAudioDevice(audio_);  // the callback looks at music_
      const std::unique_ptr<MusicPlayer> gone = std::move(music_);
      SDL_UnlockAudioDevice(audio_);
      return;
    }
    if (front_.paused() != music_->paused()) {  // Doom's pause holds the music too (S_PauseSound)
      SDL_LockAudioDevice(audio_);
      front_.paused() ? music_->pause() : music_->resume();
      SDL_UnlockAudioDevice(audio_);
    }
    const play::Track want = front_.music();
    if (want == music_track_) return;  // Doom's S_ChangeMusic: the same track goes on
    music_track_ = want;
    std::optional<wad::MidiSong> song = front_.music_song(want.music);
    SDL_LockAudioDevice(audio_);
    if (song) music_->play(std::move(*song), want.looping);
    else music_->stop();
    SDL_UnlockAudioDevice(audio_);
  }

  // Starts the sounds of the tics just run and moves the others with the listener.
  void play_sounds() {
    std::vector<Session::PlacedSound> sounds = front_.take_sounds();
    if (!audio_) return;
    const Session* session = front_.session();
    const play::Listener listener = session ? session->listener() : play::Listener{};
    for (const Session::PlacedSound& s : sounds) front_.sound_clip(s.sound);  // decoded outside the lock
    SDL_LockAudioDevice(audio_);
    for (const Session::PlacedSound& s : sounds) mixer_->start(s.sound, s.origin, s.at, listener);
    mixer_->update(listener, [&](uint64_t origin) { return session ? session->sound_origin(origin) : std::nullopt; });
    SDL_UnlockAudioDevice(audio_);
  }

  // What the tics asked for: sounds and music, settings to apply and keep, the quit.
  void after_tics() {
    play_sounds();
    update_music();
    if (front_.settings_changed()) {
      apply_volumes();
      if (o_.keep_settings) o_.keep_settings(settings_);
    }
    if (front_.quit_requested()) running_ = false;
    const std::string title = window_title();
    if (title != shown_title_) SDL_SetWindowTitle(window_, (shown_title_ = title).c_str());
  }

  // The window as the player left it, kept when it changed (or the WAD played did).
  void keep_window_settings() {
    if (!o_.keep_settings) return;
    const Settings before = settings_;
    settings_.fullscreen = SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP;
    if (!settings_.fullscreen) SDL_GetWindowSize(window_, &settings_.window_width, &settings_.window_height);
    if (settings_.fullscreen != before.fullscreen || settings_.window_width != before.window_width ||
        settings_.window_height != before.window_height || o_.wad_changed)
      o_.keep_settings(settings_);
  }

  // ---- frames
  // The heads-up times: averages over the last half second.
  void show_averages(double now) {
    const double n = double(summed_frames_);
    times_ = {n / (now - summed_start_), summed_.frame_ms / n, summed_.sim_ms / n, summed_.render_ms / n,
              summed_.present_ms / n};
    summed_ = {};
    summed_frames_ = 0;
    summed_start_ = now;
  }

  // Renders at the window's size unless a fixed resolution was asked for; only here
  // are the frame and the streaming texture (re)allocated.
  bool resize() {
    int w = o_.render_width, h = o_.render_height;
    if (w <= 0 || h <= 0) SDL_GetRendererOutputSize(renderer_, &w, &h);
    w = std::max(w, 16), h = std::max(h, 16);
    if (texture_ && w == frame_.width && h == frame_.height) return true;
    if (texture_) SDL_DestroyTexture(texture_);
    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, w, h);
    if (!texture_) {
      fail("cannot create the frame texture");
      return false;
    }
    frame_ = render::Frame(w, h);
    return true;
  }

  // The frame through Doom's gamma correction, on the screen.
  void present() {
    const uint32_t* pixels = frame_.pixels.data();
    if (settings_.menu.gamma > 0) {
      shown_.assign(frame_.pixels.begin(), frame_.pixels.end());
      front::apply_gamma(settings_.menu.gamma, shown_);
      pixels = shown_.data();
    }
    SDL_UpdateTexture(texture_, nullptr, pixels, frame_.width * 4);
    SDL_RenderClear(renderer_);
    SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
    SDL_RenderPresent(renderer_);
  }

  void screenshot() {
    try {
      const auto path = screenshot_path();
      image::save_png(frame_, path);
      front_.say("saved " + path.string());
    } catch (const std::exception& e) {
      front_.say(e.what());
    }
  }

  // ---- input
  void poll_events() {
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
      if (e.type == SDL_QUIT) running_ = false;
      if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED && !resize()) running_ = false;
      if (e.type == SDL_MOUSEMOTION && SDL_GetRelativeMouseMode()) front_.mouse_motion(e.motion.xrel);
      if ((e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP) && e.button.button == SDL_BUTTON_LEFT)
        front_.mouse_button(1, e.type == SDL_MOUSEBUTTONDOWN && SDL_GetRelativeMouseMode());
      if (e.type == SDL_KEYDOWN) key_down(e.key);
      if (e.type == SDL_KEYUP) front_.key_up(doom_key(e.key.keysym.sym));
    }
  }

  void key_down(const SDL_KeyboardEvent& k) {
    if (k.keysym.sym == SDLK_RETURN && (k.keysym.mod & KMOD_ALT)) {  // Alt+Enter: fullscreen, as Chocolate Doom
      if (!k.repeat) {
        const bool full = SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP;
        SDL_SetWindowFullscreen(window_, full ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
      }
      return;
    }
    const int key = doom_key(k.keysym.sym);
    if (!key || (k.repeat && !front_.menu_active())) return;  // held keys repeat in menus only (typing, moving)
    front_.key_down(key);
  }

  // The mouse turns the player while it plays; menus and pages free it.
  void follow_mouse() {
    const bool want = front_.playing() && !front_.waiting() && !o_.play && !autopilot_;
    if (want != bool(SDL_GetRelativeMouseMode())) SDL_SetRelativeMouseMode(want ? SDL_TRUE : SDL_FALSE);
  }

  // A netgame's tics: ours sent as they fall due, each run once the server sent the others'.
  void net_tics() {
    const uint64_t run = o_.netplay->step(
        *front_.session(), [&] { return front_.command(); }, [&](const play::TicCmd& ours) { front_.tic({ours, 0}); });
    if (o_.quit_after_tics && run >= o_.quit_after_tics) running_ = false;
  }

  void run_tic() {
    if (o_.play) {  // through the tallies into the next maps, as Doom plays a demo on
      if (played_ >= o_.play->tics.size() || !front_.in_game()) {
        running_ = false;
        return;
      }
      if (front_.melting())
        front_.tic();  // the demo's next tic waits for the screen
      else
        front_.tic(o_.play->tics[played_++]);
    } else if (autopilot_ && front_.in_level()) {
      const Session& s = *front_.session();
      front_.tic({autopilot_->next(s.pose().pos, s.pose().angle), 0});
      if (autopilot_->done()) running_ = false;
    } else {
      front_.tic();
    }
    const Session* s = front_.session();
    if (s && autopilot_ && s->exited() != play::ExitKind::kNone) running_ = false;  // a route holds one level
    if (o_.quit_after_tics && ++tics_run_ >= o_.quit_after_tics) running_ = false;
  }

  FrontEnd& front_;
  Settings& settings_;
  const WindowOptions& o_;
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  render::Frame frame_;
  std::vector<uint32_t> shown_;  // the frame through gamma
  std::string shown_title_;
  FrameTimes times_, summed_;  // shown, and being summed
  uint64_t summed_frames_ = 0;
  double summed_start_ = now_seconds();
  bool running_ = true;
  size_t played_ = 0;
  uint64_t tics_run_ = 0;
  std::optional<Autopilot> autopilot_;
  std::optional<SoundMixer> mixer_;
  std::unique_ptr<MusicPlayer> music_;
  play::Track music_track_{play::Music::kNone, false};  // what the player was last asked to play
  SDL_AudioDeviceID audio_ = 0;
};

}  // namespace

int run_window(FrontEnd& front, Settings& settings, const WindowOptions& options) {
  return Window(front, settings, options).run();
}

}  // namespace p3d::game
