// Chocolate Doom's network protocol ("CHOCOLATE_DOOM_0", Chocolate Doom 3.0 and later),
// as bytes: its packets, the records they carry and the tic commands sent as
// differences. Learnt from Chocolate Doom's net_packet.c, net_structrw.c and net_defs.h;
// the numbers are big-endian, strings end with a NUL.
//
// A game goes: the client sends SYN (magic, version, protocols, what it plays, its
// name) until the server answers SYN (reliable); the server sends WAITING_DATA while
// players join; the controller (the first to join) sends LAUNCH, and every client
// GAMESTART with its settings (the controller's are the game's); the server answers
// each with GAMESTART (its player number); then each client sends GAMEDATA (its
// commands, a few tics again each time) and the server GAMEDATA (every other player's
// command for each tic), with acknowledgements and resend requests both ways.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace p3d::net {

constexpr uint32_t kMagic = 1454104972u;        // NET_MAGIC_NUMBER
constexpr uint32_t kOldMagic = 3436803284u;     // before Chocolate Doom 3.0
constexpr const char* kProtocolName = "CHOCOLATE_DOOM_0";
constexpr uint16_t kReliable = 1 << 15;         // a packet type's bit: resent until acknowledged
constexpr int kDefaultPort = 2342;
constexpr int kMaxPlayers = 8;                  // NET_MAXPLAYERS (Doom plays 4)
constexpr int kMaxPlayerName = 30;
constexpr int kBackupTics = 128;                // BACKUPTICS: the windows of tics in flight

enum class PacketType : uint16_t {
  kSyn,
  kAck,  // no longer sent
  kRejected,
  kKeepalive,
  kWaitingData,
  kGameStart,
  kGameData,
  kGameDataAck,
  kDisconnect,
  kDisconnectAck,
  kReliableAck,
  kGameDataResend,
  kConsoleMessage,
  kQuery,
  kQueryResponse,
  kLaunch,
  kNatHolePunch,
};

// Doom's ticcmd_t as the protocol carries it (Heretic's, Hexen's and Strife's fields
// are read and dropped).
struct TicCmd {
  int8_t forward = 0, side = 0;
  int16_t turn = 0;
  uint8_t buttons = 0;
  uint8_t consistancy = 0;  // the low byte of the player's x some tics before (G_Ticker checks it)
  uint8_t chatchar = 0;
  friend bool operator==(const TicCmd&, const TicCmd&) = default;
};

// A command as the fields that changed since the sender's last one.
struct TicDiff {
  enum : uint8_t { kForward = 1, kSide = 2, kTurn = 4, kButtons = 8, kConsistancy = 16, kChat = 32, kRaven = 64, kStrife = 128 };
  uint8_t changed = 0;
  TicCmd cmd;
};
TicDiff diff_tic(const TicCmd& before, const TicCmd& now);
TicCmd patch_tic(const TicCmd& before, const TicDiff& diff);

// What a client says it plays (net_connect_data_t).
struct ConnectData {
  int game_mode = 0, game_mission = 0;  // Chocolate's GameMode_t and GameMission_t
  bool low_res_turn = false, drone = false;
  int max_players = 4;
  bool is_freedoom = false;
  std::array<uint8_t, 20> wad_sha1{}, deh_sha1{};
  int player_class = 0;
};

// The game (net_gamesettings_t): the controller's, then the server's with each
// client's player number.
struct GameSettings {
  int ticdup = 1, extratics = 1, deathmatch = 0, episode = 1, map = 1;
  int skill = 2;  // Doom's 0..4 (sk_baby..sk_nightmare); -1 no things
  bool no_monsters = false, fast_monsters = false, respawn_monsters = false;
  int game_version = 0;  // Chocolate's GameVersion_t
  bool low_res_turn = false, new_sync = true;
  int time_limit = 0;  // minutes
  int load_game = -1, random = 0;
  int num_players = 1, console_player = 0;
  std::array<int, kMaxPlayers> player_classes{};
};

// The server's word while players join (net_waitdata_t).
struct WaitData {
  int num_players = 0, num_drones = 0, ready_players = 0, max_players = 0;
  bool is_controller = false;
  int console_player = -1;
  std::vector<std::string> player_names, player_addresses;
  std::array<uint8_t, 20> wad_sha1{}, deh_sha1{};
  bool is_freedoom = false;
};

// One tic as the server sends it: each other player's command as a difference.
struct FullTic {
  int latency = 0;
  std::array<bool, kMaxPlayers> in_game{};
  std::array<TicDiff, kMaxPlayers> cmds{};
};

// Chocolate's NET_ExpandTicNum: an 8-bit tic number near `relative`, made whole.
uint32_t expand_tic(uint32_t relative, uint32_t low_byte);

class PacketWriter {
 public:
  explicit PacketWriter(PacketType type, bool reliable = false) { u16(uint16_t(type) | (reliable ? kReliable : 0)); }
  void u8(uint32_t v) { bytes_.push_back(uint8_t(v)); }
  void u16(uint32_t v) { u8(v >> 8), u8(v); }
  void u32(uint32_t v) { u16(v >> 16), u16(v); }
  void str(const std::string& s);
  void blob(std::span<const uint8_t> b) { bytes_.insert(bytes_.end(), b.begin(), b.end()); }
  void connect_data(const ConnectData& d);
  void settings(const GameSettings& s);
  void tic_diff(const TicDiff& d, bool low_res_turn);
  void full_tic(const FullTic& t, bool low_res_turn);
  void wait_data(const WaitData& w);
  void protocol_list();  // every protocol spoken: ours alone
  std::vector<uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
};

// Reads what a packet holds; every read says whether the bytes were there (a short or
// malformed packet is dropped, as Chocolate drops it).
class PacketReader {
 public:
  explicit PacketReader(std::span<const uint8_t> bytes) : bytes_(bytes) {}
  std::optional<uint32_t> u8();
  std::optional<uint32_t> u16();
  std::optional<uint32_t> u32();
  std::optional<int32_t> s8();
  std::optional<int32_t> s16();
  std::optional<std::string> str();  // up to its NUL; nullopt if the packet ends first
  bool blob(std::span<uint8_t> out);
  std::optional<ConnectData> connect_data();
  std::optional<GameSettings> settings();
  std::optional<TicDiff> tic_diff(bool low_res_turn);
  std::optional<FullTic> full_tic(bool low_res_turn);
  std::optional<WaitData> wait_data();
  bool protocol_list_has_ours();  // NET_ReadProtocolList found CHOCOLATE_DOOM_0
  size_t left() const { return bytes_.size() - at_; }

 private:
  std::span<const uint8_t> bytes_;
  size_t at_ = 0;
};

}  // namespace p3d::net
