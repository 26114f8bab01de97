// Doom's menus (its m_menu.c): the main menu, episodes, skills, options, the sound
// volumes, load and save with six slots and typed descriptions, Read This!, and the
// questions answered y or n (nightmare, end game, quit, quicksave, quickload), with
// Doom's keys, letter shortcuts, function keys and sounds. A state machine fed Doom's
// key codes one tic at a time; what it decides leaves as requests (start a game,
// load slot 3, quit...) that the front end carries out, and sounds it plays. Pure:
// no files, no clock (the slots' descriptions are handed in).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/front/game_mode.h"
#include "engine/play/info.h"

namespace p3d::front {

// What the menus change: Doom's defaults (Chocolate Doom's default.cfg).
struct MenuSettings {
  int mouse_sensitivity = 5;  // 0..9
  bool show_messages = true;
  bool low_detail = false;
  int screen_blocks = 9;      // 3..11: the view's size (10 fills the width above the bar, 11 hides the bar)
  int sfx_volume = 8;         // 0..15
  int music_volume = 8;       // 0..15
  int gamma = 0;              // 0..4: Doom's gamma correction levels
};
constexpr int kMinScreenBlocks = 3, kMaxScreenBlocks = 11;

constexpr int kMenuLineHeight = 16;  // rows between a menu's items (Doom's LINEHEIGHT)
constexpr int kSaveSlots = 6;
constexpr int kSaveStringSize = 24;
constexpr int kFontFirst = '!', kFontLast = '_';  // Doom's heads-up font (HU_FONTSTART, its last letter)  // a description's bytes with its terminating zero (Doom's SAVESTRINGSIZE)

// What the menu asks the game to do.
struct MenuRequest {
  enum class Kind : uint8_t {
    kNewGame,     // episode, skill (Doom's G_DeferedInitNew)
    kLoadGame,    // slot
    kSaveGame,    // slot, text: the description
    kEndGame,     // back to the title loop (D_StartTitle)
    kQuit,        // after the quit sound has played
    kMessage,     // text: shown on the message line even with messages off
    kScreenshot,
    kSettings,    // MenuSettings changed (volumes, screen size, detail, gamma...)
  };
  Kind kind;
  int episode = 1, skill = 3, slot = 0;
  std::string text;
};

// What the game tells the menu about itself.
struct MenuContext {
  GameMode mode = GameMode::kCommercial;
  bool user_game = false;      // a game the player started or loaded (Doom's usergame): saving and ending allowed
  bool in_level = false;       // Doom's gamestate == GS_LEVEL
  bool netgame = false;        // no new game, load or end then; a save is every player's
  bool automap = false;        // the screen-size keys belong to the map then
  uint64_t game_tic = 0;       // Doom's gametic: picks the quit message and its sound
};

class Menu {
 public:
  // The descriptions of the six save slots (nullopt: empty), read when the load or
  // save menu opens (Doom's M_ReadSaveStrings).
  using SlotReader = std::function<std::array<std::optional<std::string>, kSaveSlots>()>;
  // `texts` rewords Doom's English as the WAD's DEHACKED does (play::GameOptions::texts).
  Menu(GameMode mode, MenuSettings& settings, SlotReader slots,
       std::function<std::string(const std::string&)> texts = {});

  // Doom's M_Responder: a key pressed (Doom's key code; `ch` the character typed, 0
  // for none). True when the menu took it (it was open, or a function key).
  bool key(int key, int ch, const MenuContext& context);
  // Doom's M_StartControlPanel: the main menu, at the item last chosen.
  void open();
  // How wide Doom's font writes a text (M_StringWidth): a typed description stops
  // short of the slot's end. Without one, 8 pixels a character.
  std::function<int(const std::string&)> text_width = [](const std::string& s) { return int(s.size()) * 8; };
  // Doom's M_Ticker: the skull's blink.
  void tic();

  bool active() const { return active_; }
  // A question or a notice is on screen (Doom draws it alone, without the menu).
  bool showing_message() const { return message_.has_value(); }
  // Help pages (Read This!, F1) cover the whole screen.
  bool showing_help() const;
  // Typing a save's description.
  bool entering_save_name() const { return entering_save_; }

  std::vector<MenuRequest> take_requests() { return std::exchange(requests_, {}); }
  std::vector<play::Sound> take_sounds() { return std::exchange(sounds_, {}); }

