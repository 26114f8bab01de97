// Whole-file reads and atomic writes (temporary file + rename), so that a failed
// tool never leaves a partial output behind.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
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

// A file being written, as a streamed output's writer sees it: bytes appended, and
// bytes already written overwritten (a header's sizes, known at the end). Errors are
// remembered and reported when the file is closed.
class OutputFile {
 public:
  void write(std::span<const uint8_t> bytes);
  void write_at(size_t offset, std::span<const uint8_t> bytes);

 private:
  friend class Outputs;
  explicit OutputFile(std::FILE* f) : f_(f) {}
  std::FILE* f_;
  bool ok_ = true;
};

// Several outputs of one command, all or nothing: every file goes to a temporary
// first, and only when all are written are they renamed into place.
class Outputs {
 public:
  Outputs() = default;
  Outputs(const Outputs&) = delete;
  Outputs& operator=(const Outputs&) = delete;
  ~Outputs();  // a command that did not commit leaves no temporary behind

  using Writer = std::function<void(OutputFile&)>;
  void add(std::filesystem::path path, std::vector<uint8_t> bytes);
  void add(std::filesystem::path path, const std::string& text) { add(std::move(path), std::vector<uint8_t>(text.begin(), text.end())); }
  // A file written piece by piece at commit(), never whole in memory (what `write`
  // reads must outlive the commit).
  void add(std::filesystem::path path, Writer write) { files_.push_back({std::move(path), std::move(write)}); }
  // A file written to its temporary at once, not kept in memory until commit() (which
  // renames it with the rest); throws Error if it cannot be written.
  void write_now(const std::filesystem::path& path, std::span<const uint8_t> bytes);
  // Throws Error (and leaves nothing behind) if any cannot be written.
  void commit();

 private:
  static void write_temporary(const std::filesystem::path& path, const Writer& write);
  void remove_temporaries(size_t files_written);
  std::vector<std::pair<std::filesystem::path, Writer>> files_;
  std::vector<std::filesystem::path> written_;  // write_now's, on disk as temporaries
};

}  // namespace p3d
