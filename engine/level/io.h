// Reading and writing compiled levels (format.h). The reader is the only place
// bytes become a Level, and it checks every size, index and the checksum.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "engine/level/level.h"
#include "engine/util/file.h"

namespace p3d::level {

std::vector<uint8_t> encode(const Level& level);
// The same bytes written to a file as they are made: the encoding is never whole in
// memory (216 bytes a wall: 216 MB for a million walls).
void encode(const Level& level, OutputFile& file);
void write(const Level& level, const std::filesystem::path& path);  // atomic

// Throws Error("<what>: message") for a truncated, corrupted or wrong-version file.
Level decode(std::span<const uint8_t> bytes, const std::string& what);
Level read(const std::filesystem::path& path);

}  // namespace p3d::level
