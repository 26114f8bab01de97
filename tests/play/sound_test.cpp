// Doom's sound effects, decided without a sound card: DMX lumps decoded (and
// broken ones refused with their name), where and how loud a sound is heard, the
// eight channels shared by priority, and every sound lump of Freedoom readable.
#include <gtest/gtest.h>

#include "engine/bsp/load.h"
#include "engine/play/sound.h"
#include "engine/util/error.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

std::vector<uint8_t> dmx(int rate, uint32_t length, size_t bytes_after_header) {
  std::vector<uint8_t> lump = {3, 0, uint8_t(rate), uint8_t(rate >> 8), uint8_t(length), uint8_t(length >> 8),
                               uint8_t(length >> 16), uint8_t(length >> 24)};
  for (size_t i = 0; i < bytes_after_header; ++i) lump.push_back(uint8_t(i));
  return lump;
}

std::string sound_refusal(const std::vector<uint8_t>& lump) {
  try {
    decode_dmx(lump, "DSTEST");
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Sound, DmxLumpsDecodeWithoutTheirPaddingAndBrokenOnesAreRefused) {
  const SoundClip clip = decode_dmx(dmx(11025, 100, 100), "DSTEST");
  EXPECT_EQ(clip.rate, 11025);
  ASSERT_EQ(clip.samples.size(), 68u) << "DMX skips 16 samples at each end";
  EXPECT_EQ(clip.samples.front(), 16);
  EXPECT_EQ(clip.samples.back(), 83);
  EXPECT_EQ(sound_refusal(dmx(11025, 200, 100)), "DSTEST: 200 samples do not fit in 108 bytes");
  EXPECT_EQ(sound_refusal(dmx(11025, 48, 48)), "DSTEST: 48 samples, too short to play");
  EXPECT_EQ(sound_refusal({1, 0, 0}), "DSTEST: not a Doom sound (DMX format 3)");
  EXPECT_EQ(sound_refusal(dmx(0, 100, 100)), "DSTEST: bad sample rate 0");
  EXPECT_EQ(sound_lump_name(Sound::kPistol), "DSPISTOL");
}

TEST(Sound, HeardLouderNearAndFromItsSide) {
  const Listener east{0, 0, 0};  // at the origin, facing east
  const auto ahead = hear(east, to_fixed(100), 0);
  ASSERT_TRUE(ahead);
  EXPECT_EQ(ahead->volume, kMaxVolume) << "within 200 units: full volume";
  EXPECT_NEAR(ahead->separation, kCentre, 1);
  const auto left = hear(east, 0, to_fixed(600)), right = hear(east, 0, to_fixed(-600));
  ASSERT_TRUE(left && right);
  EXPECT_EQ(left->volume, kMaxVolume * (1200 - 600) / 1000) << "fading linearly from 200 to 1200 units";
  EXPECT_EQ(left->separation, kCentre - 96 + 1) << "Doom's stereo swing of 96, sine just short of one";
  EXPECT_GT(right->separation, kCentre + 90);
  EXPECT_FALSE(hear(east, to_fixed(1300), 0)) << "beyond 1200 units: not heard";
  const auto boss = hear(east, to_fixed(3000), 0, kMaxVolume, true);
  ASSERT_TRUE(boss) << "on map 8 every sound carries";
  EXPECT_EQ(boss->volume, 15);
  // Turning to face the sound brings it to the centre.
  const auto facing = hear({0, 0, kAngle90}, 0, to_fixed(600));
  ASSERT_TRUE(facing);
  EXPECT_NEAR(facing->separation, kCentre, 1);
  EXPECT_EQ(linked_volume(Sound::kChgun), kMaxVolume) << "the chaingun's link leaves the volume";
}

TEST(Sound, ChannelsGoByPriorityAndOneSoundAnOrigin) {
  Channels channels;
  for (uint64_t origin = 1; origin <= 8; ++origin) EXPECT_EQ(channels.start(Sound::kPistol, origin), int(origin - 1));
  EXPECT_EQ(channels.start(Sound::kDoropn, 9), -1) << "priority 100 displaces no 64";
  EXPECT_EQ(channels.start(Sound::kGetpow, 9), 0) << "priority 60 takes the first channel of 64";
  EXPECT_EQ(channels[0].sound, Sound::kGetpow);
  EXPECT_EQ(channels.start(Sound::kShotgn, 5), 4) << "an origin's new sound replaces its old one";
  for (int c = 0; c < Channels::kCount; ++c) channels.stop(c);
  EXPECT_EQ(channels.start(Sound::kDoropn, 3), 0);
}

TEST(Sound, EveryFreedoomSoundLumpDecodes) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  int found = 0;
  for (size_t s = 1; s < size_t(Sound::kCount); ++s) {
    const Sound sound = Sound(s);
    if (kSounds[s].link != Sound::kNone) continue;  // played with its link's lump
    const wad::Lump* lump = wads.find(sound_lump_name(sound));
    if (!lump) continue;
    if (lump->bytes.size() < 8) {  // Freedoom's silent placeholders: Doom would not play them either
      EXPECT_EQ(sound_refusal({lump->bytes.begin(), lump->bytes.end()}), "DSTEST: not a Doom sound (DMX format 3)");
      continue;
    }
    ++found;
    const SoundClip clip = decode_dmx(lump->bytes, lump->name);
    EXPECT_GT(clip.samples.size(), 100u) << lump->name;
    EXPECT_GE(clip.rate, 11025) << lump->name;
  }
  EXPECT_GT(found, 90);
}

}  // namespace
}  // namespace p3d::play
