#include "engine/util/file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "engine/util/error.h"
#include "engine/util/limits.h"

namespace p3d {

namespace {

std::string errno_text() { return std::strerror(errno); }

// Only regular files are read (a FIFO would block for ever, /dev/zero never ends), and
// none larger than limits::kMaxFileBytes.
void check_readable(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec) throw Error(path.string() + ": cannot open: " + ec.message());
  if (std::filesystem::is_directory(status)) throw Error(path.string() + ": is a directory");
  if (!std::filesystem::is_regular_file(status)) throw Error(path.string() + ": not a regular file (a device, FIFO or socket)");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(path.string() + ": cannot open: " + ec.message());
  if (size > limits::kMaxFileBytes)
    throw Error(path.string() + ": too large (" + std::to_string(size) + " bytes; at most " +
                std::to_string(limits::kMaxFileBytes) + ")");
}

template <typename Container>
Container read_all(const std::filesystem::path& path) {
  check_readable(path);
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw Error(path.string() + ": cannot open: " + errno_text());
  Container data;
  char buffer[1 << 16];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0 && data.size() <= limits::kMaxFileBytes)
    data.insert(data.end(), buffer, buffer + n);
  const bool failed = std::ferror(f);
  std::fclose(f);
  if (failed) throw Error(path.string() + ": read error");
  return data;
}

}  // namespace

std::vector<uint8_t> read_file_bytes(const std::filesystem::path& path) { return read_all<std::vector<uint8_t>>(path); }

std::string read_file_text(const std::filesystem::path& path) { return read_all<std::string>(path); }

MappedFile::MappedFile(const std::filesystem::path& path) {
  check_readable(path);
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) throw Error(path.string() + ": cannot open: " + errno_text());
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    void* map = ::mmap(nullptr, size_t(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (map != MAP_FAILED) {
      data_ = static_cast<const uint8_t*>(map);
      size_ = size_t(st.st_size);
    }
  }
  ::close(fd);
  if (!data_) {
    copy_ = read_file_bytes(path);
    data_ = copy_.data();
    size_ = copy_.size();
  }
}

MappedFile::~MappedFile() {
  if (copy_.empty() && data_) ::munmap(const_cast<uint8_t*>(data_), size_);
}

namespace {

// Renaming over a device, a FIFO or a symbolic link would replace it by a regular file.
void check_replaceable(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw Error(path.string() + ": not a regular file (" +
                (std::filesystem::is_directory(status) ? std::string("a directory")
                 : std::filesystem::is_symlink(status) ? std::string("a symbolic link")
                                                       : std::string("a device, FIFO or socket")) +
                "); refusing to replace it");
}

std::filesystem::path temporary_for(const std::filesystem::path& path) {
  return path.string() + ".tmp-" + std::to_string(::getpid());
}

void rename_temporary(const std::filesystem::path& path) {
  const std::filesystem::path tmp = temporary_for(path);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = errno_text();
    std::remove(tmp.c_str());
    throw Error(path.string() + ": cannot write: " + why);
  }
}

}  // namespace

void OutputFile::write(std::span<const uint8_t> bytes) {
  if (ok_ && !bytes.empty()) ok_ = std::fwrite(bytes.data(), 1, bytes.size(), f_) == bytes.size();
}

void OutputFile::write_at(size_t offset, std::span<const uint8_t> bytes) {
  const long end = std::ftell(f_);
  if (ok_) ok_ = end >= 0 && std::fseek(f_, long(offset), SEEK_SET) == 0;
  write(bytes);
  if (ok_) ok_ = std::fseek(f_, end, SEEK_SET) == 0;
}

// Writes path's temporary; throws (removing it) on failure.
void Outputs::write_temporary(const std::filesystem::path& path, const Writer& write) {
  check_replaceable(path);
  const std::filesystem::path tmp = temporary_for(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw Error(path.string() + ": cannot write: " + errno_text());
  OutputFile out(f);
  try {
    write(out);
  } catch (...) {
    std::fclose(f);
    std::remove(tmp.c_str());
    throw;
  }
  const bool closed = std::fclose(f) == 0;
  if (!out.ok_ || !closed) {
    const std::string why = errno_text();
    std::remove(tmp.c_str());
    throw Error(path.string() + ": cannot write: " + why);
  }
}

void Outputs::add(std::filesystem::path path, std::vector<uint8_t> bytes) {
  add(std::move(path), [bytes = std::move(bytes)](OutputFile& out) { out.write(bytes); });
}

void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> bytes) {
  Outputs outputs;
  outputs.add(path, [bytes](OutputFile& out) { out.write(bytes); });
  outputs.commit();
}

void Outputs::write_now(const std::filesystem::path& path, std::span<const uint8_t> bytes) {
  write_temporary(path, [bytes](OutputFile& out) { out.write(bytes); });
  written_.push_back(path);
}

void Outputs::commit() {
  size_t written = 0;
  try {
    for (; written < files_.size(); ++written) write_temporary(files_[written].first, files_[written].second);
  } catch (...) {
    remove_temporaries(written);
    throw;
  }
  for (const std::filesystem::path& path : written_) rename_temporary(path);
  for (const auto& [path, write] : files_) rename_temporary(path);
  written_.clear();
  files_.clear();
}

// write_now's temporaries, and the first `files_written` of files_'s.
void Outputs::remove_temporaries(size_t files_written) {
  for (const std::filesystem::path& path : written_) std::remove(temporary_for(path).c_str());
  written_.clear();
  for (size_t i = 0; i < files_written; ++i) std::remove(temporary_for(files_[i].first).c_str());
}

Outputs::~Outputs() { remove_temporaries(0); }

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  write_file_atomically(path, std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

}  // namespace p3d
