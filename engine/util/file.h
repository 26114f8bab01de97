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

// A whole file, read-only and memory-mapped, so that only the pages read are loaded
// (a 28 MB IWAD of which a map uses a few hundred KB). Throws Error when it cannot be opened.
class MappedFile {
 public:
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  std::span<const uint8_t> bytes() const { return {data_, size_}; }

 private:
  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
  std::vector<uint8_t> copy_;  // a file that cannot be mapped (empty, or not a regular file) is read
};

// Writes to "<path>.tmp-<pid>" in the same directory, then renames over path.
void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes);
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

// Several outputs of one command, all or nothing: every file goes to a temporary
// first, and only when all are written are they renamed into place.
class Outputs {
 public:
  void add(std::filesystem::path path, std::vector<uint8_t> bytes) { files_.push_back({std::move(path), std::move(bytes)}); }
  void add(std::filesystem::path path, const std::string& text) { add(std::move(path), std::vector<uint8_t>(text.begin(), text.end())); }
  // Throws Error (and leaves nothing behind) if any cannot be written.
  void commit();

 private:
  std::vector<std::pair<std::filesystem::path, std::vector<uint8_t>>> files_;
};

}  // namespace p3d
