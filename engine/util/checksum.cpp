#include "engine/util/checksum.h"

#include <xxhash.h>

#include <new>

namespace p3d {

uint64_t checksum64(std::span<const uint8_t> bytes) { return XXH3_64bits(bytes.data(), bytes.size()); }

Checksum64::Checksum64() : state_(XXH3_createState()) {
  if (!state_) throw std::bad_alloc();
  XXH3_64bits_reset(state_.get());
}

Checksum64::~Checksum64() = default;

void Checksum64::Free::operator()(XXH3_state_s* state) const { XXH3_freeState(state); }

void Checksum64::add(std::span<const uint8_t> bytes) { XXH3_64bits_update(state_.get(), bytes.data(), bytes.size()); }

uint64_t Checksum64::value() const { return XXH3_64bits_digest(state_.get()); }

}  // namespace p3d
