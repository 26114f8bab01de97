// WAD files, Doom's resource archives: a validated directory over the file's
// bytes, and a stack of WADs (the IWAD, then PWADs) where a later lump overrides
// an earlier one of the same name, as Doom's -file does. No file access here:
// a Wad is made from bytes (engine/wad/load.h reads files).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace p3d::wad {

constexpr size_t kHeaderSize = 12;
constexpr size_t kDirectoryEntrySize = 16;
constexpr size_t kNameSize = 8;

struct Lump {
  std::string name;                // upper case, cut at the first NUL, at most 8 characters
  std::span<const uint8_t> bytes;  // inside the owning Wad's bytes
  int index = 0;                   // position in its WAD's directory
};

class Wad {
 public:
  // Validates the header and the directory (every lump inside the file); throws
  // Error("<name>: ...") otherwise. `name` is how messages refer to the file.
  Wad(std::vector<uint8_t> bytes, std::string name);
  // The same over bytes that `owner` keeps alive (a mapped file).
  Wad(std::span<const uint8_t> bytes, std::shared_ptr<const void> owner, std::string name);

  const std::string& name() const { return name_; }
  bool is_iwad() const { return iwad_; }
  const std::vector<Lump>& lumps() const { return lumps_; }
  // The last lump of this name in this WAD, or nullptr.
  const Lump* find(std::string_view name) const;

 private:
  void read_directory(std::span<const uint8_t> data);

  std::shared_ptr<const void> owner_;  // keeps the bytes alive: Lump spans outlive moves of the Wad
  std::string name_;
  bool iwad_ = false;
  std::vector<Lump> lumps_;
};

// The lumps of one map: its marker and the lumps after it (THINGS ... or TEXTMAP ... ENDMAP).
struct MapLumps {
  std::string name;      // the marker's name, e.g. MAP01 or E1M1
  std::string wad_name;  // the WAD that holds it
  std::vector<const Lump*> lumps;
  const Lump* find(std::string_view lump_name) const;
  bool udmf() const { return find("TEXTMAP") != nullptr; }
};

class Stack {
 public:
  void add(Wad wad);
  const std::vector<Wad>& wads() const { return wads_; }
  bool empty() const { return wads_.empty(); }

  // The last lump of this name in any WAD (later WADs win), or nullptr. Case-insensitive.
  const Lump* find(std::string_view name) const;

  // Lumps between START and END markers of a namespace (e.g. "F" and "FF" for flats:
  // F_START..F_END, FF_START..FF_END, and their numbered sub-ranges), in every WAD;
  // a later lump of a name replaces an earlier one. Sorted by name.
  std::vector<const Lump*> namespace_lumps(std::initializer_list<std::string_view> prefixes) const;

  // Every map name in the stack, in the order of first appearance.
  std::vector<std::string> map_names() const;
  // The map from the last WAD that holds it; nullopt if none does.
  std::optional<MapLumps> map(std::string_view name) const;

 private:
  std::vector<Wad> wads_;
};

// Lump names as Doom compares them: upper case, at most 8 characters.
std::string normalize_name(std::string_view name);
// A lump name for messages: printable characters kept, others escaped (\xNN).
std::string printable(std::string_view text);

}  // namespace p3d::wad
