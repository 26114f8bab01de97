#include "game/sdl_platform.h"

#include <SDL.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "engine/image/image.h"
#include "engine/util/file.h"
#include "game/autopilot.h"
#include "game/music_player.h"
#include "game/sound_mixer.h"

namespace p3d::game {

namespace {

constexpr double kTicSeconds = 1.0 / kTicRate;

double now_seconds() { return double(SDL_GetPerformanceCounter()) / double(SDL_GetPerformanceFrequency()); }

Controls read_controls(int mouse_dx) {
  const Uint8* k = SDL_GetKeyboardState(nullptr);
  Controls c;
  c.forward = k[SDL_SCANCODE_W] || k[SDL_SCANCODE_UP];
  c.back = k[SDL_SCANCODE_S] || k[SDL_SCANCODE_DOWN];
  c.turn_left = k[SDL_SCANCODE_LEFT];
  c.turn_right = k[SDL_SCANCODE_RIGHT];
  c.strafe_left = k[SDL_SCANCODE_A];
  c.strafe_right = k[SDL_SCANCODE_D];
  c.use = k[SDL_SCANCODE_SPACE] || k[SDL_SCANCODE_E];
  c.attack = k[SDL_SCANCODE_LCTRL] || k[SDL_SCANCODE_RCTRL] ||
             (SDL_GetRelativeMouseMode() && (SDL_GetMouseState(nullptr, nullptr) & SDL_BUTTON_LMASK));
  c.strafe_modifier = k[SDL_SCANCODE_LALT] || k[SDL_SCANCODE_RALT];
  c.run = k[SDL_SCANCODE_LSHIFT] || k[SDL_SCANCODE_RSHIFT];
  c.mouse_dx = mouse_dx;
  return c;
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
    "to render without a display: game LEVEL --headless --play DEMO --out DIR (or --autopilot ROUTE)";

class Window {
 public:
  Window(Session& session, const WindowOptions& options) : session_(session), o_(options) {}
  ~Window() {
    if (audio_) SDL_CloseAudioDevice(audio_);  // stops the callback before the mixer goes
    if (texture_) SDL_DestroyTexture(texture_);
    if (renderer_) SDL_DestroyRenderer(renderer_);
    if (window_) SDL_DestroyWindow(window_);
    SDL_Quit();
  }

  int run() {
    if (const char* why = why_no_display()) {
      std::fprintf(stderr, "game: no display to open a window on (%s); %s\n", why, kHeadlessHint);
      return 1;
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return fail("cannot start SDL video");
    if (offscreen_driver()) {
      std::fprintf(stderr, "game: SDL found no display, only its offscreen driver; %s\n", kHeadlessHint);
      return 1;
    }
    if (o_.sound) open_audio();
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "nearest");  // a fixed low resolution stays crisp
    window_ = SDL_CreateWindow(("pseudo3d: " + session_.title()).c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                               o_.window_width, o_.window_height,
                               SDL_WINDOW_RESIZABLE | (o_.fullscreen ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0));
    if (!window_) return fail("cannot open a window");
    renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED | (o_.vsync ? SDL_RENDERER_PRESENTVSYNC : 0));
    if (!renderer_) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
    if (!renderer_) return fail("cannot create a renderer");
    if (!resize()) return 1;
    SDL_SetRelativeMouseMode(SDL_TRUE);
    if (o_.autopilot) autopilot_.emplace(*o_.autopilot);
    if (o_.play) {  // the demo's start and keys, as recorded
      if (o_.play->custom_start) session_.spawn(o_.play->start, o_.play->angle);
      session_.set_keys(o_.play->keys);
    }
    if (!o_.record.empty()) session_.start_recording(o_.record.extension() == ".lmp");
    if (o_.map_reload) session_.watch_files();

    double last = now_seconds(), accumulator = 0;
    const double start = last;
    uint64_t frames = 0;
    while (running_) {
      poll_events();
      const double t0 = now_seconds();
      accumulator = std::min(accumulator + (t0 - last), 0.25);  // after a stall, do not race to catch up
      if (o_.timedemo) accumulator = kTicSeconds;              // exactly one tic per frame
      if (session_.menu.is_open()) accumulator = 0;             // the game waits while the menu is open
      summed_.frame_ms += (t0 - last) * 1000;
      last = t0;
      while (accumulator >= kTicSeconds && running_) {
        run_tic();
        accumulator -= kTicSeconds;
      }
      play_sounds();
      update_music();
      const double t1 = now_seconds();
      session_.reload_if_saved(t1);
      const double alpha = accumulator / kTicSeconds;
      session_.render(frame_, alpha);
      session_.draw_overlays(frame_, times_, alpha);
      const double t2 = now_seconds();
      SDL_UpdateTexture(texture_, nullptr, frame_.pixels.data(), frame_.width * 4);
      SDL_RenderClear(renderer_);
      SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
      SDL_RenderPresent(renderer_);
      const double t3 = now_seconds();
      summed_.sim_ms += (t1 - t0) * 1000;
      summed_.render_ms += (t2 - t1) * 1000;
      summed_.present_ms += (t3 - t2) * 1000;
      ++summed_frames_;
      if (t3 - summed_start_ >= 0.5) show_averages(t3);
      ++frames;
    }
    if (o_.play)
      std::printf("%llu tics, %llu frames in %.2f s: %.1f fps\n", (unsigned long long)session_.tics(),
                  (unsigned long long)frames, now_seconds() - start, frames / std::max(1e-9, now_seconds() - start));
    if (!o_.record.empty()) {
      write_file_atomically(o_.record, session_.encode_recording(o_.record));
      std::printf("recorded %zu tics to %s\n", session_.recording().tics.size(), o_.record.c_str());
    }
    return 0;
  }

 private:
  int fail(const char* what) {
    std::fprintf(stderr, "game: %s: %s\n", what, SDL_GetError());
    return 1;
  }

  // ---- sound: the mixer on SDL's audio thread; without a device the game is silent
  void open_audio() {
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
      std::fprintf(stderr, "game: no sound (%s)\n", SDL_GetError());
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
    mixer_.emplace(want.freq, [this](play::Sound s) { return session_.sound_clip(s); });
    if (o_.music) open_music(want.freq);
    audio_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (!audio_) {
      std::fprintf(stderr, "game: no sound (%s)\n", SDL_GetError());
      return;
    }
    SDL_PauseAudioDevice(audio_, 0);
    session_.listen();
  }

  // ---- music: the player made before the device starts calling it; its sound font
  // loads on a thread of its own meanwhile
  void open_music(int rate) {
    std::string why;
    const std::optional<std::filesystem::path> font = find_soundfont(o_.soundfont, why);
    if (!font) {
      std::fprintf(stderr, "game: no music: %s\n", why.c_str());
      return;
    }
    music_ = std::make_unique<MusicPlayer>(MusicOptions{rate, *font});
    music_->set_volume(o_.music_volume);
  }

  // Once a frame: the track Doom plays now (the map's, the intermission's) started when
  // it changes, read from the WADs outside the device's lock.
  void update_music() {
    if (!music_ || !audio_) return;
    if (music_->failed()) {
      std::fprintf(stderr, "game: no music: %s\n", music_->problem().c_str());
      SDL_LockAudioDevice(audio_);  // the callback looks at music_
      const std::unique_ptr<MusicPlayer> gone = std::move(music_);
      SDL_UnlockAudioDevice(audio_);
      return;
    }
    const play::Track want = session_.music();
    if (want == music_track_) return;
    music_track_ = want;
    std::optional<wad::MidiSong> song = session_.music_song(want.music);
    SDL_LockAudioDevice(audio_);
    if (song) music_->play(std::move(*song), want.looping);
    else music_->stop();
    SDL_UnlockAudioDevice(audio_);
  }

  // Starts the sounds of the tics just run and moves the others with the listener.
  void play_sounds() {
    std::vector<Session::PlacedSound> sounds = session_.take_sounds();
    if (!audio_) return;
    const play::Listener listener = session_.listener();
    for (const Session::PlacedSound& s : sounds) session_.sound_clip(s.sound);  // decoded outside the lock
    SDL_LockAudioDevice(audio_);
    for (const Session::PlacedSound& s : sounds) mixer_->start(s.sound, s.origin, s.at, listener);
    mixer_->update(listener, [&](uint64_t origin) { return session_.sound_origin(origin); });
    SDL_UnlockAudioDevice(audio_);
  }

  // Renders at the window's size unless a fixed resolution was asked for; only here
  // are the frame and the streaming texture (re)allocated.
  // The heads-up times: averages over the last half second.
  void show_averages(double now) {
    const double n = double(summed_frames_);
    times_ = {n / (now - summed_start_), summed_.frame_ms / n, summed_.sim_ms / n, summed_.render_ms / n,
              summed_.present_ms / n};
    summed_ = {};
    summed_frames_ = 0;
    summed_start_ = now;
  }

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

  void poll_events() {
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
      if (e.type == SDL_QUIT) running_ = false;
      if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED && !resize()) running_ = false;
      if (e.type == SDL_MOUSEMOTION && SDL_GetRelativeMouseMode()) mouse_dx_ += e.motion.xrel;
      if (e.type == SDL_MOUSEBUTTONDOWN && !session_.menu.is_open()) SDL_SetRelativeMouseMode(SDL_TRUE);
      if (e.type == SDL_KEYDOWN && !e.key.repeat) {
        if (session_.menu.is_open())
          menu_key(e.key.keysym.sym);
        else
          key(e.key.keysym.sym);
      }
    }
  }

