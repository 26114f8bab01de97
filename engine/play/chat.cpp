#include "engine/play/chat.h"

namespace p3d::play {

namespace {

constexpr size_t kMaxLine = 80;       // HU_MAXLINELENGTH
constexpr size_t kMaxQueued = 128;    // QUEUESIZE

// HUlib_keyInIText: Doom's letters ' ' to '_', backspace and enter; false for the rest.
bool key_in_line(std::string& line, int ch) {
  if (ch >= ' ' && ch <= '_') {
    if (line.size() < kMaxLine) line += char(ch);
  } else if (ch == Chat::kBackspace) {
    if (!line.empty()) line.pop_back();
  } else if (ch != Chat::kEnter) {
    return false;
  }
  return true;
}

}  // namespace

void Chat::start(uint8_t destination) {
  typing_ = true;
  line_.clear();
  if (outgoing_.size() < kMaxQueued) outgoing_.push_back(destination);
}

bool Chat::key(int ch, std::optional<std::string>* sent) {
  if (!typing_) return false;
  if (ch == kEscape) {
    typing_ = false;
    return true;
  }
  if (ch >= 'a' && ch <= 'z') ch -= 'a' - 'A';  // Doom's shiftxform
  if (!key_in_line(line_, ch)) return false;
  if (outgoing_.size() < kMaxQueued) outgoing_.push_back(uint8_t(ch));
  if (ch == kEnter) {
    typing_ = false;
    if (sent && !line_.empty()) *sent = line_;
  }
  return true;
}

uint8_t Chat::next_char() {
  if (outgoing_.empty()) return 0;
  const uint8_t c = outgoing_.front();
  outgoing_.pop_front();
  return c;
}

std::optional<Chat::Line> Chat::receive(const std::array<TicCmd, kMaxPlayers>& cmds,
                                        const std::array<bool, kMaxPlayers>& in_game, int console_player) {
  std::optional<Line> shown;
  for (int i = 0; i < kMaxPlayers; ++i) {
    const uint8_t c = cmds[size_t(i)].chatchar;
    if (!in_game[size_t(i)] || i == console_player || !c) continue;
    if (c <= kToEveryone) {
      destination_[size_t(i)] = c;
      continue;
    }
    std::string& line = incoming_[size_t(i)];
    if (!key_in_line(line, c) || c != kEnter) continue;
    const uint8_t to = destination_[size_t(i)];
    if (!line.empty() && (to == console_player + 1 || to == kToEveryone)) shown = Line{i, line};
    line.clear();
  }
  return shown;
}

}  // namespace p3d::play
