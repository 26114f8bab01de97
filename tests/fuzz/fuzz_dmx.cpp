// A sound lump's bytes (Doom's DMX format): decoded, and when accepted mixed for a
// few hundred samples from each side of the listener.
#include "engine/play/sound.h"
#include "engine/util/error.h"
#include "tests/fuzz/target.h"
#include "tests/fuzz/harness.h"

using namespace p3d;

P3D_FUZZ_TARGET(dmx) {
  try {
    const play::SoundClip clip = play::decode_dmx(std::span(data, size), "DSFUZZ");
    uint64_t sum = 0;
    for (uint8_t s : clip.samples) sum += s;
    const play::Listener listener{0, 0, play::Angle(sum * 2654435761u)};
    for (play::Fixed x : {play::to_fixed(-600), play::to_fixed(0), play::to_fixed(900)})
      (void)play::hear(listener, x, play::to_fixed(int(sum % 2000) - 1000));
  } catch (const Error&) {
  }
  return 0;
}