  // A text by its mnemonic (or Doom's English for those without), as the WAD words it.
  std::string doom_text(const std::string& mnemonic) const;

  // ---- what MenuArt draws
  struct Item {
    int status = 1;          // 0: no cursor (an empty load slot), 1: chosen with enter, 2: a slider, -1: a gap
    std::string picture;     // its lump ("M_NGAME"), or empty
    char hotkey = 0;
  };
  enum class Page : uint8_t { kMain, kEpisode, kNewGame, kOptions, kReadThis1, kReadThis2, kSound, kLoad, kSave };
  struct Screen {
    Page page = Page::kMain;
    int x = 0, y = 0;
    std::vector<Item> items;
    int item_on = 0;
    int skull = 0;  // 0 or 1: M_SKULL1 or M_SKULL2
  };
  Screen screen() const;
  const std::optional<std::string>& message() const { return message_; }
  const std::array<std::string, kSaveSlots>& slot_texts() const { return slot_texts_; }
  int save_slot() const { return save_slot_; }
  const MenuSettings& settings() const { return settings_; }
  GameMode mode() const { return mode_; }
  // Doom's screenSize: the options' slider (screen_blocks - 3, at most 8).
  int screen_size_slider() const;

 private:
  using Action = void (Menu::*)(int choice);
  struct MenuDef {  // Doom's menu_t
    std::vector<Item> items;
    std::vector<Action> actions;  // per item, or nullptr
    std::optional<Page> previous;
    int x = 0, y = 0;
    int last_on = 0;
  };
  MenuDef& def(Page page) { return menus_[size_t(page)]; }
  const MenuDef& def(Page page) const { return menus_[size_t(page)]; }

  void setup_next(Page page);
  void start_message(std::string text, Action response, bool needs_input);
  void clear() { active_ = false; }
  bool save_string_key(int key);
  bool message_key(int key, const MenuContext& context);
  bool function_key(int key, const MenuContext& context);
  bool menu_key(int key, int ch);
  void read_slots();
  void request(MenuRequest::Kind kind, int slot = 0, std::string text = {});
  void say(const std::string& text) { request(MenuRequest::Kind::kMessage, 0, text); }
  void sound(play::Sound s) { sounds_.push_back(s); }
  std::string text(const std::string& english) const { return texts_ ? texts_(english) : english; }
  void settings_changed() { request(MenuRequest::Kind::kSettings); }

  // Doom's menu routines, by their m_menu.c names.
  void new_game(int);
  void episode(int choice);
  void choose_skill(int choice);
  void verify_nightmare(int key);
  void options(int);
  void end_game(int);
  void end_game_response(int key);
  void change_messages(int);
  void change_detail(int);
  void size_display(int choice);
  void change_sensitivity(int choice);
  void sound_menu(int);
  void sfx_volume(int choice);
  void music_volume(int choice);
  void load_game(int);
  void load_select(int choice);
  void save_game(int);
  void save_select(int choice);
  void do_save(int slot);
  void quick_save();
  void quick_save_response(int key);
  void quick_load();
  void quick_load_response(int key);
  void read_this(int);
  void read_this2(int);
  void finish_read_this(int);
  void quit_doom(int);
  void quit_response(int key);

  GameMode mode_;
  MenuSettings& settings_;
  SlotReader read_slot_texts_;
  std::function<std::string(const std::string&)> texts_;
  MenuContext context_;  // as of the last key

  std::array<MenuDef, 9> menus_;
  Page current_ = Page::kMain;
  int item_on_ = 0;
  bool active_ = false;
  int skull_counter_ = 10, which_skull_ = 0;
  int episode_ = 0;

  std::optional<std::string> message_;
  Action message_response_ = nullptr;
  bool message_needs_input_ = false;
  bool message_last_active_ = false;

  std::array<std::string, kSaveSlots> slot_texts_;
  bool entering_save_ = false;
  int save_slot_ = 0;
  std::string old_save_text_;
  int quick_save_slot_ = -1;  // -1: none picked; -2: the save menu picks it now

  std::vector<MenuRequest> requests_;
  std::vector<play::Sound> sounds_;
  bool quitting_ = false;
};

// Doom's key codes that mean "nothing" to its menus but still jump among items with
// letter shortcuts (Pause, Caps Lock, Scroll Lock, Num Lock), as vanilla Doom does.
bool is_null_key(int key);

}  // namespace p3d::front
