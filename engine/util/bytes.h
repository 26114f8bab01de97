// Little-endian byte encoding with bounds-checked decoding, independent of the
// host's struct layout, plus the FNV-1a checksum of demo files.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "engine/util/error.h"

namespace p3d {

class ByteWriter {
 public:
  ByteWriter() = default;
  // A writer that hands its bytes to `drain` whenever more than `chunk` have piled up
  // (and at flush()), so that a large output is never whole in memory.
  ByteWriter(size_t chunk, std::function<void(std::span<const uint8_t>)> drain)
      : chunk_(chunk), drain_(std::move(drain)) {
    reserve(chunk + chunk / 4);
  }

  void u8(uint8_t v) {
    *room(1) = v;
    drain_if_full();
  }
  void u16(uint16_t v) { put(v); }
  void u32(uint32_t v) { put(v); }
  void i32(int32_t v) { put(static_cast<uint32_t>(v)); }
  void u64(uint64_t v) { put(v); }
  void i64(int64_t v) { put(static_cast<uint64_t>(v)); }
  void f64(double v) { put(std::bit_cast<uint64_t>(v)); }
  void str(const std::string& s) {
    u32(static_cast<uint32_t>(s.size()));
    append(s.data(), s.size());
  }
  void raw(std::span<const uint8_t> bytes) { append(bytes.data(), bytes.size()); }
  // n bytes appended for the caller to fill (bulk data such as texels, written in
  // place); a draining writer hands them on at the next write or flush().
  uint8_t* extend(size_t n) {
    drain_if_full();
    return room(n);
  }
  [[gnu::noinline]] void flush() {  // rare: kept out of the writes it follows
    if (drain_ && used_ > 0) drain_({out_.data(), used_});
    used_ = 0;
  }
  void patch_u64(size_t offset, uint64_t v) {
    for (int i = 0; i < 8; ++i) out_[offset + i] = static_cast<uint8_t>(v >> (8 * i));
  }
  size_t size() const { return used_; }
  // Room for n bytes in all, allocated (and zeroed) at once.
  void reserve(size_t n) {
    if (out_.size() < n) out_.resize(n);
  }
  std::span<const uint8_t> bytes() const { return {out_.data(), used_}; }
  // The bytes written, handed over; the writer starts empty.
  std::vector<uint8_t> release() {
    out_.resize(used_);
    used_ = 0;
    return std::move(out_);
  }

 private:
  template <typename U>
  void put(U v) {
    uint8_t* b = room(sizeof(U));
    if constexpr (std::endian::native == std::endian::little) std::memcpy(b, &v, sizeof(U));
    else
      for (size_t i = 0; i < sizeof(U); ++i) b[i] = static_cast<uint8_t>(v >> (8 * i));
    drain_if_full();
  }
  void append(const void* data, size_t n) {
    if (n == 0) return;
    std::memcpy(room(n), data, n);
    drain_if_full();
  }
  // n bytes at the end, the buffer grown by doubling: out_ is kept at its full length
  // (used_ of it written), so a small write is a memcpy, not a vector resize.
  uint8_t* room(size_t n) {
    if (out_.size() - used_ < n) [[unlikely]]
      grow(n);
    uint8_t* at = out_.data() + used_;
    used_ += n;
    return at;
  }
  [[gnu::noinline]] void grow(size_t n) { out_.resize(std::max(used_ + n, 2 * out_.size())); }
  void drain_if_full() {
    if (drain_ && used_ > chunk_) [[unlikely]]
      flush();
  }
  std::vector<uint8_t> out_;
  size_t used_ = 0;
  size_t chunk_ = 0;
  std::function<void(std::span<const uint8_t>)> drain_;  // empty: keep everything
};

// Every read checks the remaining size and throws Error("<what>: truncated ...").
class ByteReader {
 public:
  ByteReader(std::span<const uint8_t> bytes, std::string what) : bytes_(bytes), what_(std::move(what)) {}

  uint8_t u8() { return static_cast<uint8_t>(get<uint8_t>()); }
  uint16_t u16() { return get<uint16_t>(); }
  uint32_t u32() { return get<uint32_t>(); }
  int32_t i32() { return static_cast<int32_t>(get<uint32_t>()); }
  uint64_t u64() { return get<uint64_t>(); }
  int64_t i64() { return static_cast<int64_t>(get<uint64_t>()); }
  double f64() { return std::bit_cast<double>(get<uint64_t>()); }
  std::string str(size_t max_size) {
    const uint32_t n = u32();
    if (n > max_size) fail("string of " + std::to_string(n) + " bytes is too long");
    need(n);
    std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
    pos_ += n;
    return s;
  }
  std::span<const uint8_t> raw(size_t n) {
    need(n);
    auto s = bytes_.subspan(pos_, n);
    pos_ += n;
    return s;
  }
  // A count of records, each at least min_record_size bytes, that must fit in what is left.
  uint32_t count(size_t min_record_size, const char* name) {
    const uint32_t n = u32();
    if (static_cast<uint64_t>(n) * min_record_size > remaining())
      fail(std::string("truncated: ") + std::to_string(n) + " " + name + " do not fit in the file");
    return n;
  }
  size_t remaining() const { return bytes_.size() - pos_; }
  size_t position() const { return pos_; }
  // Where the reading is, for messages: "section WALL, record 17". Cheap to set per record.
  void at(const char* section, int64_t record = -1) {
    section_ = section;
    record_ = record;
  }
  [[noreturn]] void fail(const std::string& message) const {
    std::string where;
    if (section_) where = std::string("section ") + section_ + (record_ >= 0 ? ", record " + std::to_string(record_) : "") + ": ";
    throw Error(what_ + ": " + where + message);
  }

 private:
  void need(size_t n) const {
    if (n > remaining()) fail("truncated at byte " + std::to_string(pos_));
  }
  template <typename U>
  U get() {
    need(sizeof(U));
    U v = 0;
    for (size_t i = 0; i < sizeof(U); ++i) v |= static_cast<U>(static_cast<U>(bytes_[pos_ + i]) << (8 * i));
    pos_ += sizeof(U);
    return v;
  }
  std::span<const uint8_t> bytes_;
  std::string what_;
  size_t pos_ = 0;
  const char* section_ = nullptr;
  int64_t record_ = -1;
};

// FNV-1a, 64-bit: the checksum of demo files (small; compiled levels use checksum.h).
inline uint64_t fnv1a64(std::span<const uint8_t> bytes) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (uint8_t b : bytes) h = (h ^ b) * 0x100000001b3ull;
  return h;
}

}  // namespace p3d
