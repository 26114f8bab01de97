#include "engine/front/menu.h"

#include <algorithm>
#include <cctype>

#include "engine/front/keys.h"
#include "engine/front/texts.h"
#include "engine/play/dehacked.h"

namespace p3d::front {

namespace {

// The keys of Doom's menus (Chocolate Doom's defaults).
constexpr int kMenuActivate = kKeyEscape, kMenuUp = kKeyUp, kMenuDown = kKeyDown, kMenuLeft = kKeyLeft,
              kMenuRight = kKeyRight, kMenuBack = kKeyBackspace, kMenuForward = kKeyEnter, kMenuConfirm = 'y',
              kMenuAbort = 'n', kMenuHelp = kKeyF1, kMenuSave = kKeyF2, kMenuLoad = kKeyF3, kMenuVolume = kKeyF4,
              kMenuDetail = kKeyF5, kMenuQuickSave = kKeyF6, kMenuEndGame = kKeyF7, kMenuMessages = kKeyF8,
              kMenuQuickLoad = kKeyF9, kMenuQuit = kKeyF10, kMenuGamma = kKeyF11, kMenuIncreaseScreen = kKeyEquals,
              kMenuDecreaseScreen = kKeyMinus;

// The sounds of Doom's quit, by gametic (its quitsounds and quitsounds2).
constexpr play::Sound kQuitSounds[8] = {play::Sound::kPldeth, play::Sound::kDmpain, play::Sound::kPopain,
                                        play::Sound::kSlop,   play::Sound::kTelept, play::Sound::kPosit1,
                                        play::Sound::kPosit3, play::Sound::kSgtatk};
constexpr play::Sound kQuitSounds2[8] = {play::Sound::kVilact, play::Sound::kGetpow, play::Sound::kBoscub,
                                         play::Sound::kSlop,   play::Sound::kSkeswg, play::Sound::kKntdth,
                                         play::Sound::kBspact, play::Sound::kSgtatk};

}  // namespace

bool is_null_key(int key) {
  return key == kKeyPause || key == kKeyCapsLock || key == kKeyScrollLock || key == kKeyNumLock;
}

// Doom's menu tables and M_Init's changes for the game mode.
Menu::Menu(GameMode mode, MenuSettings& settings, SlotReader slots, std::function<std::string(const std::string&)> texts)
    : mode_(mode), settings_(settings), read_slot_texts_(std::move(slots)), texts_(std::move(texts)) {
  const bool commercial = mode == GameMode::kCommercial, ultimate = mode == GameMode::kRetail;
  def(Page::kMain) = {{{1, "M_NGAME", 'n'}, {1, "M_OPTION", 'o'}, {1, "M_LOADG", 'l'}, {1, "M_SAVEG", 's'},
                       {1, "M_RDTHIS", 'r'}, {1, "M_QUITG", 'q'}},
                      {&Menu::new_game, &Menu::options, &Menu::load_game, &Menu::save_game, &Menu::read_this,
                       &Menu::quit_doom},
                      std::nullopt, 97, 64, 0};
  def(Page::kEpisode) = {{{1, "M_EPI1", 'k'}, {1, "M_EPI2", 't'}, {1, "M_EPI3", 'i'}, {1, "M_EPI4", 't'}},
                         {&Menu::episode, &Menu::episode, &Menu::episode, &Menu::episode},
                         Page::kMain, 48, 63, 0};
  def(Page::kNewGame) = {{{1, "M_JKILL", 'i'}, {1, "M_ROUGH", 'h'}, {1, "M_HURT", 'h'}, {1, "M_ULTRA", 'u'},
                          {1, "M_NMARE", 'n'}},
                         {&Menu::choose_skill, &Menu::choose_skill, &Menu::choose_skill, &Menu::choose_skill,
                          &Menu::choose_skill},
                         Page::kEpisode, 48, 63, 2};
  def(Page::kOptions) = {{{1, "M_ENDGAM", 'e'}, {1, "M_MESSG", 'm'}, {1, "M_DETAIL", 'g'}, {2, "M_SCRNSZ", 's'},
                          {-1, "", 0}, {2, "M_MSENS", 'm'}, {-1, "", 0}, {1, "M_SVOL", 's'}},
                         {&Menu::end_game, &Menu::change_messages, &Menu::change_detail, &Menu::size_display, nullptr,
                          &Menu::change_sensitivity, nullptr, &Menu::sound_menu},
                         Page::kMain, 60, 37, 0};
  def(Page::kReadThis1) = {{{1, "", 0}}, {&Menu::read_this2}, Page::kMain, 280, 185, 0};
  def(Page::kReadThis2) = {{{1, "", 0}}, {&Menu::finish_read_this}, Page::kReadThis1, 330, 175, 0};
  def(Page::kSound) = {{{2, "M_SFXVOL", 's'}, {-1, "", 0}, {2, "M_MUSVOL", 'm'}, {-1, "", 0}},
                       {&Menu::sfx_volume, nullptr, &Menu::music_volume, nullptr},
                       Page::kOptions, 80, 64, 0};
  MenuDef slots_menu;
  for (int i = 0; i < kSaveSlots; ++i) slots_menu.items.push_back({1, "", char('1' + i)});
  slots_menu.previous = Page::kMain;
  slots_menu.x = 80, slots_menu.y = 54;
  def(Page::kLoad) = slots_menu;
  def(Page::kLoad).actions.assign(kSaveSlots, &Menu::load_select);
  def(Page::kSave) = slots_menu;
  def(Page::kSave).actions.assign(kSaveSlots, &Menu::save_select);

  if (ultimate) {  // Read This! goes straight to the one help page
    def(Page::kMain).actions[4] = &Menu::read_this2;
    def(Page::kReadThis2).previous.reset();
  }
  if (commercial) {  // no Read This!, no episodes
    def(Page::kMain).items[4] = def(Page::kMain).items[5];
    def(Page::kMain).actions[4] = def(Page::kMain).actions[5];
    def(Page::kMain).items.pop_back();
    def(Page::kMain).actions.pop_back();
    def(Page::kMain).y += 8;
    def(Page::kNewGame).previous = Page::kMain;
    def(Page::kReadThis1).x = 330, def(Page::kReadThis1).y = 165;
    def(Page::kReadThis1).actions[0] = &Menu::finish_read_this;
  }
  if (!ultimate) {  // three episodes before the Ultimate Doom
    def(Page::kEpisode).items.pop_back();
    def(Page::kEpisode).actions.pop_back();
  }
  for (std::string& s : slot_texts_) s = doom_text(kEmptySlot);
}

// Doom keeps screenSize = screenblocks - 3 beside screenblocks; 11 blocks (no status
// bar) is one past its slider's end.
int Menu::screen_size_slider() const { return std::clamp(settings_.screen_blocks - kMinScreenBlocks, 0, 8); }

std::string Menu::doom_text(const std::string& mnemonic) const { return text(play::english_text(mnemonic)); }

bool Menu::showing_help() const {
  return active_ && !message_ && (current_ == Page::kReadThis1 || current_ == Page::kReadThis2);
}

Menu::Screen Menu::screen() const {
  const MenuDef& d = def(current_);
  return {current_, d.x, d.y, d.items, item_on_, which_skull_};
}

void Menu::open() {
  if (active_) return;  // the title loop may call it again and again
  active_ = true;
  current_ = Page::kMain;
  item_on_ = def(current_).last_on;
}

void Menu::tic() {
  if (--skull_counter_ <= 0) {
    which_skull_ ^= 1;
    skull_counter_ = 8;
  }
}

void Menu::setup_next(Page page) {
  current_ = page;
  item_on_ = def(page).last_on;
}

void Menu::start_message(std::string message, Action response, bool needs_input) {
  message_last_active_ = active_;
  message_ = std::move(message);
  message_response_ = response;
  message_needs_input_ = needs_input;
  active_ = true;
}

void Menu::request(MenuRequest::Kind kind, int slot, std::string message) {
  MenuRequest r{kind};
  r.slot = slot;
  r.text = std::move(message);
  requests_.push_back(std::move(r));
}

// ---- keys (M_Responder)

bool Menu::key(int key, int ch, const MenuContext& context) {
  context_ = context;
  if (entering_save_) return save_string_key(key);
  if (message_) return message_key(key, context);
  if (key != 0 && key == kKeyPrintScreen) {
    request(MenuRequest::Kind::kScreenshot);
    return true;
  }
  if (!active_) {
    if (function_key(key, context)) return true;
    if (key == kMenuActivate) {
      open();
      sound(play::Sound::kSwtchn);
      return true;
    }
    return false;
  }
  return menu_key(key, ch);
}

bool Menu::save_string_key(int key) {
  std::string& s = slot_texts_[size_t(save_slot_)];
  if (key == kKeyBackspace) {
    if (!s.empty()) s.pop_back();
  } else if (key == kKeyEscape) {
    entering_save_ = false;
    s = old_save_text_;
  } else if (key == kKeyEnter) {
    entering_save_ = false;
    if (!s.empty()) do_save(save_slot_);
  } else {
    // Vanilla Doom types the key, not the character: no shift, upper case.
    const int c = key < 0x80 ? std::toupper(key) : key;
    if (c != ' ' && (c < kFontFirst || c > kFontLast)) return true;
    if (int(s.size()) < kSaveStringSize - 1 && text_width(s) < (kSaveStringSize - 2) * 8) s += char(c);
  }
  return true;
}

bool Menu::message_key(int key, const MenuContext&) {
  if (message_needs_input_ && key != ' ' && key != kKeyEscape && key != kMenuConfirm && key != kMenuAbort) return false;
  active_ = message_last_active_;
  message_.reset();
  if (message_response_) (this->*message_response_)(key);
  active_ = false;  // Doom closes the menu after any answer
  if (!quitting_) sound(play::Sound::kSwtchx);  // Doom quits before this one
  return true;
}

bool Menu::function_key(int key, const MenuContext& context) {
  if (key == kMenuDecreaseScreen || key == kMenuIncreaseScreen) {
    if (context.automap) return false;
    size_display(key == kMenuIncreaseScreen ? 1 : 0);
    sound(play::Sound::kStnmov);
    return true;
  }
  if (key == kMenuHelp) {
    open();
    current_ = mode_ == GameMode::kRetail ? Page::kReadThis2 : Page::kReadThis1;
    item_on_ = 0;
    sound(play::Sound::kSwtchn);
    return true;
  }
  if (key == kMenuSave || key == kMenuLoad) {
    open();
    sound(play::Sound::kSwtchn);
    key == kMenuSave ? save_game(0) : load_game(0);
    return true;
  }
  if (key == kMenuVolume) {
    open();
    current_ = Page::kSound;
    item_on_ = 0;
    sound(play::Sound::kSwtchn);
    return true;
  }
  if (key == kMenuDetail) {
    change_detail(0);
    sound(play::Sound::kSwtchn);
    return true;
  }
  if (key == kMenuQuickSave || key == kMenuQuickLoad || key == kMenuEndGame || key == kMenuQuit ||
      key == kMenuMessages) {
    sound(play::Sound::kSwtchn);
    if (key == kMenuQuickSave) quick_save();
    if (key == kMenuQuickLoad) quick_load();
    if (key == kMenuEndGame) end_game(0);
    if (key == kMenuQuit) quit_doom(0);
    if (key == kMenuMessages) change_messages(0);
    return true;
  }
  if (key == kMenuGamma) {
    settings_.gamma = settings_.gamma >= 4 ? 0 : settings_.gamma + 1;
    say(doom_text(kGammaMessages[size_t(settings_.gamma)]));
    settings_changed();
    return true;
  }
  return false;
}

bool Menu::menu_key(int key, int ch) {
  MenuDef& d = def(current_);
  const int count = int(d.items.size());
  if (key == kMenuDown || key == kMenuUp) {
    do {
      item_on_ = key == kMenuDown ? (item_on_ + 1 > count - 1 ? 0 : item_on_ + 1) : (item_on_ == 0 ? count - 1 : item_on_ - 1);
      sound(play::Sound::kPstop);
    } while (d.items[size_t(item_on_)].status == -1);
    return true;
  }
  const Item& item = d.items[size_t(item_on_)];
  const Action action = d.actions[size_t(item_on_)];
  if (key == kMenuLeft || key == kMenuRight) {  // a slider
    if (action && item.status == 2) {
      sound(play::Sound::kStnmov);
      (this->*action)(key == kMenuRight ? 1 : 0);
    }
    return true;
  }
  if (key == kMenuForward) {
    if (action && item.status) {
      d.last_on = item_on_;
      if (item.status == 2) {
        (this->*action)(1);
        sound(play::Sound::kStnmov);
      } else {
        (this->*action)(item_on_);
        sound(play::Sound::kPistol);
      }
    }
    return true;
  }
  if (key == kMenuActivate) {
    d.last_on = item_on_;
    clear();
    sound(play::Sound::kSwtchx);
    return true;
  }
  if (key == kMenuBack) {
    d.last_on = item_on_;
    if (d.previous) {
      current_ = *d.previous;
      item_on_ = def(current_).last_on;
      sound(play::Sound::kSwtchn);
    }
    return true;
  }
  if (ch != 0 || is_null_key(key)) {  // a letter shortcut: the next item with it, wrapping round
    for (int pass = 0; pass < 2; ++pass)
      for (int i = pass ? 0 : item_on_ + 1; pass ? i <= item_on_ : i < count; ++i)
        if (d.items[size_t(i)].hotkey == ch) {
          item_on_ = i;
          sound(play::Sound::kPstop);
          return true;
        }
  }
  return false;
}

// ---- the routines

void Menu::new_game(int) {
  if (context_.netgame) {
    start_message(doom_text(kNewGameInNetgame), nullptr, false);
    return;
  }
  setup_next(mode_ == GameMode::kCommercial ? Page::kNewGame : Page::kEpisode);
}

void Menu::episode(int choice) {
  if (mode_ == GameMode::kShareware && choice) {
    start_message(doom_text(kSharewareOnly), nullptr, false);
    setup_next(Page::kReadThis1);
    return;
  }
  episode_ = choice;
  setup_next(Page::kNewGame);
}

void Menu::choose_skill(int choice) {
  if (choice == 4) {
    start_message(doom_text(kNightmareQuestion), &Menu::verify_nightmare, true);
    return;
  }
  MenuRequest r{MenuRequest::Kind::kNewGame};
  r.episode = episode_ + 1;
  r.skill = choice + 1;
  requests_.push_back(r);
  clear();
}

void Menu::verify_nightmare(int key) {
  if (key != kMenuConfirm) return;
  MenuRequest r{MenuRequest::Kind::kNewGame};
  r.episode = episode_ + 1;
  r.skill = 5;
  requests_.push_back(r);
  clear();
}

void Menu::options(int) { setup_next(Page::kOptions); }

void Menu::end_game(int) {
  if (!context_.user_game) {
    sound(play::Sound::kOof);
    return;
  }
  if (context_.netgame) {
    start_message(doom_text(kEndNetgame), nullptr, false);
    return;
  }
  start_message(doom_text(kEndGameQuestion), &Menu::end_game_response, true);
}

void Menu::end_game_response(int key) {
  if (key != kMenuConfirm) return;
  def(current_).last_on = item_on_;
  clear();
  request(MenuRequest::Kind::kEndGame);
}

void Menu::change_messages(int) {
  settings_.show_messages = !settings_.show_messages;
  say(doom_text(settings_.show_messages ? kMessagesOn : kMessagesOff));
  settings_changed();
}

void Menu::change_detail(int) {
  settings_.low_detail = !settings_.low_detail;
  say(doom_text(settings_.low_detail ? kDetailLow : kDetailHigh));
  settings_changed();
}

void Menu::size_display(int choice) {
  if (choice == 0 && screen_size_slider() > 0) --settings_.screen_blocks;
  if (choice == 1 && screen_size_slider() < 8) ++settings_.screen_blocks;
  settings_changed();
}

void Menu::change_sensitivity(int choice) {
  if (choice == 0 && settings_.mouse_sensitivity > 0) --settings_.mouse_sensitivity;
  if (choice == 1 && settings_.mouse_sensitivity < 9) ++settings_.mouse_sensitivity;
  settings_changed();
}

void Menu::sound_menu(int) { setup_next(Page::kSound); }

void Menu::sfx_volume(int choice) {
  if (choice == 0 && settings_.sfx_volume > 0) --settings_.sfx_volume;
  if (choice == 1 && settings_.sfx_volume < 15) ++settings_.sfx_volume;
  settings_changed();
}

void Menu::music_volume(int choice) {
  if (choice == 0 && settings_.music_volume > 0) --settings_.music_volume;
  if (choice == 1 && settings_.music_volume < 15) ++settings_.music_volume;
  settings_changed();
}

void Menu::read_slots() {
  const auto slots = read_slot_texts_ ? read_slot_texts_() : std::array<std::optional<std::string>, kSaveSlots>{};
  for (int i = 0; i < kSaveSlots; ++i) {
    slot_texts_[size_t(i)] = slots[size_t(i)] ? *slots[size_t(i)] : doom_text(kEmptySlot);
    def(Page::kLoad).items[size_t(i)].status = slots[size_t(i)] ? 1 : 0;
  }
}

void Menu::load_game(int) {
  if (context_.netgame) {
    start_message(doom_text(kLoadInNetgame), nullptr, false);
    return;
  }
  setup_next(Page::kLoad);
  read_slots();
}

void Menu::load_select(int choice) {
  request(MenuRequest::Kind::kLoadGame, choice);
  clear();
}

void Menu::save_game(int) {
  if (!context_.user_game) {
    start_message(doom_text(kSaveDead), nullptr, false);
    return;
  }
  if (!context_.in_level) return;
  setup_next(Page::kSave);
  read_slots();
}

void Menu::save_select(int choice) {
  entering_save_ = true;
  save_slot_ = choice;
  old_save_text_ = slot_texts_[size_t(choice)];
  if (slot_texts_[size_t(choice)] == doom_text(kEmptySlot)) slot_texts_[size_t(choice)].clear();
}

void Menu::do_save(int slot) {
  request(MenuRequest::Kind::kSaveGame, slot, slot_texts_[size_t(slot)]);
  clear();
  if (quick_save_slot_ == -2) quick_save_slot_ = slot;
}

void Menu::quick_save() {
  if (!context_.user_game) {
    sound(play::Sound::kOof);
    return;
  }
  if (!context_.in_level) return;
  if (quick_save_slot_ < 0) {
    open();
    read_slots();
    setup_next(Page::kSave);
    quick_save_slot_ = -2;  // the save menu picks it
    return;
  }
  start_message(format_prompt(doom_text(kQuickSavePrompt), slot_texts_[size_t(quick_save_slot_)]), &Menu::quick_save_response,
                true);
}

void Menu::quick_save_response(int key) {
  if (key != kMenuConfirm) return;
  do_save(quick_save_slot_);
  sound(play::Sound::kSwtchx);
}

void Menu::quick_load() {
  if (context_.netgame) {
    start_message(doom_text(kQuickLoadInNetgame), nullptr, false);
    return;
  }
  if (quick_save_slot_ < 0) {
    start_message(doom_text(kQuickSaveSpot), nullptr, false);
    return;
  }
  start_message(format_prompt(doom_text(kQuickLoadPrompt), slot_texts_[size_t(quick_save_slot_)]), &Menu::quick_load_response,
                true);
}

void Menu::quick_load_response(int key) {
  if (key != kMenuConfirm) return;
  load_select(quick_save_slot_);
  sound(play::Sound::kSwtchx);
}

void Menu::read_this(int) { setup_next(Page::kReadThis1); }
void Menu::read_this2(int) { setup_next(Page::kReadThis2); }
void Menu::finish_read_this(int) { setup_next(Page::kMain); }

void Menu::quit_doom(int) {
  const auto& messages = mode_ == GameMode::kCommercial ? kDoom2QuitMessages : kDoom1QuitMessages;
  const std::string message = messages[context_.game_tic % messages.size()];
  start_message(doom_text(message) + "\n\n" + kQuitDos, &Menu::quit_response, true);
}

void Menu::quit_response(int key) {
  if (key != kMenuConfirm) return;
  const auto& sounds = mode_ == GameMode::kCommercial ? kQuitSounds2 : kQuitSounds;
  sound(sounds[(context_.game_tic >> 2) & 7]);
  request(MenuRequest::Kind::kQuit);
  quitting_ = true;
}

}  // namespace p3d::front
