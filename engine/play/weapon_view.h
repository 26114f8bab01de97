// The player's weapon over the 3D view (Doom's R_DrawPlayerSprites): the weapon and its
// flash, each a sprite frame hung from Doom's 320x200 screen at the psprite's place,
// lit by the sector the player stands in (or full bright, or the powers' fixed light
// map), or drawn as a shadow's fuzz while the player is invisible.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/frame.h"
#include "engine/level/level.h"
#include "engine/play/info.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::play {

struct Player;

// The weapons' sprite frames from the WADs, decoded when first drawn. It keeps its own
// copy of the stack (the lumps' bytes are shared, not copied).
class WeaponArt {
 public:
  explicit WeaponArt(const wad::Stack& wads);

  struct Picture {
    wad::IndexedImage picture;
    bool flipped = false;  // a frame named as the second half of a lump's name is drawn mirrored
  };
  // Doom's rotation-0 frame of the sprite (its lump[0]: rotation 0, else rotation 1),
  // or nullptr when the WADs have none or it is broken.
  const Picture* frame(Sprite sprite, int frame);

  // COLORMAP's maps as palette indices (34 in Doom's: the light levels, the inverse
  // map of invulnerability, black), and PLAYPAL's first palette; empty when missing.
  const std::vector<uint8_t>& colormap() const { return colormap_; }
  const std::vector<uint32_t>& palette() const { return palette_; }

 private:
  std::optional<Picture> find_frame(Sprite sprite, int frame);

  wad::Stack wads_;
  std::vector<std::string> sprite_lumps_;  // the sprite namespace's names, listed when first needed
  bool listed_ = false;
  std::map<int, std::optional<Picture>> frames_;  // by sprite and frame
  std::vector<uint8_t> colormap_;
  std::vector<uint32_t> palette_;
};

// Draws the player's psprites into the view frame as Doom's R_DrawPSprite places them.
// `status_bar_rows` is the height of the status bar below the view (32 times its whole
// scale), or 0 when the view fills the screen. The geometry is Doom's: with the bar,
// the view stands for Doom's 320x168 view (centre row 84) scaled by the bar's factor,
// its bottom on the bar's top and centred across, so that at 320x168 every pixel lands
// where Chocolate Doom puts it; without it, for Doom's full 320x200 view, at the
// largest whole scale that fits, on the frame's bottom; a frame smaller than 320x200
// scales by its width / 320. Indexed frames get palette indices (and their colours),
// others the level's light maps' colours.
void draw_weapon(const Player& player, WeaponArt& art, const level::Level& level, image::Frame& view,
                 int status_bar_rows);

}  // namespace p3d::play
