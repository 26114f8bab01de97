// The WAD directory: header "IWAD"/"PWAD", lump count, directory offset; 16-byte
// entries (offset, size, 8-byte name). Every entry is checked to lie in the file.
#include "engine/wad/wad.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "engine/util/bytes.h"
#include "engine/util/error.h"

namespace p3d::wad {

namespace {

// The lumps that follow a binary-format map marker (Doom, plus Hexen's BEHAVIOR and SCRIPTS).
constexpr std::string_view kBinaryMapLumps[] = {"THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS",    "SSECTORS",
                                                "NODES",  "SECTORS",  "REJECT",   "BLOCKMAP", "BEHAVIOR", "SCRIPTS"};

bool is_binary_map_lump(std::string_view name) {
  return std::find(std::begin(kBinaryMapLumps), std::end(kBinaryMapLumps), name) != std::end(kBinaryMapLumps);
}

bool is_map_marker(const std::vector<Lump>& lumps, size_t i) {
  return i + 1 < lumps.size() && (lumps[i + 1].name == "THINGS" || lumps[i + 1].name == "TEXTMAP");
}

// The map lumps after marker i: the binary set, or everything up to and including ENDMAP.
std::vector<const Lump*> map_lumps(const std::vector<Lump>& lumps, size_t i) {
  std::vector<const Lump*> out;
  if (lumps[i + 1].name == "TEXTMAP") {
    for (size_t k = i + 1; k < lumps.size(); ++k) {
      out.push_back(&lumps[k]);
      if (lumps[k].name == "ENDMAP") break;
    }
    return out;
  }
  for (size_t k = i + 1; k < lumps.size() && is_binary_map_lump(lumps[k].name); ++k) out.push_back(&lumps[k]);
  return out;
}

}  // namespace

std::string normalize_name(std::string_view name) {
  std::string out;
  for (char c : name.substr(0, std::min(name.size(), kNameSize))) {
    if (c == '\0') break;
    out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

std::string printable(std::string_view text) {
  std::string out;
  for (unsigned char c : text) {
    if (c >= 0x20 && c < 0x7F && c != '\\') {
      out.push_back(char(c));
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
  }
  return out;
}

Wad::Wad(std::vector<uint8_t> bytes, std::string name) : name_(std::move(name)) {
  auto owned = std::make_shared<const std::vector<uint8_t>>(std::move(bytes));
  owner_ = owned;
  read_directory(*owned);
}

Wad::Wad(std::span<const uint8_t> bytes, std::shared_ptr<const void> owner, std::string name)
    : owner_(std::move(owner)), name_(std::move(name)) {
  read_directory(bytes);
}

void Wad::read_directory(std::span<const uint8_t> data) {
  if (data.size() < kHeaderSize) throw Error(name_ + ": not a WAD file (" + std::to_string(data.size()) + " bytes)");
  const std::string_view magic(reinterpret_cast<const char*>(data.data()), 4);
  if (magic != "IWAD" && magic != "PWAD")
    throw Error(name_ + ": not a WAD file (starts with '" + printable(magic) + "', expected IWAD or PWAD)");
  iwad_ = magic == "IWAD";
  const std::span<const uint8_t> all = data;
  ByteReader header(all.subspan(4, 8), name_);
  const int32_t count = header.i32(), offset = header.i32();
  if (count < 0 || offset < 0)
    throw Error(name_ + ": bad WAD header (" + std::to_string(count) + " lumps at byte " + std::to_string(offset) + ")");
  if (uint64_t(offset) + uint64_t(count) * kDirectoryEntrySize > data.size())
    throw Error(name_ + ": the directory of " + std::to_string(count) + " lumps at byte " + std::to_string(offset) +
                " runs past the end of the file (" + std::to_string(data.size()) + " bytes)");
  lumps_.reserve(size_t(count));
  ByteReader dir(all.subspan(size_t(offset), size_t(count) * kDirectoryEntrySize), name_);
  for (int32_t i = 0; i < count; ++i) {
    const int32_t pos = dir.i32(), size = dir.i32();
    const auto raw = dir.raw(kNameSize);
    const std::string lump = normalize_name(std::string_view(reinterpret_cast<const char*>(raw.data()), kNameSize));
    if (pos < 0 || size < 0 || uint64_t(pos) + uint64_t(size) > data.size())
      throw Error(name_ + ": lump #" + std::to_string(i) + " '" + printable(lump) + "' (" + std::to_string(size) +
                  " bytes at byte " + std::to_string(pos) + ") lies outside the file (" + std::to_string(data.size()) +
                  " bytes)");
    lumps_.push_back({lump, all.subspan(size_t(pos), size_t(size)), int(i)});
  }
}

const Lump* Wad::find(std::string_view name) const {
  const std::string key = normalize_name(name);
  for (auto it = lumps_.rbegin(); it != lumps_.rend(); ++it)
    if (it->name == key) return &*it;
  return nullptr;
}

const Lump* MapLumps::find(std::string_view lump_name) const {
  for (const Lump* l : lumps)
    if (l->name == lump_name) return l;
  return nullptr;
}

void Stack::add(Wad wad) { wads_.push_back(std::move(wad)); }

const Lump* Stack::find(std::string_view name) const {
  for (auto it = wads_.rbegin(); it != wads_.rend(); ++it)
    if (const Lump* l = it->find(name)) return l;
  return nullptr;
}

std::vector<const Lump*> Stack::namespace_lumps(std::initializer_list<std::string_view> prefixes) const {
  // A marker is PREFIX_START or PREFIX_END, also numbered (F1_START); any depth of nesting.
  auto marker = [&](const std::string& name, std::string_view suffix) {
    for (std::string_view p : prefixes) {
      if (name.size() < p.size() + suffix.size() || name.compare(0, p.size(), p) != 0) continue;
      const std::string_view rest = std::string_view(name).substr(p.size());
      const std::string_view digits = rest.substr(0, rest.size() - suffix.size());
      if (rest.substr(rest.size() - suffix.size()) == suffix &&
          std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
        return true;
    }
    return false;
  };
  std::vector<const Lump*> found;  // in stack order: of two lumps of a name, the later wins
  for (const Wad& w : wads_) {
    int depth = 0;
    for (const Lump& l : w.lumps()) {
      if (marker(l.name, "_START")) {
        ++depth;
      } else if (marker(l.name, "_END")) {
        depth = std::max(0, depth - 1);
      } else if (depth > 0 && !l.bytes.empty()) {
        found.push_back(&l);
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const Lump* a, const Lump* b) { return a->name < b->name; });
  std::vector<const Lump*> out;  // by name, the last of each
  for (size_t i = 0; i < found.size(); ++i)
    if (i + 1 == found.size() || found[i + 1]->name != found[i]->name) out.push_back(found[i]);
  return out;
}

std::vector<std::string> Stack::map_names() const {
  std::vector<std::string> names;
  for (const Wad& w : wads_)
    for (size_t i = 0; i < w.lumps().size(); ++i)
      if (is_map_marker(w.lumps(), i) && std::find(names.begin(), names.end(), w.lumps()[i].name) == names.end())
        names.push_back(w.lumps()[i].name);
  return names;
}

std::optional<MapLumps> Stack::map(std::string_view name) const {
  const std::string key = normalize_name(name);
  for (auto w = wads_.rbegin(); w != wads_.rend(); ++w) {
    const auto& lumps = w->lumps();
    for (size_t i = lumps.size(); i-- > 0;)
      if (lumps[i].name == key && is_map_marker(lumps, i)) return MapLumps{key, w->name(), map_lumps(lumps, i)};
  }
  return std::nullopt;
}

}  // namespace p3d::wad