  void open_menu() {
    session_.menu.open();
    SDL_SetRelativeMouseMode(SDL_FALSE);
  }

  void resume() {
    session_.menu.close();
    session_.show_help = false;
    SDL_SetRelativeMouseMode(SDL_TRUE);
  }

  void menu_key(SDL_Keycode k) {
    Menu& menu = session_.menu;
    if (k == SDLK_ESCAPE) resume();
    if (k == SDLK_UP || k == SDLK_w) menu.up();
    if (k == SDLK_DOWN || k == SDLK_s) menu.down();
    if (k == SDLK_F10) running_ = false;
    if (k != SDLK_RETURN && k != SDLK_KP_ENTER && k != SDLK_SPACE) return;
    switch (menu.selected()) {
      case Menu::Item::kResume: resume(); break;
      case Menu::Item::kKeys: session_.show_help = !session_.show_help; break;
      case Menu::Item::kQuit: running_ = false; break;
    }
  }

  void key(SDL_Keycode k) {
    if (k >= SDLK_a && k <= SDLK_z) cheats_typed_ |= cheats_.type(char(k));
    if (k == SDLK_ESCAPE) open_menu();
    if (k == SDLK_F10) running_ = false;
    if (k == SDLK_o && session_.show_automap) session_.automap.overlay = !session_.automap.overlay;
    if (k == SDLK_F1) session_.show_help = !session_.show_help;
    if (k == SDLK_F2) session_.show_hud = !session_.show_hud;
    if (k == SDLK_TAB) session_.show_automap = !session_.show_automap;
    if (k == SDLK_b) session_.automap.splitters = !session_.automap.splitters;
    if (k == SDLK_t) session_.automap.things = !session_.automap.things;
    if (k == SDLK_EQUALS || k == SDLK_PLUS || k == SDLK_KP_PLUS) session_.automap.scale = std::min(8.0, session_.automap.scale * 1.25);
    if (k == SDLK_MINUS || k == SDLK_KP_MINUS) session_.automap.scale = std::max(0.01, session_.automap.scale / 1.25);
    if (k == SDLK_F11) {
      const bool full = SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP;
      SDL_SetWindowFullscreen(window_, full ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
    }
    if (k == SDLK_F12) {
      const auto path = screenshot_path();
      try {
        image::save_png(frame_, path);
        session_.say("saved " + path.string());
      } catch (const std::exception& e) {
        session_.say(e.what());
      }
    }
    if (k >= SDLK_F5 && k <= SDLK_F9) session_.select_renderer(key_renderers()[size_t(k - SDLK_F5)]);
    if (k >= SDLK_1 && k <= SDLK_7) weapon_key_ = int(k - SDLK_0);
  }

  void run_tic() {
    play::DemoTic cmd;
    if (o_.play) {
      if (played_ >= o_.play->tics.size()) {
        running_ = false;
        return;
      }
      cmd = o_.play->tics[played_++];
    } else if (autopilot_) {
      cmd = {autopilot_->next(session_.pose().pos, session_.pose().angle), 0};
      if (autopilot_->done()) running_ = false;
    } else {
      Controls c = read_controls(mouse_dx_);
      c.cheats = std::exchange(cheats_typed_, 0);
      c.weapon = std::exchange(weapon_key_, 0);
      mouse_dx_ = 0;
      turn_held_ = c.turn_left || c.turn_right ? turn_held_ + 1 : 0;
      cmd = make_command(c, turn_held_, o_.input);
    }
    if (session_.in_intermission()) {  // the tally waits for use (Space, E) to go on
      if ((cmd.cmd.buttons & play::kBtUse) && !use_held_) session_.enter_next_map();
      use_held_ = cmd.cmd.buttons & play::kBtUse;
      return;
    }
    use_held_ = cmd.cmd.buttons & play::kBtUse;
    session_.tic(cmd);
    if (session_.exited() != play::ExitKind::kNone) {
      if (o_.play || autopilot_) running_ = false;  // a demo or a route holds one level
      else if (!session_.start_intermission()) session_.enter_next_map();
    }
    if (o_.quit_after_tics && session_.tics() >= o_.quit_after_tics) running_ = false;
  }

  Session& session_;
  const WindowOptions& o_;
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  render::Frame frame_;
  FrameTimes times_, summed_;  // shown, and being summed
  uint64_t summed_frames_ = 0;
  double summed_start_ = now_seconds();
  bool running_ = true;
  int mouse_dx_ = 0, turn_held_ = 0;
  Cheats cheats_;
  uint8_t cheats_typed_ = 0;
  int weapon_key_ = 0;
  size_t played_ = 0;
  std::optional<Autopilot> autopilot_;
  std::optional<SoundMixer> mixer_;
  std::unique_ptr<MusicPlayer> music_;
  play::Track music_track_;  // what the player was last asked to play
  bool use_held_ = false;
  SDL_AudioDeviceID audio_ = 0;
};

}  // namespace

int run_window(Session& session, const WindowOptions& options) { return Window(session, options).run(); }

}  // namespace p3d::game
