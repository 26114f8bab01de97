// Whole-file reads and atomic writes (temporary file + rename), so that a failed
// tool never leaves a partial output behind.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace p3d {

std::vector<uint8_t> read_file_bytes(const std::filesystem::path& path);
std::string read_file_text(const std::filesystem::path& path);

// Writes to "<path>.tmp-<pid>" in the same directory, then renames over path.
void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes);
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace p3d
