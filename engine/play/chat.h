// Doom's chat between the players of a netgame (hu_stuff.c): what a player types
// travels a character a tic in its commands (the ticcmd's chatchar, which the protocol
// carries and demos do not), to everyone or to one player; each node gathers the
// others' characters into their lines and shows a finished line meant for it on the
// message line after the player's name. Nothing of it touches the play.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "engine/play/world.h"

namespace p3d::play {

// Doom's English for each player's name before a line (HUSTR_PLRGREEN...), which a
// WAD's DEHACKED may reword (Freedoom's "g:").
inline constexpr std::array<const char*, kMaxPlayers> kChatNames = {"Green: ", "Indigo: ", "Brown: ", "Red: "};

class Chat {
 public:
  static constexpr uint8_t kToEveryone = 5;  // HU_BROADCAST; 1..4: to that player
  static constexpr uint8_t kEnter = 13, kBackspace = 0x7f, kEscape = 27;

  // The console player starts a line, to everyone or to one player (1..4).
  void start(uint8_t destination);
  bool typing() const { return typing_; }
  // A key while typing (Doom's HU_Responder): letters in Doom's upper case, backspace,
  // enter (the line goes; returned, to be shown as our own message) and escape (the
  // line is dropped). True when the key was the chat's.
  bool key(int ch, std::optional<std::string>* sent = nullptr);
  const std::string& line() const { return line_; }
  // The next character for this tic's command (HU_dequeueChatChar), 0 for none.
  uint8_t next_char();
  // The other players' characters of this tic (HU_Ticker): a finished line for us or
  // everyone comes back with its writer, to be shown after the writer's name.
  struct Line {
    int player = 0;
    std::string text;
  };
  std::optional<Line> receive(const std::array<TicCmd, kMaxPlayers>& cmds, const std::array<bool, kMaxPlayers>& in_game,
                              int console_player);

 private:
  bool typing_ = false;
  std::string line_;                                   // ours, as typed
  std::deque<uint8_t> outgoing_;                       // Doom's chatchars queue
  std::array<std::string, kMaxPlayers> incoming_{};    // w_inputbuffer
  std::array<uint8_t, kMaxPlayers> destination_{};     // chat_dest
};

}  // namespace p3d::play
