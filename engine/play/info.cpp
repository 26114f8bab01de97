// The numbers of Doom's info tables (see info.h). One line per state, one block
// per type of thing, one line per sound.
#include <algorithm>

#include "engine/play/info.h"

namespace p3d::play {

namespace {
using S = StateId;
using enum ThingFlag;
}  // namespace

const char kSpriteNames[size_t(Sprite::kCount)][5] = {
    "TROO", "SHTG", "PUNG", "PISG", "PISF", "SHTF", "SHT2", "CHGG", "CHGF", "MISG", "MISF", "SAWG", "PLSG",
    "PLSF", "BFGG", "BFGF", "BLUD", "PUFF", "BAL1", "BAL2", "PLSS", "PLSE", "MISL", "BFS1", "BFE1", "BFE2",
    "TFOG", "IFOG", "PLAY", "POSS", "SPOS", "VILE", "FIRE", "FATB", "FBXP", "SKEL", "MANF", "FATT", "CPOS",
    "SARG", "HEAD", "BAL7", "BOSS", "BOS2", "SKUL", "SPID", "BSPI", "APLS", "APBX", "CYBR", "PAIN", "SSWV",
    "KEEN", "BBRN", "BOSF", "ARM1", "ARM2", "BAR1", "BEXP", "FCAN", "BON1", "BON2", "BKEY", "RKEY", "YKEY",
    "BSKU", "RSKU", "YSKU", "STIM", "MEDI", "SOUL", "PINV", "PSTR", "PINS", "MEGA", "SUIT", "PMAP", "PVIS",
    "CLIP", "AMMO", "ROCK", "BROK", "CELL", "CELP", "SHEL", "SBOX", "BPAK", "BFUG", "MGUN", "CSAW", "LAUN",
    "PLAS", "SHOT", "SGN2", "COLU", "SMT2", "GOR1", "POL2", "POL5", "POL4", "POL3", "POL1", "POL6", "GOR2",
    "GOR3", "GOR4", "GOR5", "SMIT", "COL1", "COL2", "COL3", "COL4", "CAND", "CBRA", "COL6", "TRE1", "TRE2",
    "ELEC", "CEYE", "FSKU", "COL5", "TBLU", "TGRN", "TRED", "SMBT", "SMGT", "SMRT", "HDB1", "HDB2", "HDB3",
    "HDB4", "HDB5", "HDB6", "POB1", "POB2", "BRS1", "TLMP", "TLP2",
};

const StateInfo kStates[size_t(StateId::kCount)] = {
    // sprite, frame, bright, tics, action, next[, misc1, misc2]            this state
    {Sprite::kTroo, 0, false, -1, Action::kNone, S::kNull},  // kNull
    {Sprite::kShtg, 4, false, 0, Action::kLight0, S::kNull},  // kLightdone
    {Sprite::kPung, 0, false, 1, Action::kWeaponReady, S::kPunch},  // kPunch
    {Sprite::kPung, 0, false, 1, Action::kLower, S::kPunchdown},  // kPunchdown
    {Sprite::kPung, 0, false, 1, Action::kRaise, S::kPunchup},  // kPunchup
    {Sprite::kPung, 1, false, 4, Action::kNone, S::kPunch2},  // kPunch1
    {Sprite::kPung, 2, false, 4, Action::kPunch, S::kPunch3},  // kPunch2
    {Sprite::kPung, 3, false, 5, Action::kNone, S::kPunch4},  // kPunch3
    {Sprite::kPung, 2, false, 4, Action::kNone, S::kPunch5},  // kPunch4
    {Sprite::kPung, 1, false, 5, Action::kReFire, S::kPunch},  // kPunch5
    {Sprite::kPisg, 0, false, 1, Action::kWeaponReady, S::kPistol},  // kPistol
    {Sprite::kPisg, 0, false, 1, Action::kLower, S::kPistoldown},  // kPistoldown
    {Sprite::kPisg, 0, false, 1, Action::kRaise, S::kPistolup},  // kPistolup
    {Sprite::kPisg, 0, false, 4, Action::kNone, S::kPistol2},  // kPistol1
    {Sprite::kPisg, 1, false, 6, Action::kFirePistol, S::kPistol3},  // kPistol2
    {Sprite::kPisg, 2, false, 4, Action::kNone, S::kPistol4},  // kPistol3
    {Sprite::kPisg, 1, false, 5, Action::kReFire, S::kPistol},  // kPistol4
    {Sprite::kPisf, 0, true, 7, Action::kLight1, S::kLightdone},  // kPistolflash
    {Sprite::kShtg, 0, false, 1, Action::kWeaponReady, S::kSgun},  // kSgun
    {Sprite::kShtg, 0, false, 1, Action::kLower, S::kSgundown},  // kSgundown
    {Sprite::kShtg, 0, false, 1, Action::kRaise, S::kSgunup},  // kSgunup
    {Sprite::kShtg, 0, false, 3, Action::kNone, S::kSgun2},  // kSgun1
    {Sprite::kShtg, 0, false, 7, Action::kFireShotgun, S::kSgun3},  // kSgun2
    {Sprite::kShtg, 1, false, 5, Action::kNone, S::kSgun4},  // kSgun3
    {Sprite::kShtg, 2, false, 5, Action::kNone, S::kSgun5},  // kSgun4
    {Sprite::kShtg, 3, false, 4, Action::kNone, S::kSgun6},  // kSgun5
    {Sprite::kShtg, 2, false, 5, Action::kNone, S::kSgun7},  // kSgun6
    {Sprite::kShtg, 1, false, 5, Action::kNone, S::kSgun8},  // kSgun7
    {Sprite::kShtg, 0, false, 3, Action::kNone, S::kSgun9},  // kSgun8
    {Sprite::kShtg, 0, false, 7, Action::kReFire, S::kSgun},  // kSgun9
    {Sprite::kShtf, 0, true, 4, Action::kLight1, S::kSgunflash2},  // kSgunflash1
    {Sprite::kShtf, 1, true, 3, Action::kLight2, S::kLightdone},  // kSgunflash2
    {Sprite::kSht2, 0, false, 1, Action::kWeaponReady, S::kDsgun},  // kDsgun
    {Sprite::kSht2, 0, false, 1, Action::kLower, S::kDsgundown},  // kDsgundown
    {Sprite::kSht2, 0, false, 1, Action::kRaise, S::kDsgunup},  // kDsgunup
    {Sprite::kSht2, 0, false, 3, Action::kNone, S::kDsgun2},  // kDsgun1
    {Sprite::kSht2, 0, false, 7, Action::kFireShotgun2, S::kDsgun3},  // kDsgun2
    {Sprite::kSht2, 1, false, 7, Action::kNone, S::kDsgun4},  // kDsgun3
    {Sprite::kSht2, 2, false, 7, Action::kCheckReload, S::kDsgun5},  // kDsgun4
    {Sprite::kSht2, 3, false, 7, Action::kOpenShotgun2, S::kDsgun6},  // kDsgun5
    {Sprite::kSht2, 4, false, 7, Action::kNone, S::kDsgun7},  // kDsgun6
    {Sprite::kSht2, 5, false, 7, Action::kLoadShotgun2, S::kDsgun8},  // kDsgun7
    {Sprite::kSht2, 6, false, 6, Action::kNone, S::kDsgun9},  // kDsgun8
    {Sprite::kSht2, 7, false, 6, Action::kCloseShotgun2, S::kDsgun10},  // kDsgun9
    {Sprite::kSht2, 0, false, 5, Action::kReFire, S::kDsgun},  // kDsgun10
    {Sprite::kSht2, 1, false, 7, Action::kNone, S::kDsnr2},  // kDsnr1
    {Sprite::kSht2, 0, false, 3, Action::kNone, S::kDsgundown},  // kDsnr2
    {Sprite::kSht2, 8, true, 5, Action::kLight1, S::kDsgunflash2},  // kDsgunflash1
    {Sprite::kSht2, 9, true, 4, Action::kLight2, S::kLightdone},  // kDsgunflash2
    {Sprite::kChgg, 0, false, 1, Action::kWeaponReady, S::kChain},  // kChain
    {Sprite::kChgg, 0, false, 1, Action::kLower, S::kChaindown},  // kChaindown
    {Sprite::kChgg, 0, false, 1, Action::kRaise, S::kChainup},  // kChainup
    {Sprite::kChgg, 0, false, 4, Action::kFireCGun, S::kChain2},  // kChain1
    {Sprite::kChgg, 1, false, 4, Action::kFireCGun, S::kChain3},  // kChain2
    {Sprite::kChgg, 1, false, 0, Action::kReFire, S::kChain},  // kChain3
    {Sprite::kChgf, 0, true, 5, Action::kLight1, S::kLightdone},  // kChainflash1
    {Sprite::kChgf, 1, true, 5, Action::kLight2, S::kLightdone},  // kChainflash2
    {Sprite::kMisg, 0, false, 1, Action::kWeaponReady, S::kMissile},  // kMissile
    {Sprite::kMisg, 0, false, 1, Action::kLower, S::kMissiledown},  // kMissiledown
    {Sprite::kMisg, 0, false, 1, Action::kRaise, S::kMissileup},  // kMissileup
    {Sprite::kMisg, 1, false, 8, Action::kGunFlash, S::kMissile2},  // kMissile1
    {Sprite::kMisg, 1, false, 12, Action::kFireMissile, S::kMissile3},  // kMissile2
    {Sprite::kMisg, 1, false, 0, Action::kReFire, S::kMissile},  // kMissile3
    {Sprite::kMisf, 0, true, 3, Action::kLight1, S::kMissileflash2},  // kMissileflash1
    {Sprite::kMisf, 1, true, 4, Action::kNone, S::kMissileflash3},  // kMissileflash2
    {Sprite::kMisf, 2, true, 4, Action::kLight2, S::kMissileflash4},  // kMissileflash3
    {Sprite::kMisf, 3, true, 4, Action::kLight2, S::kLightdone},  // kMissileflash4
    {Sprite::kSawg, 2, false, 4, Action::kWeaponReady, S::kSawb},  // kSaw
    {Sprite::kSawg, 3, false, 4, Action::kWeaponReady, S::kSaw},  // kSawb
    {Sprite::kSawg, 2, false, 1, Action::kLower, S::kSawdown},  // kSawdown
    {Sprite::kSawg, 2, false, 1, Action::kRaise, S::kSawup},  // kSawup
    {Sprite::kSawg, 0, false, 4, Action::kSaw, S::kSaw2},  // kSaw1
    {Sprite::kSawg, 1, false, 4, Action::kSaw, S::kSaw3},  // kSaw2
    {Sprite::kSawg, 1, false, 0, Action::kReFire, S::kSaw},  // kSaw3
    {Sprite::kPlsg, 0, false, 1, Action::kWeaponReady, S::kPlasma},  // kPlasma
    {Sprite::kPlsg, 0, false, 1, Action::kLower, S::kPlasmadown},  // kPlasmadown
    {Sprite::kPlsg, 0, false, 1, Action::kRaise, S::kPlasmaup},  // kPlasmaup
    {Sprite::kPlsg, 0, false, 3, Action::kFirePlasma, S::kPlasma2},  // kPlasma1
    {Sprite::kPlsg, 1, false, 20, Action::kReFire, S::kPlasma},  // kPlasma2
    {Sprite::kPlsf, 0, true, 4, Action::kLight1, S::kLightdone},  // kPlasmaflash1
    {Sprite::kPlsf, 1, true, 4, Action::kLight1, S::kLightdone},  // kPlasmaflash2
    {Sprite::kBfgg, 0, false, 1, Action::kWeaponReady, S::kBfg},  // kBfg
    {Sprite::kBfgg, 0, false, 1, Action::kLower, S::kBfgdown},  // kBfgdown
    {Sprite::kBfgg, 0, false, 1, Action::kRaise, S::kBfgup},  // kBfgup
    {Sprite::kBfgg, 0, false, 20, Action::kBFGsound, S::kBfg2},  // kBfg1
    {Sprite::kBfgg, 1, false, 10, Action::kGunFlash, S::kBfg3},  // kBfg2
    {Sprite::kBfgg, 1, false, 10, Action::kFireBFG, S::kBfg4},  // kBfg3
    {Sprite::kBfgg, 1, false, 20, Action::kReFire, S::kBfg},  // kBfg4
    {Sprite::kBfgf, 0, true, 11, Action::kLight1, S::kBfgflash2},  // kBfgflash1
    {Sprite::kBfgf, 1, true, 6, Action::kLight2, S::kLightdone},  // kBfgflash2
    {Sprite::kBlud, 2, false, 8, Action::kNone, S::kBlood2},  // kBlood1
    {Sprite::kBlud, 1, false, 8, Action::kNone, S::kBlood3},  // kBlood2
    {Sprite::kBlud, 0, false, 8, Action::kNone, S::kNull},  // kBlood3
    {Sprite::kPuff, 0, true, 4, Action::kNone, S::kPuff2},  // kPuff1
    {Sprite::kPuff, 1, false, 4, Action::kNone, S::kPuff3},  // kPuff2
    {Sprite::kPuff, 2, false, 4, Action::kNone, S::kPuff4},  // kPuff3
    {Sprite::kPuff, 3, false, 4, Action::kNone, S::kNull},  // kPuff4
    {Sprite::kBal1, 0, true, 4, Action::kNone, S::kTball2},  // kTball1
    {Sprite::kBal1, 1, true, 4, Action::kNone, S::kTball1},  // kTball2
    {Sprite::kBal1, 2, true, 6, Action::kNone, S::kTballx2},  // kTballx1
    {Sprite::kBal1, 3, true, 6, Action::kNone, S::kTballx3},  // kTballx2
    {Sprite::kBal1, 4, true, 6, Action::kNone, S::kNull},  // kTballx3
    {Sprite::kBal2, 0, true, 4, Action::kNone, S::kRball2},  // kRball1
    {Sprite::kBal2, 1, true, 4, Action::kNone, S::kRball1},  // kRball2
    {Sprite::kBal2, 2, true, 6, Action::kNone, S::kRballx2},  // kRballx1
    {Sprite::kBal2, 3, true, 6, Action::kNone, S::kRballx3},  // kRballx2
    {Sprite::kBal2, 4, true, 6, Action::kNone, S::kNull},  // kRballx3
    {Sprite::kPlss, 0, true, 6, Action::kNone, S::kPlasball2},  // kPlasball
    {Sprite::kPlss, 1, true, 6, Action::kNone, S::kPlasball},  // kPlasball2
    {Sprite::kPlse, 0, true, 4, Action::kNone, S::kPlasexp2},  // kPlasexp
    {Sprite::kPlse, 1, true, 4, Action::kNone, S::kPlasexp3},  // kPlasexp2
    {Sprite::kPlse, 2, true, 4, Action::kNone, S::kPlasexp4},  // kPlasexp3
    {Sprite::kPlse, 3, true, 4, Action::kNone, S::kPlasexp5},  // kPlasexp4
    {Sprite::kPlse, 4, true, 4, Action::kNone, S::kNull},  // kPlasexp5
    {Sprite::kMisl, 0, true, 1, Action::kNone, S::kRocket},  // kRocket
    {Sprite::kBfs1, 0, true, 4, Action::kNone, S::kBfgshot2},  // kBfgshot
    {Sprite::kBfs1, 1, true, 4, Action::kNone, S::kBfgshot},  // kBfgshot2
    {Sprite::kBfe1, 0, true, 8, Action::kNone, S::kBfgland2},  // kBfgland
    {Sprite::kBfe1, 1, true, 8, Action::kNone, S::kBfgland3},  // kBfgland2
    {Sprite::kBfe1, 2, true, 8, Action::kBFGSpray, S::kBfgland4},  // kBfgland3
    {Sprite::kBfe1, 3, true, 8, Action::kNone, S::kBfgland5},  // kBfgland4
    {Sprite::kBfe1, 4, true, 8, Action::kNone, S::kBfgland6},  // kBfgland5
    {Sprite::kBfe1, 5, true, 8, Action::kNone, S::kNull},  // kBfgland6
    {Sprite::kBfe2, 0, true, 8, Action::kNone, S::kBfgexp2},  // kBfgexp
    {Sprite::kBfe2, 1, true, 8, Action::kNone, S::kBfgexp3},  // kBfgexp2
    {Sprite::kBfe2, 2, true, 8, Action::kNone, S::kBfgexp4},  // kBfgexp3
    {Sprite::kBfe2, 3, true, 8, Action::kNone, S::kNull},  // kBfgexp4
    {Sprite::kMisl, 1, true, 8, Action::kExplode, S::kExplode2},  // kExplode1
    {Sprite::kMisl, 2, true, 6, Action::kNone, S::kExplode3},  // kExplode2
    {Sprite::kMisl, 3, true, 4, Action::kNone, S::kNull},  // kExplode3
    {Sprite::kTfog, 0, true, 6, Action::kNone, S::kTfog01},  // kTfog
    {Sprite::kTfog, 1, true, 6, Action::kNone, S::kTfog02},  // kTfog01
    {Sprite::kTfog, 0, true, 6, Action::kNone, S::kTfog2},  // kTfog02
    {Sprite::kTfog, 1, true, 6, Action::kNone, S::kTfog3},  // kTfog2
    {Sprite::kTfog, 2, true, 6, Action::kNone, S::kTfog4},  // kTfog3
    {Sprite::kTfog, 3, true, 6, Action::kNone, S::kTfog5},  // kTfog4
    {Sprite::kTfog, 4, true, 6, Action::kNone, S::kTfog6},  // kTfog5
    {Sprite::kTfog, 5, true, 6, Action::kNone, S::kTfog7},  // kTfog6
    {Sprite::kTfog, 6, true, 6, Action::kNone, S::kTfog8},  // kTfog7
    {Sprite::kTfog, 7, true, 6, Action::kNone, S::kTfog9},  // kTfog8
    {Sprite::kTfog, 8, true, 6, Action::kNone, S::kTfog10},  // kTfog9
    {Sprite::kTfog, 9, true, 6, Action::kNone, S::kNull},  // kTfog10
    {Sprite::kIfog, 0, true, 6, Action::kNone, S::kIfog01},  // kIfog
    {Sprite::kIfog, 1, true, 6, Action::kNone, S::kIfog02},  // kIfog01
    {Sprite::kIfog, 0, true, 6, Action::kNone, S::kIfog2},  // kIfog02
    {Sprite::kIfog, 1, true, 6, Action::kNone, S::kIfog3},  // kIfog2
    {Sprite::kIfog, 2, true, 6, Action::kNone, S::kIfog4},  // kIfog3
    {Sprite::kIfog, 3, true, 6, Action::kNone, S::kIfog5},  // kIfog4
    {Sprite::kIfog, 4, true, 6, Action::kNone, S::kNull},  // kIfog5
    {Sprite::kPlay, 0, false, -1, Action::kNone, S::kNull},  // kPlay
    {Sprite::kPlay, 0, false, 4, Action::kNone, S::kPlayRun2},  // kPlayRun1
    {Sprite::kPlay, 1, false, 4, Action::kNone, S::kPlayRun3},  // kPlayRun2
    {Sprite::kPlay, 2, false, 4, Action::kNone, S::kPlayRun4},  // kPlayRun3
    {Sprite::kPlay, 3, false, 4, Action::kNone, S::kPlayRun1},  // kPlayRun4
    {Sprite::kPlay, 4, false, 12, Action::kNone, S::kPlay},  // kPlayAtk1
    {Sprite::kPlay, 5, true, 6, Action::kNone, S::kPlayAtk1},  // kPlayAtk2
    {Sprite::kPlay, 6, false, 4, Action::kNone, S::kPlayPain2},  // kPlayPain
    {Sprite::kPlay, 6, false, 4, Action::kPain, S::kPlay},  // kPlayPain2
    {Sprite::kPlay, 7, false, 10, Action::kNone, S::kPlayDie2},  // kPlayDie1
    {Sprite::kPlay, 8, false, 10, Action::kPlayerScream, S::kPlayDie3},  // kPlayDie2
    {Sprite::kPlay, 9, false, 10, Action::kFall, S::kPlayDie4},  // kPlayDie3
    {Sprite::kPlay, 10, false, 10, Action::kNone, S::kPlayDie5},  // kPlayDie4
    {Sprite::kPlay, 11, false, 10, Action::kNone, S::kPlayDie6},  // kPlayDie5
    {Sprite::kPlay, 12, false, 10, Action::kNone, S::kPlayDie7},  // kPlayDie6
    {Sprite::kPlay, 13, false, -1, Action::kNone, S::kNull},  // kPlayDie7
    {Sprite::kPlay, 14, false, 5, Action::kNone, S::kPlayXdie2},  // kPlayXdie1
    {Sprite::kPlay, 15, false, 5, Action::kXScream, S::kPlayXdie3},  // kPlayXdie2
    {Sprite::kPlay, 16, false, 5, Action::kFall, S::kPlayXdie4},  // kPlayXdie3
    {Sprite::kPlay, 17, false, 5, Action::kNone, S::kPlayXdie5},  // kPlayXdie4
    {Sprite::kPlay, 18, false, 5, Action::kNone, S::kPlayXdie6},  // kPlayXdie5
    {Sprite::kPlay, 19, false, 5, Action::kNone, S::kPlayXdie7},  // kPlayXdie6
    {Sprite::kPlay, 20, false, 5, Action::kNone, S::kPlayXdie8},  // kPlayXdie7
    {Sprite::kPlay, 21, false, 5, Action::kNone, S::kPlayXdie9},  // kPlayXdie8
    {Sprite::kPlay, 22, false, -1, Action::kNone, S::kNull},  // kPlayXdie9
    {Sprite::kPoss, 0, false, 10, Action::kLook, S::kPossStnd2},  // kPossStnd
    {Sprite::kPoss, 1, false, 10, Action::kLook, S::kPossStnd},  // kPossStnd2
    {Sprite::kPoss, 0, false, 4, Action::kChase, S::kPossRun2},  // kPossRun1
    {Sprite::kPoss, 0, false, 4, Action::kChase, S::kPossRun3},  // kPossRun2
    {Sprite::kPoss, 1, false, 4, Action::kChase, S::kPossRun4},  // kPossRun3
    {Sprite::kPoss, 1, false, 4, Action::kChase, S::kPossRun5},  // kPossRun4
    {Sprite::kPoss, 2, false, 4, Action::kChase, S::kPossRun6},  // kPossRun5
    {Sprite::kPoss, 2, false, 4, Action::kChase, S::kPossRun7},  // kPossRun6
    {Sprite::kPoss, 3, false, 4, Action::kChase, S::kPossRun8},  // kPossRun7
    {Sprite::kPoss, 3, false, 4, Action::kChase, S::kPossRun1},  // kPossRun8
    {Sprite::kPoss, 4, false, 10, Action::kFaceTarget, S::kPossAtk2},  // kPossAtk1
    {Sprite::kPoss, 5, false, 8, Action::kPosAttack, S::kPossAtk3},  // kPossAtk2
    {Sprite::kPoss, 4, false, 8, Action::kNone, S::kPossRun1},  // kPossAtk3
    {Sprite::kPoss, 6, false, 3, Action::kNone, S::kPossPain2},  // kPossPain
    {Sprite::kPoss, 6, false, 3, Action::kPain, S::kPossRun1},  // kPossPain2
    {Sprite::kPoss, 7, false, 5, Action::kNone, S::kPossDie2},  // kPossDie1
    {Sprite::kPoss, 8, false, 5, Action::kScream, S::kPossDie3},  // kPossDie2
    {Sprite::kPoss, 9, false, 5, Action::kFall, S::kPossDie4},  // kPossDie3
    {Sprite::kPoss, 10, false, 5, Action::kNone, S::kPossDie5},  // kPossDie4
    {Sprite::kPoss, 11, false, -1, Action::kNone, S::kNull},  // kPossDie5
    {Sprite::kPoss, 12, false, 5, Action::kNone, S::kPossXdie2},  // kPossXdie1
    {Sprite::kPoss, 13, false, 5, Action::kXScream, S::kPossXdie3},  // kPossXdie2
    {Sprite::kPoss, 14, false, 5, Action::kFall, S::kPossXdie4},  // kPossXdie3
    {Sprite::kPoss, 15, false, 5, Action::kNone, S::kPossXdie5},  // kPossXdie4
    {Sprite::kPoss, 16, false, 5, Action::kNone, S::kPossXdie6},  // kPossXdie5
    {Sprite::kPoss, 17, false, 5, Action::kNone, S::kPossXdie7},  // kPossXdie6
    {Sprite::kPoss, 18, false, 5, Action::kNone, S::kPossXdie8},  // kPossXdie7
    {Sprite::kPoss, 19, false, 5, Action::kNone, S::kPossXdie9},  // kPossXdie8
    {Sprite::kPoss, 20, false, -1, Action::kNone, S::kNull},  // kPossXdie9
    {Sprite::kPoss, 10, false, 5, Action::kNone, S::kPossRaise2},  // kPossRaise1
    {Sprite::kPoss, 9, false, 5, Action::kNone, S::kPossRaise3},  // kPossRaise2
    {Sprite::kPoss, 8, false, 5, Action::kNone, S::kPossRaise4},  // kPossRaise3
    {Sprite::kPoss, 7, false, 5, Action::kNone, S::kPossRun1},  // kPossRaise4
    {Sprite::kSpos, 0, false, 10, Action::kLook, S::kSposStnd2},  // kSposStnd
    {Sprite::kSpos, 1, false, 10, Action::kLook, S::kSposStnd},  // kSposStnd2
    {Sprite::kSpos, 0, false, 3, Action::kChase, S::kSposRun2},  // kSposRun1
    {Sprite::kSpos, 0, false, 3, Action::kChase, S::kSposRun3},  // kSposRun2
    {Sprite::kSpos, 1, false, 3, Action::kChase, S::kSposRun4},  // kSposRun3
    {Sprite::kSpos, 1, false, 3, Action::kChase, S::kSposRun5},  // kSposRun4
    {Sprite::kSpos, 2, false, 3, Action::kChase, S::kSposRun6},  // kSposRun5
    {Sprite::kSpos, 2, false, 3, Action::kChase, S::kSposRun7},  // kSposRun6
    {Sprite::kSpos, 3, false, 3, Action::kChase, S::kSposRun8},  // kSposRun7
    {Sprite::kSpos, 3, false, 3, Action::kChase, S::kSposRun1},  // kSposRun8
    {Sprite::kSpos, 4, false, 10, Action::kFaceTarget, S::kSposAtk2},  // kSposAtk1
    {Sprite::kSpos, 5, true, 10, Action::kSPosAttack, S::kSposAtk3},  // kSposAtk2
    {Sprite::kSpos, 4, false, 10, Action::kNone, S::kSposRun1},  // kSposAtk3
    {Sprite::kSpos, 6, false, 3, Action::kNone, S::kSposPain2},  // kSposPain
    {Sprite::kSpos, 6, false, 3, Action::kPain, S::kSposRun1},  // kSposPain2
    {Sprite::kSpos, 7, false, 5, Action::kNone, S::kSposDie2},  // kSposDie1
    {Sprite::kSpos, 8, false, 5, Action::kScream, S::kSposDie3},  // kSposDie2
    {Sprite::kSpos, 9, false, 5, Action::kFall, S::kSposDie4},  // kSposDie3
    {Sprite::kSpos, 10, false, 5, Action::kNone, S::kSposDie5},  // kSposDie4
    {Sprite::kSpos, 11, false, -1, Action::kNone, S::kNull},  // kSposDie5
    {Sprite::kSpos, 12, false, 5, Action::kNone, S::kSposXdie2},  // kSposXdie1
    {Sprite::kSpos, 13, false, 5, Action::kXScream, S::kSposXdie3},  // kSposXdie2
    {Sprite::kSpos, 14, false, 5, Action::kFall, S::kSposXdie4},  // kSposXdie3
    {Sprite::kSpos, 15, false, 5, Action::kNone, S::kSposXdie5},  // kSposXdie4
    {Sprite::kSpos, 16, false, 5, Action::kNone, S::kSposXdie6},  // kSposXdie5
    {Sprite::kSpos, 17, false, 5, Action::kNone, S::kSposXdie7},  // kSposXdie6
    {Sprite::kSpos, 18, false, 5, Action::kNone, S::kSposXdie8},  // kSposXdie7
    {Sprite::kSpos, 19, false, 5, Action::kNone, S::kSposXdie9},  // kSposXdie8
    {Sprite::kSpos, 20, false, -1, Action::kNone, S::kNull},  // kSposXdie9
    {Sprite::kSpos, 11, false, 5, Action::kNone, S::kSposRaise2},  // kSposRaise1
    {Sprite::kSpos, 10, false, 5, Action::kNone, S::kSposRaise3},  // kSposRaise2
    {Sprite::kSpos, 9, false, 5, Action::kNone, S::kSposRaise4},  // kSposRaise3
    {Sprite::kSpos, 8, false, 5, Action::kNone, S::kSposRaise5},  // kSposRaise4
    {Sprite::kSpos, 7, false, 5, Action::kNone, S::kSposRun1},  // kSposRaise5
    {Sprite::kVile, 0, false, 10, Action::kLook, S::kVileStnd2},  // kVileStnd
    {Sprite::kVile, 1, false, 10, Action::kLook, S::kVileStnd},  // kVileStnd2
    {Sprite::kVile, 0, false, 2, Action::kVileChase, S::kVileRun2},  // kVileRun1
    {Sprite::kVile, 0, false, 2, Action::kVileChase, S::kVileRun3},  // kVileRun2
    {Sprite::kVile, 1, false, 2, Action::kVileChase, S::kVileRun4},  // kVileRun3
    {Sprite::kVile, 1, false, 2, Action::kVileChase, S::kVileRun5},  // kVileRun4
    {Sprite::kVile, 2, false, 2, Action::kVileChase, S::kVileRun6},  // kVileRun5
    {Sprite::kVile, 2, false, 2, Action::kVileChase, S::kVileRun7},  // kVileRun6
    {Sprite::kVile, 3, false, 2, Action::kVileChase, S::kVileRun8},  // kVileRun7
    {Sprite::kVile, 3, false, 2, Action::kVileChase, S::kVileRun9},  // kVileRun8
    {Sprite::kVile, 4, false, 2, Action::kVileChase, S::kVileRun10},  // kVileRun9
    {Sprite::kVile, 4, false, 2, Action::kVileChase, S::kVileRun11},  // kVileRun10
    {Sprite::kVile, 5, false, 2, Action::kVileChase, S::kVileRun12},  // kVileRun11
    {Sprite::kVile, 5, false, 2, Action::kVileChase, S::kVileRun1},  // kVileRun12
    {Sprite::kVile, 6, true, 0, Action::kVileStart, S::kVileAtk2},  // kVileAtk1
    {Sprite::kVile, 6, true, 10, Action::kFaceTarget, S::kVileAtk3},  // kVileAtk2
    {Sprite::kVile, 7, true, 8, Action::kVileTarget, S::kVileAtk4},  // kVileAtk3
    {Sprite::kVile, 8, true, 8, Action::kFaceTarget, S::kVileAtk5},  // kVileAtk4
    {Sprite::kVile, 9, true, 8, Action::kFaceTarget, S::kVileAtk6},  // kVileAtk5
    {Sprite::kVile, 10, true, 8, Action::kFaceTarget, S::kVileAtk7},  // kVileAtk6
    {Sprite::kVile, 11, true, 8, Action::kFaceTarget, S::kVileAtk8},  // kVileAtk7
    {Sprite::kVile, 12, true, 8, Action::kFaceTarget, S::kVileAtk9},  // kVileAtk8
    {Sprite::kVile, 13, true, 8, Action::kFaceTarget, S::kVileAtk10},  // kVileAtk9
    {Sprite::kVile, 14, true, 8, Action::kVileAttack, S::kVileAtk11},  // kVileAtk10
    {Sprite::kVile, 15, true, 20, Action::kNone, S::kVileRun1},  // kVileAtk11
    {Sprite::kVile, 26, true, 10, Action::kNone, S::kVileHeal2},  // kVileHeal1
    {Sprite::kVile, 27, true, 10, Action::kNone, S::kVileHeal3},  // kVileHeal2
    {Sprite::kVile, 28, true, 10, Action::kNone, S::kVileRun1},  // kVileHeal3
    {Sprite::kVile, 16, false, 5, Action::kNone, S::kVilePain2},  // kVilePain
    {Sprite::kVile, 16, false, 5, Action::kPain, S::kVileRun1},  // kVilePain2
    {Sprite::kVile, 16, false, 7, Action::kNone, S::kVileDie2},  // kVileDie1
    {Sprite::kVile, 17, false, 7, Action::kScream, S::kVileDie3},  // kVileDie2
    {Sprite::kVile, 18, false, 7, Action::kFall, S::kVileDie4},  // kVileDie3
    {Sprite::kVile, 19, false, 7, Action::kNone, S::kVileDie5},  // kVileDie4
    {Sprite::kVile, 20, false, 7, Action::kNone, S::kVileDie6},  // kVileDie5
    {Sprite::kVile, 21, false, 7, Action::kNone, S::kVileDie7},  // kVileDie6
    {Sprite::kVile, 22, false, 7, Action::kNone, S::kVileDie8},  // kVileDie7
    {Sprite::kVile, 23, false, 5, Action::kNone, S::kVileDie9},  // kVileDie8
    {Sprite::kVile, 24, false, 5, Action::kNone, S::kVileDie10},  // kVileDie9
    {Sprite::kVile, 25, false, -1, Action::kNone, S::kNull},  // kVileDie10
    {Sprite::kFire, 0, true, 2, Action::kStartFire, S::kFire2},  // kFire1
    {Sprite::kFire, 1, true, 2, Action::kFire, S::kFire3},  // kFire2
    {Sprite::kFire, 0, true, 2, Action::kFire, S::kFire4},  // kFire3
    {Sprite::kFire, 1, true, 2, Action::kFire, S::kFire5},  // kFire4
    {Sprite::kFire, 2, true, 2, Action::kFireCrackle, S::kFire6},  // kFire5
    {Sprite::kFire, 1, true, 2, Action::kFire, S::kFire7},  // kFire6
    {Sprite::kFire, 2, true, 2, Action::kFire, S::kFire8},  // kFire7
    {Sprite::kFire, 1, true, 2, Action::kFire, S::kFire9},  // kFire8
    {Sprite::kFire, 2, true, 2, Action::kFire, S::kFire10},  // kFire9
    {Sprite::kFire, 3, true, 2, Action::kFire, S::kFire11},  // kFire10
    {Sprite::kFire, 2, true, 2, Action::kFire, S::kFire12},  // kFire11
    {Sprite::kFire, 3, true, 2, Action::kFire, S::kFire13},  // kFire12
    {Sprite::kFire, 2, true, 2, Action::kFire, S::kFire14},  // kFire13
    {Sprite::kFire, 3, true, 2, Action::kFire, S::kFire15},  // kFire14
    {Sprite::kFire, 4, true, 2, Action::kFire, S::kFire16},  // kFire15
    {Sprite::kFire, 3, true, 2, Action::kFire, S::kFire17},  // kFire16
    {Sprite::kFire, 4, true, 2, Action::kFire, S::kFire18},  // kFire17
    {Sprite::kFire, 3, true, 2, Action::kFire, S::kFire19},  // kFire18
    {Sprite::kFire, 4, true, 2, Action::kFireCrackle, S::kFire20},  // kFire19
    {Sprite::kFire, 5, true, 2, Action::kFire, S::kFire21},  // kFire20
    {Sprite::kFire, 4, true, 2, Action::kFire, S::kFire22},  // kFire21
    {Sprite::kFire, 5, true, 2, Action::kFire, S::kFire23},  // kFire22
    {Sprite::kFire, 4, true, 2, Action::kFire, S::kFire24},  // kFire23
    {Sprite::kFire, 5, true, 2, Action::kFire, S::kFire25},  // kFire24
    {Sprite::kFire, 6, true, 2, Action::kFire, S::kFire26},  // kFire25
    {Sprite::kFire, 7, true, 2, Action::kFire, S::kFire27},  // kFire26
    {Sprite::kFire, 6, true, 2, Action::kFire, S::kFire28},  // kFire27
    {Sprite::kFire, 7, true, 2, Action::kFire, S::kFire29},  // kFire28
    {Sprite::kFire, 6, true, 2, Action::kFire, S::kFire30},  // kFire29
    {Sprite::kFire, 7, true, 2, Action::kFire, S::kNull},  // kFire30
    {Sprite::kPuff, 1, false, 4, Action::kNone, S::kSmoke2},  // kSmoke1
    {Sprite::kPuff, 2, false, 4, Action::kNone, S::kSmoke3},  // kSmoke2
    {Sprite::kPuff, 1, false, 4, Action::kNone, S::kSmoke4},  // kSmoke3
    {Sprite::kPuff, 2, false, 4, Action::kNone, S::kSmoke5},  // kSmoke4
    {Sprite::kPuff, 3, false, 4, Action::kNone, S::kNull},  // kSmoke5
    {Sprite::kFatb, 0, true, 2, Action::kTracer, S::kTracer2},  // kTracer
    {Sprite::kFatb, 1, true, 2, Action::kTracer, S::kTracer},  // kTracer2
    {Sprite::kFbxp, 0, true, 8, Action::kNone, S::kTraceexp2},  // kTraceexp1
    {Sprite::kFbxp, 1, true, 6, Action::kNone, S::kTraceexp3},  // kTraceexp2
    {Sprite::kFbxp, 2, true, 4, Action::kNone, S::kNull},  // kTraceexp3
    {Sprite::kSkel, 0, false, 10, Action::kLook, S::kSkelStnd2},  // kSkelStnd
    {Sprite::kSkel, 1, false, 10, Action::kLook, S::kSkelStnd},  // kSkelStnd2
    {Sprite::kSkel, 0, false, 2, Action::kChase, S::kSkelRun2},  // kSkelRun1
    {Sprite::kSkel, 0, false, 2, Action::kChase, S::kSkelRun3},  // kSkelRun2
    {Sprite::kSkel, 1, false, 2, Action::kChase, S::kSkelRun4},  // kSkelRun3
    {Sprite::kSkel, 1, false, 2, Action::kChase, S::kSkelRun5},  // kSkelRun4
    {Sprite::kSkel, 2, false, 2, Action::kChase, S::kSkelRun6},  // kSkelRun5
    {Sprite::kSkel, 2, false, 2, Action::kChase, S::kSkelRun7},  // kSkelRun6
    {Sprite::kSkel, 3, false, 2, Action::kChase, S::kSkelRun8},  // kSkelRun7
    {Sprite::kSkel, 3, false, 2, Action::kChase, S::kSkelRun9},  // kSkelRun8
    {Sprite::kSkel, 4, false, 2, Action::kChase, S::kSkelRun10},  // kSkelRun9
    {Sprite::kSkel, 4, false, 2, Action::kChase, S::kSkelRun11},  // kSkelRun10
    {Sprite::kSkel, 5, false, 2, Action::kChase, S::kSkelRun12},  // kSkelRun11
    {Sprite::kSkel, 5, false, 2, Action::kChase, S::kSkelRun1},  // kSkelRun12
    {Sprite::kSkel, 6, false, 0, Action::kFaceTarget, S::kSkelFist2},  // kSkelFist1
    {Sprite::kSkel, 6, false, 6, Action::kSkelWhoosh, S::kSkelFist3},  // kSkelFist2
    {Sprite::kSkel, 7, false, 6, Action::kFaceTarget, S::kSkelFist4},  // kSkelFist3
    {Sprite::kSkel, 8, false, 6, Action::kSkelFist, S::kSkelRun1},  // kSkelFist4
    {Sprite::kSkel, 9, true, 0, Action::kFaceTarget, S::kSkelMiss2},  // kSkelMiss1
    {Sprite::kSkel, 9, true, 10, Action::kFaceTarget, S::kSkelMiss3},  // kSkelMiss2
    {Sprite::kSkel, 10, false, 10, Action::kSkelMissile, S::kSkelMiss4},  // kSkelMiss3
    {Sprite::kSkel, 10, false, 10, Action::kFaceTarget, S::kSkelRun1},  // kSkelMiss4
    {Sprite::kSkel, 11, false, 5, Action::kNone, S::kSkelPain2},  // kSkelPain
    {Sprite::kSkel, 11, false, 5, Action::kPain, S::kSkelRun1},  // kSkelPain2
    {Sprite::kSkel, 11, false, 7, Action::kNone, S::kSkelDie2},  // kSkelDie1
    {Sprite::kSkel, 12, false, 7, Action::kNone, S::kSkelDie3},  // kSkelDie2
    {Sprite::kSkel, 13, false, 7, Action::kScream, S::kSkelDie4},  // kSkelDie3
    {Sprite::kSkel, 14, false, 7, Action::kFall, S::kSkelDie5},  // kSkelDie4
    {Sprite::kSkel, 15, false, 7, Action::kNone, S::kSkelDie6},  // kSkelDie5
    {Sprite::kSkel, 16, false, -1, Action::kNone, S::kNull},  // kSkelDie6
    {Sprite::kSkel, 16, false, 5, Action::kNone, S::kSkelRaise2},  // kSkelRaise1
    {Sprite::kSkel, 15, false, 5, Action::kNone, S::kSkelRaise3},  // kSkelRaise2
    {Sprite::kSkel, 14, false, 5, Action::kNone, S::kSkelRaise4},  // kSkelRaise3
    {Sprite::kSkel, 13, false, 5, Action::kNone, S::kSkelRaise5},  // kSkelRaise4
    {Sprite::kSkel, 12, false, 5, Action::kNone, S::kSkelRaise6},  // kSkelRaise5
    {Sprite::kSkel, 11, false, 5, Action::kNone, S::kSkelRun1},  // kSkelRaise6
    {Sprite::kManf, 0, true, 4, Action::kNone, S::kFatshot2},  // kFatshot1
    {Sprite::kManf, 1, true, 4, Action::kNone, S::kFatshot1},  // kFatshot2
    {Sprite::kMisl, 1, true, 8, Action::kNone, S::kFatshotx2},  // kFatshotx1
    {Sprite::kMisl, 2, true, 6, Action::kNone, S::kFatshotx3},  // kFatshotx2
    {Sprite::kMisl, 3, true, 4, Action::kNone, S::kNull},  // kFatshotx3
    {Sprite::kFatt, 0, false, 15, Action::kLook, S::kFattStnd2},  // kFattStnd
    {Sprite::kFatt, 1, false, 15, Action::kLook, S::kFattStnd},  // kFattStnd2
    {Sprite::kFatt, 0, false, 4, Action::kChase, S::kFattRun2},  // kFattRun1
    {Sprite::kFatt, 0, false, 4, Action::kChase, S::kFattRun3},  // kFattRun2
    {Sprite::kFatt, 1, false, 4, Action::kChase, S::kFattRun4},  // kFattRun3
    {Sprite::kFatt, 1, false, 4, Action::kChase, S::kFattRun5},  // kFattRun4
    {Sprite::kFatt, 2, false, 4, Action::kChase, S::kFattRun6},  // kFattRun5
    {Sprite::kFatt, 2, false, 4, Action::kChase, S::kFattRun7},  // kFattRun6
    {Sprite::kFatt, 3, false, 4, Action::kChase, S::kFattRun8},  // kFattRun7
    {Sprite::kFatt, 3, false, 4, Action::kChase, S::kFattRun9},  // kFattRun8
    {Sprite::kFatt, 4, false, 4, Action::kChase, S::kFattRun10},  // kFattRun9
    {Sprite::kFatt, 4, false, 4, Action::kChase, S::kFattRun11},  // kFattRun10
    {Sprite::kFatt, 5, false, 4, Action::kChase, S::kFattRun12},  // kFattRun11
    {Sprite::kFatt, 5, false, 4, Action::kChase, S::kFattRun1},  // kFattRun12
    {Sprite::kFatt, 6, false, 20, Action::kFatRaise, S::kFattAtk2},  // kFattAtk1
    {Sprite::kFatt, 7, true, 10, Action::kFatAttack1, S::kFattAtk3},  // kFattAtk2
    {Sprite::kFatt, 8, false, 5, Action::kFaceTarget, S::kFattAtk4},  // kFattAtk3
    {Sprite::kFatt, 6, false, 5, Action::kFaceTarget, S::kFattAtk5},  // kFattAtk4
    {Sprite::kFatt, 7, true, 10, Action::kFatAttack2, S::kFattAtk6},  // kFattAtk5
    {Sprite::kFatt, 8, false, 5, Action::kFaceTarget, S::kFattAtk7},  // kFattAtk6
    {Sprite::kFatt, 6, false, 5, Action::kFaceTarget, S::kFattAtk8},  // kFattAtk7
    {Sprite::kFatt, 7, true, 10, Action::kFatAttack3, S::kFattAtk9},  // kFattAtk8
    {Sprite::kFatt, 8, false, 5, Action::kFaceTarget, S::kFattAtk10},  // kFattAtk9
    {Sprite::kFatt, 6, false, 5, Action::kFaceTarget, S::kFattRun1},  // kFattAtk10
    {Sprite::kFatt, 9, false, 3, Action::kNone, S::kFattPain2},  // kFattPain
    {Sprite::kFatt, 9, false, 3, Action::kPain, S::kFattRun1},  // kFattPain2
    {Sprite::kFatt, 10, false, 6, Action::kNone, S::kFattDie2},  // kFattDie1
    {Sprite::kFatt, 11, false, 6, Action::kScream, S::kFattDie3},  // kFattDie2
    {Sprite::kFatt, 12, false, 6, Action::kFall, S::kFattDie4},  // kFattDie3
    {Sprite::kFatt, 13, false, 6, Action::kNone, S::kFattDie5},  // kFattDie4
    {Sprite::kFatt, 14, false, 6, Action::kNone, S::kFattDie6},  // kFattDie5
    {Sprite::kFatt, 15, false, 6, Action::kNone, S::kFattDie7},  // kFattDie6
    {Sprite::kFatt, 16, false, 6, Action::kNone, S::kFattDie8},  // kFattDie7
    {Sprite::kFatt, 17, false, 6, Action::kNone, S::kFattDie9},  // kFattDie8
    {Sprite::kFatt, 18, false, 6, Action::kNone, S::kFattDie10},  // kFattDie9
    {Sprite::kFatt, 19, false, -1, Action::kBossDeath, S::kNull},  // kFattDie10
    {Sprite::kFatt, 17, false, 5, Action::kNone, S::kFattRaise2},  // kFattRaise1
    {Sprite::kFatt, 16, false, 5, Action::kNone, S::kFattRaise3},  // kFattRaise2
    {Sprite::kFatt, 15, false, 5, Action::kNone, S::kFattRaise4},  // kFattRaise3
    {Sprite::kFatt, 14, false, 5, Action::kNone, S::kFattRaise5},  // kFattRaise4
    {Sprite::kFatt, 13, false, 5, Action::kNone, S::kFattRaise6},  // kFattRaise5
    {Sprite::kFatt, 12, false, 5, Action::kNone, S::kFattRaise7},  // kFattRaise6
    {Sprite::kFatt, 11, false, 5, Action::kNone, S::kFattRaise8},  // kFattRaise7
    {Sprite::kFatt, 10, false, 5, Action::kNone, S::kFattRun1},  // kFattRaise8
    {Sprite::kCpos, 0, false, 10, Action::kLook, S::kCposStnd2},  // kCposStnd
    {Sprite::kCpos, 1, false, 10, Action::kLook, S::kCposStnd},  // kCposStnd2
    {Sprite::kCpos, 0, false, 3, Action::kChase, S::kCposRun2},  // kCposRun1
    {Sprite::kCpos, 0, false, 3, Action::kChase, S::kCposRun3},  // kCposRun2
    {Sprite::kCpos, 1, false, 3, Action::kChase, S::kCposRun4},  // kCposRun3
    {Sprite::kCpos, 1, false, 3, Action::kChase, S::kCposRun5},  // kCposRun4
    {Sprite::kCpos, 2, false, 3, Action::kChase, S::kCposRun6},  // kCposRun5
    {Sprite::kCpos, 2, false, 3, Action::kChase, S::kCposRun7},  // kCposRun6
    {Sprite::kCpos, 3, false, 3, Action::kChase, S::kCposRun8},  // kCposRun7
    {Sprite::kCpos, 3, false, 3, Action::kChase, S::kCposRun1},  // kCposRun8
    {Sprite::kCpos, 4, false, 10, Action::kFaceTarget, S::kCposAtk2},  // kCposAtk1
    {Sprite::kCpos, 5, true, 4, Action::kCPosAttack, S::kCposAtk3},  // kCposAtk2
    {Sprite::kCpos, 4, true, 4, Action::kCPosAttack, S::kCposAtk4},  // kCposAtk3
    {Sprite::kCpos, 5, false, 1, Action::kCPosRefire, S::kCposAtk2},  // kCposAtk4
    {Sprite::kCpos, 6, false, 3, Action::kNone, S::kCposPain2},  // kCposPain
    {Sprite::kCpos, 6, false, 3, Action::kPain, S::kCposRun1},  // kCposPain2
    {Sprite::kCpos, 7, false, 5, Action::kNone, S::kCposDie2},  // kCposDie1
    {Sprite::kCpos, 8, false, 5, Action::kScream, S::kCposDie3},  // kCposDie2
    {Sprite::kCpos, 9, false, 5, Action::kFall, S::kCposDie4},  // kCposDie3
    {Sprite::kCpos, 10, false, 5, Action::kNone, S::kCposDie5},  // kCposDie4
    {Sprite::kCpos, 11, false, 5, Action::kNone, S::kCposDie6},  // kCposDie5
    {Sprite::kCpos, 12, false, 5, Action::kNone, S::kCposDie7},  // kCposDie6
    {Sprite::kCpos, 13, false, -1, Action::kNone, S::kNull},  // kCposDie7
    {Sprite::kCpos, 14, false, 5, Action::kNone, S::kCposXdie2},  // kCposXdie1
    {Sprite::kCpos, 15, false, 5, Action::kXScream, S::kCposXdie3},  // kCposXdie2
    {Sprite::kCpos, 16, false, 5, Action::kFall, S::kCposXdie4},  // kCposXdie3
    {Sprite::kCpos, 17, false, 5, Action::kNone, S::kCposXdie5},  // kCposXdie4
    {Sprite::kCpos, 18, false, 5, Action::kNone, S::kCposXdie6},  // kCposXdie5
    {Sprite::kCpos, 19, false, -1, Action::kNone, S::kNull},  // kCposXdie6
    {Sprite::kCpos, 13, false, 5, Action::kNone, S::kCposRaise2},  // kCposRaise1
    {Sprite::kCpos, 12, false, 5, Action::kNone, S::kCposRaise3},  // kCposRaise2
    {Sprite::kCpos, 11, false, 5, Action::kNone, S::kCposRaise4},  // kCposRaise3
    {Sprite::kCpos, 10, false, 5, Action::kNone, S::kCposRaise5},  // kCposRaise4
    {Sprite::kCpos, 9, false, 5, Action::kNone, S::kCposRaise6},  // kCposRaise5
    {Sprite::kCpos, 8, false, 5, Action::kNone, S::kCposRaise7},  // kCposRaise6
    {Sprite::kCpos, 7, false, 5, Action::kNone, S::kCposRun1},  // kCposRaise7
    {Sprite::kTroo, 0, false, 10, Action::kLook, S::kTrooStnd2},  // kTrooStnd
    {Sprite::kTroo, 1, false, 10, Action::kLook, S::kTrooStnd},  // kTrooStnd2
    {Sprite::kTroo, 0, false, 3, Action::kChase, S::kTrooRun2},  // kTrooRun1
    {Sprite::kTroo, 0, false, 3, Action::kChase, S::kTrooRun3},  // kTrooRun2
    {Sprite::kTroo, 1, false, 3, Action::kChase, S::kTrooRun4},  // kTrooRun3
    {Sprite::kTroo, 1, false, 3, Action::kChase, S::kTrooRun5},  // kTrooRun4
    {Sprite::kTroo, 2, false, 3, Action::kChase, S::kTrooRun6},  // kTrooRun5
    {Sprite::kTroo, 2, false, 3, Action::kChase, S::kTrooRun7},  // kTrooRun6
    {Sprite::kTroo, 3, false, 3, Action::kChase, S::kTrooRun8},  // kTrooRun7
    {Sprite::kTroo, 3, false, 3, Action::kChase, S::kTrooRun1},  // kTrooRun8
    {Sprite::kTroo, 4, false, 8, Action::kFaceTarget, S::kTrooAtk2},  // kTrooAtk1
    {Sprite::kTroo, 5, false, 8, Action::kFaceTarget, S::kTrooAtk3},  // kTrooAtk2
    {Sprite::kTroo, 6, false, 6, Action::kTroopAttack, S::kTrooRun1},  // kTrooAtk3
    {Sprite::kTroo, 7, false, 2, Action::kNone, S::kTrooPain2},  // kTrooPain
    {Sprite::kTroo, 7, false, 2, Action::kPain, S::kTrooRun1},  // kTrooPain2
    {Sprite::kTroo, 8, false, 8, Action::kNone, S::kTrooDie2},  // kTrooDie1
    {Sprite::kTroo, 9, false, 8, Action::kScream, S::kTrooDie3},  // kTrooDie2
    {Sprite::kTroo, 10, false, 6, Action::kNone, S::kTrooDie4},  // kTrooDie3
    {Sprite::kTroo, 11, false, 6, Action::kFall, S::kTrooDie5},  // kTrooDie4
    {Sprite::kTroo, 12, false, -1, Action::kNone, S::kNull},  // kTrooDie5
    {Sprite::kTroo, 13, false, 5, Action::kNone, S::kTrooXdie2},  // kTrooXdie1
    {Sprite::kTroo, 14, false, 5, Action::kXScream, S::kTrooXdie3},  // kTrooXdie2
    {Sprite::kTroo, 15, false, 5, Action::kNone, S::kTrooXdie4},  // kTrooXdie3
    {Sprite::kTroo, 16, false, 5, Action::kFall, S::kTrooXdie5},  // kTrooXdie4
    {Sprite::kTroo, 17, false, 5, Action::kNone, S::kTrooXdie6},  // kTrooXdie5
    {Sprite::kTroo, 18, false, 5, Action::kNone, S::kTrooXdie7},  // kTrooXdie6
    {Sprite::kTroo, 19, false, 5, Action::kNone, S::kTrooXdie8},  // kTrooXdie7
    {Sprite::kTroo, 20, false, -1, Action::kNone, S::kNull},  // kTrooXdie8
    {Sprite::kTroo, 12, false, 8, Action::kNone, S::kTrooRaise2},  // kTrooRaise1
    {Sprite::kTroo, 11, false, 8, Action::kNone, S::kTrooRaise3},  // kTrooRaise2
    {Sprite::kTroo, 10, false, 6, Action::kNone, S::kTrooRaise4},  // kTrooRaise3
    {Sprite::kTroo, 9, false, 6, Action::kNone, S::kTrooRaise5},  // kTrooRaise4
    {Sprite::kTroo, 8, false, 6, Action::kNone, S::kTrooRun1},  // kTrooRaise5
    {Sprite::kSarg, 0, false, 10, Action::kLook, S::kSargStnd2},  // kSargStnd
    {Sprite::kSarg, 1, false, 10, Action::kLook, S::kSargStnd},  // kSargStnd2
    {Sprite::kSarg, 0, false, 2, Action::kChase, S::kSargRun2},  // kSargRun1
    {Sprite::kSarg, 0, false, 2, Action::kChase, S::kSargRun3},  // kSargRun2
    {Sprite::kSarg, 1, false, 2, Action::kChase, S::kSargRun4},  // kSargRun3
    {Sprite::kSarg, 1, false, 2, Action::kChase, S::kSargRun5},  // kSargRun4
    {Sprite::kSarg, 2, false, 2, Action::kChase, S::kSargRun6},  // kSargRun5
    {Sprite::kSarg, 2, false, 2, Action::kChase, S::kSargRun7},  // kSargRun6
    {Sprite::kSarg, 3, false, 2, Action::kChase, S::kSargRun8},  // kSargRun7
    {Sprite::kSarg, 3, false, 2, Action::kChase, S::kSargRun1},  // kSargRun8
    {Sprite::kSarg, 4, false, 8, Action::kFaceTarget, S::kSargAtk2},  // kSargAtk1
    {Sprite::kSarg, 5, false, 8, Action::kFaceTarget, S::kSargAtk3},  // kSargAtk2
    {Sprite::kSarg, 6, false, 8, Action::kSargAttack, S::kSargRun1},  // kSargAtk3
    {Sprite::kSarg, 7, false, 2, Action::kNone, S::kSargPain2},  // kSargPain
    {Sprite::kSarg, 7, false, 2, Action::kPain, S::kSargRun1},  // kSargPain2
    {Sprite::kSarg, 8, false, 8, Action::kNone, S::kSargDie2},  // kSargDie1
    {Sprite::kSarg, 9, false, 8, Action::kScream, S::kSargDie3},  // kSargDie2
    {Sprite::kSarg, 10, false, 4, Action::kNone, S::kSargDie4},  // kSargDie3
    {Sprite::kSarg, 11, false, 4, Action::kFall, S::kSargDie5},  // kSargDie4
    {Sprite::kSarg, 12, false, 4, Action::kNone, S::kSargDie6},  // kSargDie5
    {Sprite::kSarg, 13, false, -1, Action::kNone, S::kNull},  // kSargDie6
    {Sprite::kSarg, 13, false, 5, Action::kNone, S::kSargRaise2},  // kSargRaise1
    {Sprite::kSarg, 12, false, 5, Action::kNone, S::kSargRaise3},  // kSargRaise2
    {Sprite::kSarg, 11, false, 5, Action::kNone, S::kSargRaise4},  // kSargRaise3
    {Sprite::kSarg, 10, false, 5, Action::kNone, S::kSargRaise5},  // kSargRaise4
    {Sprite::kSarg, 9, false, 5, Action::kNone, S::kSargRaise6},  // kSargRaise5
    {Sprite::kSarg, 8, false, 5, Action::kNone, S::kSargRun1},  // kSargRaise6
    {Sprite::kHead, 0, false, 10, Action::kLook, S::kHeadStnd},  // kHeadStnd
    {Sprite::kHead, 0, false, 3, Action::kChase, S::kHeadRun1},  // kHeadRun1
    {Sprite::kHead, 1, false, 5, Action::kFaceTarget, S::kHeadAtk2},  // kHeadAtk1
    {Sprite::kHead, 2, false, 5, Action::kFaceTarget, S::kHeadAtk3},  // kHeadAtk2
    {Sprite::kHead, 3, true, 5, Action::kHeadAttack, S::kHeadRun1},  // kHeadAtk3
    {Sprite::kHead, 4, false, 3, Action::kNone, S::kHeadPain2},  // kHeadPain
    {Sprite::kHead, 4, false, 3, Action::kPain, S::kHeadPain3},  // kHeadPain2
    {Sprite::kHead, 5, false, 6, Action::kNone, S::kHeadRun1},  // kHeadPain3
    {Sprite::kHead, 6, false, 8, Action::kNone, S::kHeadDie2},  // kHeadDie1
    {Sprite::kHead, 7, false, 8, Action::kScream, S::kHeadDie3},  // kHeadDie2
    {Sprite::kHead, 8, false, 8, Action::kNone, S::kHeadDie4},  // kHeadDie3
    {Sprite::kHead, 9, false, 8, Action::kNone, S::kHeadDie5},  // kHeadDie4
    {Sprite::kHead, 10, false, 8, Action::kFall, S::kHeadDie6},  // kHeadDie5
    {Sprite::kHead, 11, false, -1, Action::kNone, S::kNull},  // kHeadDie6
    {Sprite::kHead, 11, false, 8, Action::kNone, S::kHeadRaise2},  // kHeadRaise1
    {Sprite::kHead, 10, false, 8, Action::kNone, S::kHeadRaise3},  // kHeadRaise2
    {Sprite::kHead, 9, false, 8, Action::kNone, S::kHeadRaise4},  // kHeadRaise3
    {Sprite::kHead, 8, false, 8, Action::kNone, S::kHeadRaise5},  // kHeadRaise4
    {Sprite::kHead, 7, false, 8, Action::kNone, S::kHeadRaise6},  // kHeadRaise5
    {Sprite::kHead, 6, false, 8, Action::kNone, S::kHeadRun1},  // kHeadRaise6
    {Sprite::kBal7, 0, true, 4, Action::kNone, S::kBrball2},  // kBrball1
    {Sprite::kBal7, 1, true, 4, Action::kNone, S::kBrball1},  // kBrball2
    {Sprite::kBal7, 2, true, 6, Action::kNone, S::kBrballx2},  // kBrballx1
    {Sprite::kBal7, 3, true, 6, Action::kNone, S::kBrballx3},  // kBrballx2
    {Sprite::kBal7, 4, true, 6, Action::kNone, S::kNull},  // kBrballx3
    {Sprite::kBoss, 0, false, 10, Action::kLook, S::kBossStnd2},  // kBossStnd
    {Sprite::kBoss, 1, false, 10, Action::kLook, S::kBossStnd},  // kBossStnd2
    {Sprite::kBoss, 0, false, 3, Action::kChase, S::kBossRun2},  // kBossRun1
    {Sprite::kBoss, 0, false, 3, Action::kChase, S::kBossRun3},  // kBossRun2
    {Sprite::kBoss, 1, false, 3, Action::kChase, S::kBossRun4},  // kBossRun3
    {Sprite::kBoss, 1, false, 3, Action::kChase, S::kBossRun5},  // kBossRun4
    {Sprite::kBoss, 2, false, 3, Action::kChase, S::kBossRun6},  // kBossRun5
    {Sprite::kBoss, 2, false, 3, Action::kChase, S::kBossRun7},  // kBossRun6
    {Sprite::kBoss, 3, false, 3, Action::kChase, S::kBossRun8},  // kBossRun7
    {Sprite::kBoss, 3, false, 3, Action::kChase, S::kBossRun1},  // kBossRun8
    {Sprite::kBoss, 4, false, 8, Action::kFaceTarget, S::kBossAtk2},  // kBossAtk1
    {Sprite::kBoss, 5, false, 8, Action::kFaceTarget, S::kBossAtk3},  // kBossAtk2
    {Sprite::kBoss, 6, false, 8, Action::kBruisAttack, S::kBossRun1},  // kBossAtk3
    {Sprite::kBoss, 7, false, 2, Action::kNone, S::kBossPain2},  // kBossPain
    {Sprite::kBoss, 7, false, 2, Action::kPain, S::kBossRun1},  // kBossPain2
    {Sprite::kBoss, 8, false, 8, Action::kNone, S::kBossDie2},  // kBossDie1
    {Sprite::kBoss, 9, false, 8, Action::kScream, S::kBossDie3},  // kBossDie2
    {Sprite::kBoss, 10, false, 8, Action::kNone, S::kBossDie4},  // kBossDie3
    {Sprite::kBoss, 11, false, 8, Action::kFall, S::kBossDie5},  // kBossDie4
    {Sprite::kBoss, 12, false, 8, Action::kNone, S::kBossDie6},  // kBossDie5
    {Sprite::kBoss, 13, false, 8, Action::kNone, S::kBossDie7},  // kBossDie6
    {Sprite::kBoss, 14, false, -1, Action::kBossDeath, S::kNull},  // kBossDie7
    {Sprite::kBoss, 14, false, 8, Action::kNone, S::kBossRaise2},  // kBossRaise1
    {Sprite::kBoss, 13, false, 8, Action::kNone, S::kBossRaise3},  // kBossRaise2
    {Sprite::kBoss, 12, false, 8, Action::kNone, S::kBossRaise4},  // kBossRaise3
    {Sprite::kBoss, 11, false, 8, Action::kNone, S::kBossRaise5},  // kBossRaise4
    {Sprite::kBoss, 10, false, 8, Action::kNone, S::kBossRaise6},  // kBossRaise5
    {Sprite::kBoss, 9, false, 8, Action::kNone, S::kBossRaise7},  // kBossRaise6
    {Sprite::kBoss, 8, false, 8, Action::kNone, S::kBossRun1},  // kBossRaise7
    {Sprite::kBos2, 0, false, 10, Action::kLook, S::kBos2Stnd2},  // kBos2Stnd
    {Sprite::kBos2, 1, false, 10, Action::kLook, S::kBos2Stnd},  // kBos2Stnd2
    {Sprite::kBos2, 0, false, 3, Action::kChase, S::kBos2Run2},  // kBos2Run1
    {Sprite::kBos2, 0, false, 3, Action::kChase, S::kBos2Run3},  // kBos2Run2
    {Sprite::kBos2, 1, false, 3, Action::kChase, S::kBos2Run4},  // kBos2Run3
    {Sprite::kBos2, 1, false, 3, Action::kChase, S::kBos2Run5},  // kBos2Run4
    {Sprite::kBos2, 2, false, 3, Action::kChase, S::kBos2Run6},  // kBos2Run5
    {Sprite::kBos2, 2, false, 3, Action::kChase, S::kBos2Run7},  // kBos2Run6
    {Sprite::kBos2, 3, false, 3, Action::kChase, S::kBos2Run8},  // kBos2Run7
    {Sprite::kBos2, 3, false, 3, Action::kChase, S::kBos2Run1},  // kBos2Run8
    {Sprite::kBos2, 4, false, 8, Action::kFaceTarget, S::kBos2Atk2},  // kBos2Atk1
    {Sprite::kBos2, 5, false, 8, Action::kFaceTarget, S::kBos2Atk3},  // kBos2Atk2
    {Sprite::kBos2, 6, false, 8, Action::kBruisAttack, S::kBos2Run1},  // kBos2Atk3
    {Sprite::kBos2, 7, false, 2, Action::kNone, S::kBos2Pain2},  // kBos2Pain
    {Sprite::kBos2, 7, false, 2, Action::kPain, S::kBos2Run1},  // kBos2Pain2
    {Sprite::kBos2, 8, false, 8, Action::kNone, S::kBos2Die2},  // kBos2Die1
    {Sprite::kBos2, 9, false, 8, Action::kScream, S::kBos2Die3},  // kBos2Die2
    {Sprite::kBos2, 10, false, 8, Action::kNone, S::kBos2Die4},  // kBos2Die3
    {Sprite::kBos2, 11, false, 8, Action::kFall, S::kBos2Die5},  // kBos2Die4
    {Sprite::kBos2, 12, false, 8, Action::kNone, S::kBos2Die6},  // kBos2Die5
    {Sprite::kBos2, 13, false, 8, Action::kNone, S::kBos2Die7},  // kBos2Die6
    {Sprite::kBos2, 14, false, -1, Action::kNone, S::kNull},  // kBos2Die7
    {Sprite::kBos2, 14, false, 8, Action::kNone, S::kBos2Raise2},  // kBos2Raise1
    {Sprite::kBos2, 13, false, 8, Action::kNone, S::kBos2Raise3},  // kBos2Raise2
    {Sprite::kBos2, 12, false, 8, Action::kNone, S::kBos2Raise4},  // kBos2Raise3
    {Sprite::kBos2, 11, false, 8, Action::kNone, S::kBos2Raise5},  // kBos2Raise4
    {Sprite::kBos2, 10, false, 8, Action::kNone, S::kBos2Raise6},  // kBos2Raise5
    {Sprite::kBos2, 9, false, 8, Action::kNone, S::kBos2Raise7},  // kBos2Raise6
    {Sprite::kBos2, 8, false, 8, Action::kNone, S::kBos2Run1},  // kBos2Raise7
    {Sprite::kSkul, 0, true, 10, Action::kLook, S::kSkullStnd2},  // kSkullStnd
    {Sprite::kSkul, 1, true, 10, Action::kLook, S::kSkullStnd},  // kSkullStnd2
    {Sprite::kSkul, 0, true, 6, Action::kChase, S::kSkullRun2},  // kSkullRun1
    {Sprite::kSkul, 1, true, 6, Action::kChase, S::kSkullRun1},  // kSkullRun2
    {Sprite::kSkul, 2, true, 10, Action::kFaceTarget, S::kSkullAtk2},  // kSkullAtk1
    {Sprite::kSkul, 3, true, 4, Action::kSkullAttack, S::kSkullAtk3},  // kSkullAtk2
    {Sprite::kSkul, 2, true, 4, Action::kNone, S::kSkullAtk4},  // kSkullAtk3
    {Sprite::kSkul, 3, true, 4, Action::kNone, S::kSkullAtk3},  // kSkullAtk4
    {Sprite::kSkul, 4, true, 3, Action::kNone, S::kSkullPain2},  // kSkullPain
    {Sprite::kSkul, 4, true, 3, Action::kPain, S::kSkullRun1},  // kSkullPain2
    {Sprite::kSkul, 5, true, 6, Action::kNone, S::kSkullDie2},  // kSkullDie1
    {Sprite::kSkul, 6, true, 6, Action::kScream, S::kSkullDie3},  // kSkullDie2
    {Sprite::kSkul, 7, true, 6, Action::kNone, S::kSkullDie4},  // kSkullDie3
    {Sprite::kSkul, 8, true, 6, Action::kFall, S::kSkullDie5},  // kSkullDie4
    {Sprite::kSkul, 9, false, 6, Action::kNone, S::kSkullDie6},  // kSkullDie5
    {Sprite::kSkul, 10, false, 6, Action::kNone, S::kNull},  // kSkullDie6
    {Sprite::kSpid, 0, false, 10, Action::kLook, S::kSpidStnd2},  // kSpidStnd
    {Sprite::kSpid, 1, false, 10, Action::kLook, S::kSpidStnd},  // kSpidStnd2
    {Sprite::kSpid, 0, false, 3, Action::kMetal, S::kSpidRun2},  // kSpidRun1
    {Sprite::kSpid, 0, false, 3, Action::kChase, S::kSpidRun3},  // kSpidRun2
    {Sprite::kSpid, 1, false, 3, Action::kChase, S::kSpidRun4},  // kSpidRun3
    {Sprite::kSpid, 1, false, 3, Action::kChase, S::kSpidRun5},  // kSpidRun4
    {Sprite::kSpid, 2, false, 3, Action::kMetal, S::kSpidRun6},  // kSpidRun5
    {Sprite::kSpid, 2, false, 3, Action::kChase, S::kSpidRun7},  // kSpidRun6
    {Sprite::kSpid, 3, false, 3, Action::kChase, S::kSpidRun8},  // kSpidRun7
    {Sprite::kSpid, 3, false, 3, Action::kChase, S::kSpidRun9},  // kSpidRun8
    {Sprite::kSpid, 4, false, 3, Action::kMetal, S::kSpidRun10},  // kSpidRun9
    {Sprite::kSpid, 4, false, 3, Action::kChase, S::kSpidRun11},  // kSpidRun10
    {Sprite::kSpid, 5, false, 3, Action::kChase, S::kSpidRun12},  // kSpidRun11
    {Sprite::kSpid, 5, false, 3, Action::kChase, S::kSpidRun1},  // kSpidRun12
    {Sprite::kSpid, 0, true, 20, Action::kFaceTarget, S::kSpidAtk2},  // kSpidAtk1
    {Sprite::kSpid, 6, true, 4, Action::kSPosAttack, S::kSpidAtk3},  // kSpidAtk2
    {Sprite::kSpid, 7, true, 4, Action::kSPosAttack, S::kSpidAtk4},  // kSpidAtk3
    {Sprite::kSpid, 7, true, 1, Action::kSpidRefire, S::kSpidAtk2},  // kSpidAtk4
    {Sprite::kSpid, 8, false, 3, Action::kNone, S::kSpidPain2},  // kSpidPain
    {Sprite::kSpid, 8, false, 3, Action::kPain, S::kSpidRun1},  // kSpidPain2
    {Sprite::kSpid, 9, false, 20, Action::kScream, S::kSpidDie2},  // kSpidDie1
    {Sprite::kSpid, 10, false, 10, Action::kFall, S::kSpidDie3},  // kSpidDie2
    {Sprite::kSpid, 11, false, 10, Action::kNone, S::kSpidDie4},  // kSpidDie3
    {Sprite::kSpid, 12, false, 10, Action::kNone, S::kSpidDie5},  // kSpidDie4
    {Sprite::kSpid, 13, false, 10, Action::kNone, S::kSpidDie6},  // kSpidDie5
    {Sprite::kSpid, 14, false, 10, Action::kNone, S::kSpidDie7},  // kSpidDie6
    {Sprite::kSpid, 15, false, 10, Action::kNone, S::kSpidDie8},  // kSpidDie7
    {Sprite::kSpid, 16, false, 10, Action::kNone, S::kSpidDie9},  // kSpidDie8
    {Sprite::kSpid, 17, false, 10, Action::kNone, S::kSpidDie10},  // kSpidDie9
    {Sprite::kSpid, 18, false, 30, Action::kNone, S::kSpidDie11},  // kSpidDie10
    {Sprite::kSpid, 18, false, -1, Action::kBossDeath, S::kNull},  // kSpidDie11
    {Sprite::kBspi, 0, false, 10, Action::kLook, S::kBspiStnd2},  // kBspiStnd
    {Sprite::kBspi, 1, false, 10, Action::kLook, S::kBspiStnd},  // kBspiStnd2
    {Sprite::kBspi, 0, false, 20, Action::kNone, S::kBspiRun1},  // kBspiSight
    {Sprite::kBspi, 0, false, 3, Action::kBabyMetal, S::kBspiRun2},  // kBspiRun1
    {Sprite::kBspi, 0, false, 3, Action::kChase, S::kBspiRun3},  // kBspiRun2
    {Sprite::kBspi, 1, false, 3, Action::kChase, S::kBspiRun4},  // kBspiRun3
    {Sprite::kBspi, 1, false, 3, Action::kChase, S::kBspiRun5},  // kBspiRun4
    {Sprite::kBspi, 2, false, 3, Action::kChase, S::kBspiRun6},  // kBspiRun5
    {Sprite::kBspi, 2, false, 3, Action::kChase, S::kBspiRun7},  // kBspiRun6
    {Sprite::kBspi, 3, false, 3, Action::kBabyMetal, S::kBspiRun8},  // kBspiRun7
    {Sprite::kBspi, 3, false, 3, Action::kChase, S::kBspiRun9},  // kBspiRun8
    {Sprite::kBspi, 4, false, 3, Action::kChase, S::kBspiRun10},  // kBspiRun9
    {Sprite::kBspi, 4, false, 3, Action::kChase, S::kBspiRun11},  // kBspiRun10
    {Sprite::kBspi, 5, false, 3, Action::kChase, S::kBspiRun12},  // kBspiRun11
    {Sprite::kBspi, 5, false, 3, Action::kChase, S::kBspiRun1},  // kBspiRun12
    {Sprite::kBspi, 0, true, 20, Action::kFaceTarget, S::kBspiAtk2},  // kBspiAtk1
    {Sprite::kBspi, 6, true, 4, Action::kBspiAttack, S::kBspiAtk3},  // kBspiAtk2
    {Sprite::kBspi, 7, true, 4, Action::kNone, S::kBspiAtk4},  // kBspiAtk3
    {Sprite::kBspi, 7, true, 1, Action::kSpidRefire, S::kBspiAtk2},  // kBspiAtk4
    {Sprite::kBspi, 8, false, 3, Action::kNone, S::kBspiPain2},  // kBspiPain
    {Sprite::kBspi, 8, false, 3, Action::kPain, S::kBspiRun1},  // kBspiPain2
    {Sprite::kBspi, 9, false, 20, Action::kScream, S::kBspiDie2},  // kBspiDie1
    {Sprite::kBspi, 10, false, 7, Action::kFall, S::kBspiDie3},  // kBspiDie2
    {Sprite::kBspi, 11, false, 7, Action::kNone, S::kBspiDie4},  // kBspiDie3
    {Sprite::kBspi, 12, false, 7, Action::kNone, S::kBspiDie5},  // kBspiDie4
    {Sprite::kBspi, 13, false, 7, Action::kNone, S::kBspiDie6},  // kBspiDie5
    {Sprite::kBspi, 14, false, 7, Action::kNone, S::kBspiDie7},  // kBspiDie6
    {Sprite::kBspi, 15, false, -1, Action::kBossDeath, S::kNull},  // kBspiDie7
    {Sprite::kBspi, 15, false, 5, Action::kNone, S::kBspiRaise2},  // kBspiRaise1
    {Sprite::kBspi, 14, false, 5, Action::kNone, S::kBspiRaise3},  // kBspiRaise2
    {Sprite::kBspi, 13, false, 5, Action::kNone, S::kBspiRaise4},  // kBspiRaise3
    {Sprite::kBspi, 12, false, 5, Action::kNone, S::kBspiRaise5},  // kBspiRaise4
    {Sprite::kBspi, 11, false, 5, Action::kNone, S::kBspiRaise6},  // kBspiRaise5
    {Sprite::kBspi, 10, false, 5, Action::kNone, S::kBspiRaise7},  // kBspiRaise6
    {Sprite::kBspi, 9, false, 5, Action::kNone, S::kBspiRun1},  // kBspiRaise7
    {Sprite::kApls, 0, true, 5, Action::kNone, S::kArachPlaz2},  // kArachPlaz
    {Sprite::kApls, 1, true, 5, Action::kNone, S::kArachPlaz},  // kArachPlaz2
    {Sprite::kApbx, 0, true, 5, Action::kNone, S::kArachPlex2},  // kArachPlex
    {Sprite::kApbx, 1, true, 5, Action::kNone, S::kArachPlex3},  // kArachPlex2
    {Sprite::kApbx, 2, true, 5, Action::kNone, S::kArachPlex4},  // kArachPlex3
    {Sprite::kApbx, 3, true, 5, Action::kNone, S::kArachPlex5},  // kArachPlex4
    {Sprite::kApbx, 4, true, 5, Action::kNone, S::kNull},  // kArachPlex5
    {Sprite::kCybr, 0, false, 10, Action::kLook, S::kCyberStnd2},  // kCyberStnd
    {Sprite::kCybr, 1, false, 10, Action::kLook, S::kCyberStnd},  // kCyberStnd2
    {Sprite::kCybr, 0, false, 3, Action::kHoof, S::kCyberRun2},  // kCyberRun1
    {Sprite::kCybr, 0, false, 3, Action::kChase, S::kCyberRun3},  // kCyberRun2
    {Sprite::kCybr, 1, false, 3, Action::kChase, S::kCyberRun4},  // kCyberRun3
    {Sprite::kCybr, 1, false, 3, Action::kChase, S::kCyberRun5},  // kCyberRun4
    {Sprite::kCybr, 2, false, 3, Action::kChase, S::kCyberRun6},  // kCyberRun5
    {Sprite::kCybr, 2, false, 3, Action::kChase, S::kCyberRun7},  // kCyberRun6
    {Sprite::kCybr, 3, false, 3, Action::kMetal, S::kCyberRun8},  // kCyberRun7
    {Sprite::kCybr, 3, false, 3, Action::kChase, S::kCyberRun1},  // kCyberRun8
    {Sprite::kCybr, 4, false, 6, Action::kFaceTarget, S::kCyberAtk2},  // kCyberAtk1
    {Sprite::kCybr, 5, false, 12, Action::kCyberAttack, S::kCyberAtk3},  // kCyberAtk2
    {Sprite::kCybr, 4, false, 12, Action::kFaceTarget, S::kCyberAtk4},  // kCyberAtk3
    {Sprite::kCybr, 5, false, 12, Action::kCyberAttack, S::kCyberAtk5},  // kCyberAtk4
    {Sprite::kCybr, 4, false, 12, Action::kFaceTarget, S::kCyberAtk6},  // kCyberAtk5
    {Sprite::kCybr, 5, false, 12, Action::kCyberAttack, S::kCyberRun1},  // kCyberAtk6
    {Sprite::kCybr, 6, false, 10, Action::kPain, S::kCyberRun1},  // kCyberPain
    {Sprite::kCybr, 7, false, 10, Action::kNone, S::kCyberDie2},  // kCyberDie1
    {Sprite::kCybr, 8, false, 10, Action::kScream, S::kCyberDie3},  // kCyberDie2
    {Sprite::kCybr, 9, false, 10, Action::kNone, S::kCyberDie4},  // kCyberDie3
    {Sprite::kCybr, 10, false, 10, Action::kNone, S::kCyberDie5},  // kCyberDie4
    {Sprite::kCybr, 11, false, 10, Action::kNone, S::kCyberDie6},  // kCyberDie5
    {Sprite::kCybr, 12, false, 10, Action::kFall, S::kCyberDie7},  // kCyberDie6
    {Sprite::kCybr, 13, false, 10, Action::kNone, S::kCyberDie8},  // kCyberDie7
    {Sprite::kCybr, 14, false, 10, Action::kNone, S::kCyberDie9},  // kCyberDie8
    {Sprite::kCybr, 15, false, 30, Action::kNone, S::kCyberDie10},  // kCyberDie9
    {Sprite::kCybr, 15, false, -1, Action::kBossDeath, S::kNull},  // kCyberDie10
    {Sprite::kPain, 0, false, 10, Action::kLook, S::kPainStnd},  // kPainStnd
    {Sprite::kPain, 0, false, 3, Action::kChase, S::kPainRun2},  // kPainRun1
    {Sprite::kPain, 0, false, 3, Action::kChase, S::kPainRun3},  // kPainRun2
    {Sprite::kPain, 1, false, 3, Action::kChase, S::kPainRun4},  // kPainRun3
    {Sprite::kPain, 1, false, 3, Action::kChase, S::kPainRun5},  // kPainRun4
    {Sprite::kPain, 2, false, 3, Action::kChase, S::kPainRun6},  // kPainRun5
    {Sprite::kPain, 2, false, 3, Action::kChase, S::kPainRun1},  // kPainRun6
    {Sprite::kPain, 3, false, 5, Action::kFaceTarget, S::kPainAtk2},  // kPainAtk1
    {Sprite::kPain, 4, false, 5, Action::kFaceTarget, S::kPainAtk3},  // kPainAtk2
    {Sprite::kPain, 5, true, 5, Action::kFaceTarget, S::kPainAtk4},  // kPainAtk3
    {Sprite::kPain, 5, true, 0, Action::kPainAttack, S::kPainRun1},  // kPainAtk4
    {Sprite::kPain, 6, false, 6, Action::kNone, S::kPainPain2},  // kPainPain
    {Sprite::kPain, 6, false, 6, Action::kPain, S::kPainRun1},  // kPainPain2
    {Sprite::kPain, 7, true, 8, Action::kNone, S::kPainDie2},  // kPainDie1
    {Sprite::kPain, 8, true, 8, Action::kScream, S::kPainDie3},  // kPainDie2
    {Sprite::kPain, 9, true, 8, Action::kNone, S::kPainDie4},  // kPainDie3
    {Sprite::kPain, 10, true, 8, Action::kNone, S::kPainDie5},  // kPainDie4
    {Sprite::kPain, 11, true, 8, Action::kPainDie, S::kPainDie6},  // kPainDie5
    {Sprite::kPain, 12, true, 8, Action::kNone, S::kNull},  // kPainDie6
    {Sprite::kPain, 12, false, 8, Action::kNone, S::kPainRaise2},  // kPainRaise1
    {Sprite::kPain, 11, false, 8, Action::kNone, S::kPainRaise3},  // kPainRaise2
    {Sprite::kPain, 10, false, 8, Action::kNone, S::kPainRaise4},  // kPainRaise3
    {Sprite::kPain, 9, false, 8, Action::kNone, S::kPainRaise5},  // kPainRaise4
    {Sprite::kPain, 8, false, 8, Action::kNone, S::kPainRaise6},  // kPainRaise5
    {Sprite::kPain, 7, false, 8, Action::kNone, S::kPainRun1},  // kPainRaise6
    {Sprite::kSswv, 0, false, 10, Action::kLook, S::kSswvStnd2},  // kSswvStnd
    {Sprite::kSswv, 1, false, 10, Action::kLook, S::kSswvStnd},  // kSswvStnd2
    {Sprite::kSswv, 0, false, 3, Action::kChase, S::kSswvRun2},  // kSswvRun1
    {Sprite::kSswv, 0, false, 3, Action::kChase, S::kSswvRun3},  // kSswvRun2
    {Sprite::kSswv, 1, false, 3, Action::kChase, S::kSswvRun4},  // kSswvRun3
    {Sprite::kSswv, 1, false, 3, Action::kChase, S::kSswvRun5},  // kSswvRun4
    {Sprite::kSswv, 2, false, 3, Action::kChase, S::kSswvRun6},  // kSswvRun5
    {Sprite::kSswv, 2, false, 3, Action::kChase, S::kSswvRun7},  // kSswvRun6
    {Sprite::kSswv, 3, false, 3, Action::kChase, S::kSswvRun8},  // kSswvRun7
    {Sprite::kSswv, 3, false, 3, Action::kChase, S::kSswvRun1},  // kSswvRun8
    {Sprite::kSswv, 4, false, 10, Action::kFaceTarget, S::kSswvAtk2},  // kSswvAtk1
    {Sprite::kSswv, 5, false, 10, Action::kFaceTarget, S::kSswvAtk3},  // kSswvAtk2
    {Sprite::kSswv, 6, true, 4, Action::kCPosAttack, S::kSswvAtk4},  // kSswvAtk3
    {Sprite::kSswv, 5, false, 6, Action::kFaceTarget, S::kSswvAtk5},  // kSswvAtk4
    {Sprite::kSswv, 6, true, 4, Action::kCPosAttack, S::kSswvAtk6},  // kSswvAtk5
    {Sprite::kSswv, 5, false, 1, Action::kCPosRefire, S::kSswvAtk2},  // kSswvAtk6
    {Sprite::kSswv, 7, false, 3, Action::kNone, S::kSswvPain2},  // kSswvPain
    {Sprite::kSswv, 7, false, 3, Action::kPain, S::kSswvRun1},  // kSswvPain2
    {Sprite::kSswv, 8, false, 5, Action::kNone, S::kSswvDie2},  // kSswvDie1
    {Sprite::kSswv, 9, false, 5, Action::kScream, S::kSswvDie3},  // kSswvDie2
    {Sprite::kSswv, 10, false, 5, Action::kFall, S::kSswvDie4},  // kSswvDie3
    {Sprite::kSswv, 11, false, 5, Action::kNone, S::kSswvDie5},  // kSswvDie4
    {Sprite::kSswv, 12, false, -1, Action::kNone, S::kNull},  // kSswvDie5
    {Sprite::kSswv, 13, false, 5, Action::kNone, S::kSswvXdie2},  // kSswvXdie1
    {Sprite::kSswv, 14, false, 5, Action::kXScream, S::kSswvXdie3},  // kSswvXdie2
    {Sprite::kSswv, 15, false, 5, Action::kFall, S::kSswvXdie4},  // kSswvXdie3
    {Sprite::kSswv, 16, false, 5, Action::kNone, S::kSswvXdie5},  // kSswvXdie4
    {Sprite::kSswv, 17, false, 5, Action::kNone, S::kSswvXdie6},  // kSswvXdie5
    {Sprite::kSswv, 18, false, 5, Action::kNone, S::kSswvXdie7},  // kSswvXdie6
    {Sprite::kSswv, 19, false, 5, Action::kNone, S::kSswvXdie8},  // kSswvXdie7
    {Sprite::kSswv, 20, false, 5, Action::kNone, S::kSswvXdie9},  // kSswvXdie8
    {Sprite::kSswv, 21, false, -1, Action::kNone, S::kNull},  // kSswvXdie9
    {Sprite::kSswv, 12, false, 5, Action::kNone, S::kSswvRaise2},  // kSswvRaise1
    {Sprite::kSswv, 11, false, 5, Action::kNone, S::kSswvRaise3},  // kSswvRaise2
    {Sprite::kSswv, 10, false, 5, Action::kNone, S::kSswvRaise4},  // kSswvRaise3
    {Sprite::kSswv, 9, false, 5, Action::kNone, S::kSswvRaise5},  // kSswvRaise4
    {Sprite::kSswv, 8, false, 5, Action::kNone, S::kSswvRun1},  // kSswvRaise5
    {Sprite::kKeen, 0, false, -1, Action::kNone, S::kKeenstnd},  // kKeenstnd
    {Sprite::kKeen, 0, false, 6, Action::kNone, S::kCommkeen2},  // kCommkeen
    {Sprite::kKeen, 1, false, 6, Action::kNone, S::kCommkeen3},  // kCommkeen2
    {Sprite::kKeen, 2, false, 6, Action::kScream, S::kCommkeen4},  // kCommkeen3
    {Sprite::kKeen, 3, false, 6, Action::kNone, S::kCommkeen5},  // kCommkeen4
    {Sprite::kKeen, 4, false, 6, Action::kNone, S::kCommkeen6},  // kCommkeen5
    {Sprite::kKeen, 5, false, 6, Action::kNone, S::kCommkeen7},  // kCommkeen6
    {Sprite::kKeen, 6, false, 6, Action::kNone, S::kCommkeen8},  // kCommkeen7
    {Sprite::kKeen, 7, false, 6, Action::kNone, S::kCommkeen9},  // kCommkeen8
    {Sprite::kKeen, 8, false, 6, Action::kNone, S::kCommkeen10},  // kCommkeen9
    {Sprite::kKeen, 9, false, 6, Action::kNone, S::kCommkeen11},  // kCommkeen10
    {Sprite::kKeen, 10, false, 6, Action::kKeenDie, S::kCommkeen12},  // kCommkeen11
    {Sprite::kKeen, 11, false, -1, Action::kNone, S::kNull},  // kCommkeen12
    {Sprite::kKeen, 12, false, 4, Action::kNone, S::kKeenpain2},  // kKeenpain
    {Sprite::kKeen, 12, false, 8, Action::kPain, S::kKeenstnd},  // kKeenpain2
    {Sprite::kBbrn, 0, false, -1, Action::kNone, S::kNull},  // kBrain
    {Sprite::kBbrn, 1, false, 36, Action::kBrainPain, S::kBrain},  // kBrainPain
    {Sprite::kBbrn, 0, false, 100, Action::kBrainScream, S::kBrainDie2},  // kBrainDie1
    {Sprite::kBbrn, 0, false, 10, Action::kNone, S::kBrainDie3},  // kBrainDie2
    {Sprite::kBbrn, 0, false, 10, Action::kNone, S::kBrainDie4},  // kBrainDie3
    {Sprite::kBbrn, 0, false, -1, Action::kBrainDie, S::kNull},  // kBrainDie4
    {Sprite::kSswv, 0, false, 10, Action::kLook, S::kBraineye},  // kBraineye
    {Sprite::kSswv, 0, false, 181, Action::kBrainAwake, S::kBraineye1},  // kBraineyesee
    {Sprite::kSswv, 0, false, 150, Action::kBrainSpit, S::kBraineye1},  // kBraineye1
    {Sprite::kBosf, 0, true, 3, Action::kSpawnSound, S::kSpawn2},  // kSpawn1
    {Sprite::kBosf, 1, true, 3, Action::kSpawnFly, S::kSpawn3},  // kSpawn2
    {Sprite::kBosf, 2, true, 3, Action::kSpawnFly, S::kSpawn4},  // kSpawn3
    {Sprite::kBosf, 3, true, 3, Action::kSpawnFly, S::kSpawn1},  // kSpawn4
    {Sprite::kFire, 0, true, 4, Action::kFire, S::kSpawnfire2},  // kSpawnfire1
    {Sprite::kFire, 1, true, 4, Action::kFire, S::kSpawnfire3},  // kSpawnfire2
    {Sprite::kFire, 2, true, 4, Action::kFire, S::kSpawnfire4},  // kSpawnfire3
    {Sprite::kFire, 3, true, 4, Action::kFire, S::kSpawnfire5},  // kSpawnfire4
    {Sprite::kFire, 4, true, 4, Action::kFire, S::kSpawnfire6},  // kSpawnfire5
    {Sprite::kFire, 5, true, 4, Action::kFire, S::kSpawnfire7},  // kSpawnfire6
    {Sprite::kFire, 6, true, 4, Action::kFire, S::kSpawnfire8},  // kSpawnfire7
    {Sprite::kFire, 7, true, 4, Action::kFire, S::kNull},  // kSpawnfire8
    {Sprite::kMisl, 1, true, 10, Action::kNone, S::kBrainexplode2},  // kBrainexplode1
    {Sprite::kMisl, 2, true, 10, Action::kNone, S::kBrainexplode3},  // kBrainexplode2
    {Sprite::kMisl, 3, true, 10, Action::kBrainExplode, S::kNull},  // kBrainexplode3
    {Sprite::kArm1, 0, false, 6, Action::kNone, S::kArm1a},  // kArm1
    {Sprite::kArm1, 1, true, 7, Action::kNone, S::kArm1},  // kArm1a
    {Sprite::kArm2, 0, false, 6, Action::kNone, S::kArm2a},  // kArm2
    {Sprite::kArm2, 1, true, 6, Action::kNone, S::kArm2},  // kArm2a
    {Sprite::kBar1, 0, false, 6, Action::kNone, S::kBar2},  // kBar1
    {Sprite::kBar1, 1, false, 6, Action::kNone, S::kBar1},  // kBar2
    {Sprite::kBexp, 0, true, 5, Action::kNone, S::kBexp2},  // kBexp
    {Sprite::kBexp, 1, true, 5, Action::kScream, S::kBexp3},  // kBexp2
    {Sprite::kBexp, 2, true, 5, Action::kNone, S::kBexp4},  // kBexp3
    {Sprite::kBexp, 3, true, 10, Action::kExplode, S::kBexp5},  // kBexp4
    {Sprite::kBexp, 4, true, 10, Action::kNone, S::kNull},  // kBexp5
    {Sprite::kFcan, 0, true, 4, Action::kNone, S::kBbar2},  // kBbar1
    {Sprite::kFcan, 1, true, 4, Action::kNone, S::kBbar3},  // kBbar2
    {Sprite::kFcan, 2, true, 4, Action::kNone, S::kBbar1},  // kBbar3
    {Sprite::kBon1, 0, false, 6, Action::kNone, S::kBon1a},  // kBon1
    {Sprite::kBon1, 1, false, 6, Action::kNone, S::kBon1b},  // kBon1a
    {Sprite::kBon1, 2, false, 6, Action::kNone, S::kBon1c},  // kBon1b
    {Sprite::kBon1, 3, false, 6, Action::kNone, S::kBon1d},  // kBon1c
    {Sprite::kBon1, 2, false, 6, Action::kNone, S::kBon1e},  // kBon1d
    {Sprite::kBon1, 1, false, 6, Action::kNone, S::kBon1},  // kBon1e
    {Sprite::kBon2, 0, false, 6, Action::kNone, S::kBon2a},  // kBon2
    {Sprite::kBon2, 1, false, 6, Action::kNone, S::kBon2b},  // kBon2a
    {Sprite::kBon2, 2, false, 6, Action::kNone, S::kBon2c},  // kBon2b
    {Sprite::kBon2, 3, false, 6, Action::kNone, S::kBon2d},  // kBon2c
    {Sprite::kBon2, 2, false, 6, Action::kNone, S::kBon2e},  // kBon2d
    {Sprite::kBon2, 1, false, 6, Action::kNone, S::kBon2},  // kBon2e
    {Sprite::kBkey, 0, false, 10, Action::kNone, S::kBkey2},  // kBkey
    {Sprite::kBkey, 1, true, 10, Action::kNone, S::kBkey},  // kBkey2
    {Sprite::kRkey, 0, false, 10, Action::kNone, S::kRkey2},  // kRkey
    {Sprite::kRkey, 1, true, 10, Action::kNone, S::kRkey},  // kRkey2
    {Sprite::kYkey, 0, false, 10, Action::kNone, S::kYkey2},  // kYkey
    {Sprite::kYkey, 1, true, 10, Action::kNone, S::kYkey},  // kYkey2
    {Sprite::kBsku, 0, false, 10, Action::kNone, S::kBskull2},  // kBskull
    {Sprite::kBsku, 1, true, 10, Action::kNone, S::kBskull},  // kBskull2
    {Sprite::kRsku, 0, false, 10, Action::kNone, S::kRskull2},  // kRskull
    {Sprite::kRsku, 1, true, 10, Action::kNone, S::kRskull},  // kRskull2
    {Sprite::kYsku, 0, false, 10, Action::kNone, S::kYskull2},  // kYskull
    {Sprite::kYsku, 1, true, 10, Action::kNone, S::kYskull},  // kYskull2
    {Sprite::kStim, 0, false, -1, Action::kNone, S::kNull},  // kStim
    {Sprite::kMedi, 0, false, -1, Action::kNone, S::kNull},  // kMedi
    {Sprite::kSoul, 0, true, 6, Action::kNone, S::kSoul2},  // kSoul
    {Sprite::kSoul, 1, true, 6, Action::kNone, S::kSoul3},  // kSoul2
    {Sprite::kSoul, 2, true, 6, Action::kNone, S::kSoul4},  // kSoul3
    {Sprite::kSoul, 3, true, 6, Action::kNone, S::kSoul5},  // kSoul4
    {Sprite::kSoul, 2, true, 6, Action::kNone, S::kSoul6},  // kSoul5
    {Sprite::kSoul, 1, true, 6, Action::kNone, S::kSoul},  // kSoul6
    {Sprite::kPinv, 0, true, 6, Action::kNone, S::kPinv2},  // kPinv
    {Sprite::kPinv, 1, true, 6, Action::kNone, S::kPinv3},  // kPinv2
    {Sprite::kPinv, 2, true, 6, Action::kNone, S::kPinv4},  // kPinv3
    {Sprite::kPinv, 3, true, 6, Action::kNone, S::kPinv},  // kPinv4
    {Sprite::kPstr, 0, true, -1, Action::kNone, S::kNull},  // kPstr
    {Sprite::kPins, 0, true, 6, Action::kNone, S::kPins2},  // kPins
    {Sprite::kPins, 1, true, 6, Action::kNone, S::kPins3},  // kPins2
    {Sprite::kPins, 2, true, 6, Action::kNone, S::kPins4},  // kPins3
    {Sprite::kPins, 3, true, 6, Action::kNone, S::kPins},  // kPins4
    {Sprite::kMega, 0, true, 6, Action::kNone, S::kMega2},  // kMega
    {Sprite::kMega, 1, true, 6, Action::kNone, S::kMega3},  // kMega2
    {Sprite::kMega, 2, true, 6, Action::kNone, S::kMega4},  // kMega3
    {Sprite::kMega, 3, true, 6, Action::kNone, S::kMega},  // kMega4
    {Sprite::kSuit, 0, true, -1, Action::kNone, S::kNull},  // kSuit
    {Sprite::kPmap, 0, true, 6, Action::kNone, S::kPmap2},  // kPmap
    {Sprite::kPmap, 1, true, 6, Action::kNone, S::kPmap3},  // kPmap2
    {Sprite::kPmap, 2, true, 6, Action::kNone, S::kPmap4},  // kPmap3
    {Sprite::kPmap, 3, true, 6, Action::kNone, S::kPmap5},  // kPmap4
    {Sprite::kPmap, 2, true, 6, Action::kNone, S::kPmap6},  // kPmap5
    {Sprite::kPmap, 1, true, 6, Action::kNone, S::kPmap},  // kPmap6
    {Sprite::kPvis, 0, true, 6, Action::kNone, S::kPvis2},  // kPvis
    {Sprite::kPvis, 1, false, 6, Action::kNone, S::kPvis},  // kPvis2
    {Sprite::kClip, 0, false, -1, Action::kNone, S::kNull},  // kClip
    {Sprite::kAmmo, 0, false, -1, Action::kNone, S::kNull},  // kAmmo
    {Sprite::kRock, 0, false, -1, Action::kNone, S::kNull},  // kRock
    {Sprite::kBrok, 0, false, -1, Action::kNone, S::kNull},  // kBrok
    {Sprite::kCell, 0, false, -1, Action::kNone, S::kNull},  // kCell
    {Sprite::kCelp, 0, false, -1, Action::kNone, S::kNull},  // kCelp
    {Sprite::kShel, 0, false, -1, Action::kNone, S::kNull},  // kShel
    {Sprite::kSbox, 0, false, -1, Action::kNone, S::kNull},  // kSbox
    {Sprite::kBpak, 0, false, -1, Action::kNone, S::kNull},  // kBpak
    {Sprite::kBfug, 0, false, -1, Action::kNone, S::kNull},  // kBfug
    {Sprite::kMgun, 0, false, -1, Action::kNone, S::kNull},  // kMgun
    {Sprite::kCsaw, 0, false, -1, Action::kNone, S::kNull},  // kCsaw
    {Sprite::kLaun, 0, false, -1, Action::kNone, S::kNull},  // kLaun
    {Sprite::kPlas, 0, false, -1, Action::kNone, S::kNull},  // kPlas
    {Sprite::kShot, 0, false, -1, Action::kNone, S::kNull},  // kShot
    {Sprite::kSgn2, 0, false, -1, Action::kNone, S::kNull},  // kShot2
    {Sprite::kColu, 0, true, -1, Action::kNone, S::kNull},  // kColu
    {Sprite::kSmt2, 0, false, -1, Action::kNone, S::kNull},  // kStalag
    {Sprite::kGor1, 0, false, 10, Action::kNone, S::kBloodytwitch2},  // kBloodytwitch
    {Sprite::kGor1, 1, false, 15, Action::kNone, S::kBloodytwitch3},  // kBloodytwitch2
    {Sprite::kGor1, 2, false, 8, Action::kNone, S::kBloodytwitch4},  // kBloodytwitch3
    {Sprite::kGor1, 1, false, 6, Action::kNone, S::kBloodytwitch},  // kBloodytwitch4
    {Sprite::kPlay, 13, false, -1, Action::kNone, S::kNull},  // kDeadtorso
    {Sprite::kPlay, 18, false, -1, Action::kNone, S::kNull},  // kDeadbottom
    {Sprite::kPol2, 0, false, -1, Action::kNone, S::kNull},  // kHeadsonstick
    {Sprite::kPol5, 0, false, -1, Action::kNone, S::kNull},  // kGibs
    {Sprite::kPol4, 0, false, -1, Action::kNone, S::kNull},  // kHeadonastick
    {Sprite::kPol3, 0, true, 6, Action::kNone, S::kHeadcandles2},  // kHeadcandles
    {Sprite::kPol3, 1, true, 6, Action::kNone, S::kHeadcandles},  // kHeadcandles2
    {Sprite::kPol1, 0, false, -1, Action::kNone, S::kNull},  // kDeadstick
    {Sprite::kPol6, 0, false, 6, Action::kNone, S::kLivestick2},  // kLivestick
    {Sprite::kPol6, 1, false, 8, Action::kNone, S::kLivestick},  // kLivestick2
    {Sprite::kGor2, 0, false, -1, Action::kNone, S::kNull},  // kMeat2
    {Sprite::kGor3, 0, false, -1, Action::kNone, S::kNull},  // kMeat3
    {Sprite::kGor4, 0, false, -1, Action::kNone, S::kNull},  // kMeat4
    {Sprite::kGor5, 0, false, -1, Action::kNone, S::kNull},  // kMeat5
    {Sprite::kSmit, 0, false, -1, Action::kNone, S::kNull},  // kStalagtite
    {Sprite::kCol1, 0, false, -1, Action::kNone, S::kNull},  // kTallgrncol
    {Sprite::kCol2, 0, false, -1, Action::kNone, S::kNull},  // kShrtgrncol
    {Sprite::kCol3, 0, false, -1, Action::kNone, S::kNull},  // kTallredcol
    {Sprite::kCol4, 0, false, -1, Action::kNone, S::kNull},  // kShrtredcol
    {Sprite::kCand, 0, true, -1, Action::kNone, S::kNull},  // kCandlestik
    {Sprite::kCbra, 0, true, -1, Action::kNone, S::kNull},  // kCandelabra
    {Sprite::kCol6, 0, false, -1, Action::kNone, S::kNull},  // kSkullcol
    {Sprite::kTre1, 0, false, -1, Action::kNone, S::kNull},  // kTorchtree
    {Sprite::kTre2, 0, false, -1, Action::kNone, S::kNull},  // kBigtree
    {Sprite::kElec, 0, false, -1, Action::kNone, S::kNull},  // kTechpillar
    {Sprite::kCeye, 0, true, 6, Action::kNone, S::kEvileye2},  // kEvileye
    {Sprite::kCeye, 1, true, 6, Action::kNone, S::kEvileye3},  // kEvileye2
    {Sprite::kCeye, 2, true, 6, Action::kNone, S::kEvileye4},  // kEvileye3
    {Sprite::kCeye, 1, true, 6, Action::kNone, S::kEvileye},  // kEvileye4
    {Sprite::kFsku, 0, true, 6, Action::kNone, S::kFloatskull2},  // kFloatskull
    {Sprite::kFsku, 1, true, 6, Action::kNone, S::kFloatskull3},  // kFloatskull2
    {Sprite::kFsku, 2, true, 6, Action::kNone, S::kFloatskull},  // kFloatskull3
    {Sprite::kCol5, 0, false, 14, Action::kNone, S::kHeartcol2},  // kHeartcol
    {Sprite::kCol5, 1, false, 14, Action::kNone, S::kHeartcol},  // kHeartcol2
    {Sprite::kTblu, 0, true, 4, Action::kNone, S::kBluetorch2},  // kBluetorch
    {Sprite::kTblu, 1, true, 4, Action::kNone, S::kBluetorch3},  // kBluetorch2
    {Sprite::kTblu, 2, true, 4, Action::kNone, S::kBluetorch4},  // kBluetorch3
    {Sprite::kTblu, 3, true, 4, Action::kNone, S::kBluetorch},  // kBluetorch4
    {Sprite::kTgrn, 0, true, 4, Action::kNone, S::kGreentorch2},  // kGreentorch
    {Sprite::kTgrn, 1, true, 4, Action::kNone, S::kGreentorch3},  // kGreentorch2
    {Sprite::kTgrn, 2, true, 4, Action::kNone, S::kGreentorch4},  // kGreentorch3
    {Sprite::kTgrn, 3, true, 4, Action::kNone, S::kGreentorch},  // kGreentorch4
    {Sprite::kTred, 0, true, 4, Action::kNone, S::kRedtorch2},  // kRedtorch
    {Sprite::kTred, 1, true, 4, Action::kNone, S::kRedtorch3},  // kRedtorch2
    {Sprite::kTred, 2, true, 4, Action::kNone, S::kRedtorch4},  // kRedtorch3
    {Sprite::kTred, 3, true, 4, Action::kNone, S::kRedtorch},  // kRedtorch4
    {Sprite::kSmbt, 0, true, 4, Action::kNone, S::kBtorchshrt2},  // kBtorchshrt
    {Sprite::kSmbt, 1, true, 4, Action::kNone, S::kBtorchshrt3},  // kBtorchshrt2
    {Sprite::kSmbt, 2, true, 4, Action::kNone, S::kBtorchshrt4},  // kBtorchshrt3
    {Sprite::kSmbt, 3, true, 4, Action::kNone, S::kBtorchshrt},  // kBtorchshrt4
    {Sprite::kSmgt, 0, true, 4, Action::kNone, S::kGtorchshrt2},  // kGtorchshrt
    {Sprite::kSmgt, 1, true, 4, Action::kNone, S::kGtorchshrt3},  // kGtorchshrt2
    {Sprite::kSmgt, 2, true, 4, Action::kNone, S::kGtorchshrt4},  // kGtorchshrt3
    {Sprite::kSmgt, 3, true, 4, Action::kNone, S::kGtorchshrt},  // kGtorchshrt4
    {Sprite::kSmrt, 0, true, 4, Action::kNone, S::kRtorchshrt2},  // kRtorchshrt
    {Sprite::kSmrt, 1, true, 4, Action::kNone, S::kRtorchshrt3},  // kRtorchshrt2
    {Sprite::kSmrt, 2, true, 4, Action::kNone, S::kRtorchshrt4},  // kRtorchshrt3
    {Sprite::kSmrt, 3, true, 4, Action::kNone, S::kRtorchshrt},  // kRtorchshrt4
    {Sprite::kHdb1, 0, false, -1, Action::kNone, S::kNull},  // kHangnoguts
    {Sprite::kHdb2, 0, false, -1, Action::kNone, S::kNull},  // kHangbnobrain
    {Sprite::kHdb3, 0, false, -1, Action::kNone, S::kNull},  // kHangtlookdn
    {Sprite::kHdb4, 0, false, -1, Action::kNone, S::kNull},  // kHangtskull
    {Sprite::kHdb5, 0, false, -1, Action::kNone, S::kNull},  // kHangtlookup
    {Sprite::kHdb6, 0, false, -1, Action::kNone, S::kNull},  // kHangtnobrain
    {Sprite::kPob1, 0, false, -1, Action::kNone, S::kNull},  // kColongibs
    {Sprite::kPob2, 0, false, -1, Action::kNone, S::kNull},  // kSmallpool
    {Sprite::kBrs1, 0, false, -1, Action::kNone, S::kNull},  // kBrainstem
    {Sprite::kTlmp, 0, true, 4, Action::kNone, S::kTechlamp2},  // kTechlamp
    {Sprite::kTlmp, 1, true, 4, Action::kNone, S::kTechlamp3},  // kTechlamp2
    {Sprite::kTlmp, 2, true, 4, Action::kNone, S::kTechlamp4},  // kTechlamp3
    {Sprite::kTlmp, 3, true, 4, Action::kNone, S::kTechlamp},  // kTechlamp4
    {Sprite::kTlp2, 0, true, 4, Action::kNone, S::kTech2lamp2},  // kTech2lamp
    {Sprite::kTlp2, 1, true, 4, Action::kNone, S::kTech2lamp3},  // kTech2lamp2
    {Sprite::kTlp2, 2, true, 4, Action::kNone, S::kTech2lamp4},  // kTech2lamp3
    {Sprite::kTlp2, 3, true, 4, Action::kNone, S::kTech2lamp},  // kTech2lamp4
};

// editor number, spawn, health, see, see sound, reaction time, attack sound, pain,
// pain chance, pain sound, melee, missile, death, extreme death, death sound,
// speed, radius, height, mass, damage, active sound, flags, raise.
const ThingInfo kThingTypes[size_t(ThingType::kCount)] = {
    {-1, S::kPlay, 100, S::kPlayRun1, Sound::kNone, 0, Sound::kNone, S::kPlayPain,  // kPlayer
     255, Sound::kPlpain, S::kNull, S::kPlayAtk1, S::kPlayDie1, S::kPlayXdie1, Sound::kPldeth,
     0, 16*kFracUnit, 56*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kShootable | kDropoff | kPickup | kNotdmatch, S::kNull},
    {3004, S::kPossStnd, 20, S::kPossRun1, Sound::kPosit1, 8, Sound::kPistol, S::kPossPain,  // kPossessed
     200, Sound::kPopain, S::kNull, S::kPossAtk1, S::kPossDie1, S::kPossXdie1, Sound::kPodth1,
     8, 20*kFracUnit, 56*kFracUnit, 100, 0, Sound::kPosact,
     kSolid | kShootable | kCountkill, S::kPossRaise1},
    {9, S::kSposStnd, 30, S::kSposRun1, Sound::kPosit2, 8, Sound::kNone, S::kSposPain,  // kShotguy
     170, Sound::kPopain, S::kNull, S::kSposAtk1, S::kSposDie1, S::kSposXdie1, Sound::kPodth2,
     8, 20*kFracUnit, 56*kFracUnit, 100, 0, Sound::kPosact,
     kSolid | kShootable | kCountkill, S::kSposRaise1},
    {64, S::kVileStnd, 700, S::kVileRun1, Sound::kVilsit, 8, Sound::kNone, S::kVilePain,  // kVile
     10, Sound::kVipain, S::kNull, S::kVileAtk1, S::kVileDie1, S::kNull, Sound::kVildth,
     15, 20*kFracUnit, 56*kFracUnit, 500, 0, Sound::kVilact,
     kSolid | kShootable | kCountkill, S::kNull},
    {-1, S::kFire1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kFire
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNogravity, S::kNull},
    {66, S::kSkelStnd, 300, S::kSkelRun1, Sound::kSkesit, 8, Sound::kNone, S::kSkelPain,  // kUndead
     100, Sound::kPopain, S::kSkelFist1, S::kSkelMiss1, S::kSkelDie1, S::kNull, Sound::kSkedth,
     10, 20*kFracUnit, 56*kFracUnit, 500, 0, Sound::kSkeact,
     kSolid | kShootable | kCountkill, S::kSkelRaise1},
    {-1, S::kTracer, 1000, S::kNull, Sound::kSkeatk, 8, Sound::kNone, S::kNull,  // kTracer
     0, Sound::kNone, S::kNull, S::kNull, S::kTraceexp1, S::kNull, Sound::kBarexp,
     10*kFracUnit, 11*kFracUnit, 8*kFracUnit, 100, 10, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {-1, S::kSmoke1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kSmoke
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNogravity, S::kNull},
    {67, S::kFattStnd, 600, S::kFattRun1, Sound::kMansit, 8, Sound::kNone, S::kFattPain,  // kFatso
     80, Sound::kMnpain, S::kNull, S::kFattAtk1, S::kFattDie1, S::kNull, Sound::kMandth,
     8, 48*kFracUnit, 64*kFracUnit, 1000, 0, Sound::kPosact,
     kSolid | kShootable | kCountkill, S::kFattRaise1},
    {-1, S::kFatshot1, 1000, S::kNull, Sound::kFirsht, 8, Sound::kNone, S::kNull,  // kFatshot
     0, Sound::kNone, S::kNull, S::kNull, S::kFatshotx1, S::kNull, Sound::kFirxpl,
     20*kFracUnit, 6*kFracUnit, 8*kFracUnit, 100, 8, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {65, S::kCposStnd, 70, S::kCposRun1, Sound::kPosit2, 8, Sound::kNone, S::kCposPain,  // kChainguy
     170, Sound::kPopain, S::kNull, S::kCposAtk1, S::kCposDie1, S::kCposXdie1, Sound::kPodth2,
     8, 20*kFracUnit, 56*kFracUnit, 100, 0, Sound::kPosact,
     kSolid | kShootable | kCountkill, S::kCposRaise1},
    {3001, S::kTrooStnd, 60, S::kTrooRun1, Sound::kBgsit1, 8, Sound::kNone, S::kTrooPain,  // kTroop
     200, Sound::kPopain, S::kTrooAtk1, S::kTrooAtk1, S::kTrooDie1, S::kTrooXdie1, Sound::kBgdth1,
     8, 20*kFracUnit, 56*kFracUnit, 100, 0, Sound::kBgact,
     kSolid | kShootable | kCountkill, S::kTrooRaise1},
    {3002, S::kSargStnd, 150, S::kSargRun1, Sound::kSgtsit, 8, Sound::kSgtatk, S::kSargPain,  // kSergeant
     180, Sound::kDmpain, S::kSargAtk1, S::kNull, S::kSargDie1, S::kNull, Sound::kSgtdth,
     10, 30*kFracUnit, 56*kFracUnit, 400, 0, Sound::kDmact,
     kSolid | kShootable | kCountkill, S::kSargRaise1},
    {58, S::kSargStnd, 150, S::kSargRun1, Sound::kSgtsit, 8, Sound::kSgtatk, S::kSargPain,  // kShadows
     180, Sound::kDmpain, S::kSargAtk1, S::kNull, S::kSargDie1, S::kNull, Sound::kSgtdth,
     10, 30*kFracUnit, 56*kFracUnit, 400, 0, Sound::kDmact,
     kSolid | kShootable | kShadow | kCountkill, S::kSargRaise1},
    {3005, S::kHeadStnd, 400, S::kHeadRun1, Sound::kCacsit, 8, Sound::kNone, S::kHeadPain,  // kHead
     128, Sound::kDmpain, S::kNull, S::kHeadAtk1, S::kHeadDie1, S::kNull, Sound::kCacdth,
     8, 31*kFracUnit, 56*kFracUnit, 400, 0, Sound::kDmact,
     kSolid | kShootable | kFloat | kNogravity | kCountkill, S::kHeadRaise1},
    {3003, S::kBossStnd, 1000, S::kBossRun1, Sound::kBrssit, 8, Sound::kNone, S::kBossPain,  // kBruiser
     50, Sound::kDmpain, S::kBossAtk1, S::kBossAtk1, S::kBossDie1, S::kNull, Sound::kBrsdth,
     8, 24*kFracUnit, 64*kFracUnit, 1000, 0, Sound::kDmact,
     kSolid | kShootable | kCountkill, S::kBossRaise1},
    {-1, S::kBrball1, 1000, S::kNull, Sound::kFirsht, 8, Sound::kNone, S::kNull,  // kBruisershot
     0, Sound::kNone, S::kNull, S::kNull, S::kBrballx1, S::kNull, Sound::kFirxpl,
     15*kFracUnit, 6*kFracUnit, 8*kFracUnit, 100, 8, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {69, S::kBos2Stnd, 500, S::kBos2Run1, Sound::kKntsit, 8, Sound::kNone, S::kBos2Pain,  // kKnight
     50, Sound::kDmpain, S::kBos2Atk1, S::kBos2Atk1, S::kBos2Die1, S::kNull, Sound::kKntdth,
     8, 24*kFracUnit, 64*kFracUnit, 1000, 0, Sound::kDmact,
     kSolid | kShootable | kCountkill, S::kBos2Raise1},
    {3006, S::kSkullStnd, 100, S::kSkullRun1, Sound::kNone, 8, Sound::kSklatk, S::kSkullPain,  // kSkull
     256, Sound::kDmpain, S::kNull, S::kSkullAtk1, S::kSkullDie1, S::kNull, Sound::kFirxpl,
     8, 16*kFracUnit, 56*kFracUnit, 50, 3, Sound::kDmact,
     kSolid | kShootable | kFloat | kNogravity, S::kNull},
    {7, S::kSpidStnd, 3000, S::kSpidRun1, Sound::kSpisit, 8, Sound::kShotgn, S::kSpidPain,  // kSpider
     40, Sound::kDmpain, S::kNull, S::kSpidAtk1, S::kSpidDie1, S::kNull, Sound::kSpidth,
     12, 128*kFracUnit, 100*kFracUnit, 1000, 0, Sound::kDmact,
     kSolid | kShootable | kCountkill, S::kNull},
    {68, S::kBspiStnd, 500, S::kBspiSight, Sound::kBspsit, 8, Sound::kNone, S::kBspiPain,  // kBaby
     128, Sound::kDmpain, S::kNull, S::kBspiAtk1, S::kBspiDie1, S::kNull, Sound::kBspdth,
     12, 64*kFracUnit, 64*kFracUnit, 600, 0, Sound::kBspact,
     kSolid | kShootable | kCountkill, S::kBspiRaise1},
    {16, S::kCyberStnd, 4000, S::kCyberRun1, Sound::kCybsit, 8, Sound::kNone, S::kCyberPain,  // kCyborg
     20, Sound::kDmpain, S::kNull, S::kCyberAtk1, S::kCyberDie1, S::kNull, Sound::kCybdth,
     16, 40*kFracUnit, 110*kFracUnit, 1000, 0, Sound::kDmact,
     kSolid | kShootable | kCountkill, S::kNull},
    {71, S::kPainStnd, 400, S::kPainRun1, Sound::kPesit, 8, Sound::kNone, S::kPainPain,  // kPain
     128, Sound::kPepain, S::kNull, S::kPainAtk1, S::kPainDie1, S::kNull, Sound::kPedth,
     8, 31*kFracUnit, 56*kFracUnit, 400, 0, Sound::kDmact,
     kSolid | kShootable | kFloat | kNogravity | kCountkill, S::kPainRaise1},
    {84, S::kSswvStnd, 50, S::kSswvRun1, Sound::kSssit, 8, Sound::kNone, S::kSswvPain,  // kWolfss
     170, Sound::kPopain, S::kNull, S::kSswvAtk1, S::kSswvDie1, S::kSswvXdie1, Sound::kSsdth,
     8, 20*kFracUnit, 56*kFracUnit, 100, 0, Sound::kPosact,
     kSolid | kShootable | kCountkill, S::kSswvRaise1},
    {72, S::kKeenstnd, 100, S::kNull, Sound::kNone, 8, Sound::kNone, S::kKeenpain,  // kKeen
     256, Sound::kKeenpn, S::kNull, S::kNull, S::kCommkeen, S::kNull, Sound::kKeendt,
     0, 16*kFracUnit, 72*kFracUnit, 10000000, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity | kShootable | kCountkill, S::kNull},
    {88, S::kBrain, 250, S::kNull, Sound::kNone, 8, Sound::kNone, S::kBrainPain,  // kBossbrain
     255, Sound::kBospn, S::kNull, S::kNull, S::kBrainDie1, S::kNull, Sound::kBosdth,
     0, 16*kFracUnit, 16*kFracUnit, 10000000, 0, Sound::kNone,
     kSolid | kShootable, S::kNull},
    {89, S::kBraineye, 1000, S::kBraineyesee, Sound::kNone, 8, Sound::kNone, S::kNull,  // kBossspit
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 32*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNosector, S::kNull},
    {87, S::kNull, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kBosstarget
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 32*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNosector, S::kNull},
    {-1, S::kSpawn1, 1000, S::kNull, Sound::kBospit, 8, Sound::kNone, S::kNull,  // kSpawnshot
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kFirxpl,
     10*kFracUnit, 6*kFracUnit, 32*kFracUnit, 100, 3, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity | kNoclip, S::kNull},
    {-1, S::kSpawnfire1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kSpawnfire
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNogravity, S::kNull},
    {2035, S::kBar1, 20, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kBarrel
     0, Sound::kNone, S::kNull, S::kNull, S::kBexp, S::kNull, Sound::kBarexp,
     0, 10*kFracUnit, 42*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kShootable | kNoblood, S::kNull},
    {-1, S::kTball1, 1000, S::kNull, Sound::kFirsht, 8, Sound::kNone, S::kNull,  // kTroopshot
     0, Sound::kNone, S::kNull, S::kNull, S::kTballx1, S::kNull, Sound::kFirxpl,
     10*kFracUnit, 6*kFracUnit, 8*kFracUnit, 100, 3, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {-1, S::kRball1, 1000, S::kNull, Sound::kFirsht, 8, Sound::kNone, S::kNull,  // kHeadshot
     0, Sound::kNone, S::kNull, S::kNull, S::kRballx1, S::kNull, Sound::kFirxpl,
     10*kFracUnit, 6*kFracUnit, 8*kFracUnit, 100, 5, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {-1, S::kRocket, 1000, S::kNull, Sound::kRlaunc, 8, Sound::kNone, S::kNull,  // kRocket
     0, Sound::kNone, S::kNull, S::kNull, S::kExplode1, S::kNull, Sound::kBarexp,
     20*kFracUnit, 11*kFracUnit, 8*kFracUnit, 100, 20, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {-1, S::kPlasball, 1000, S::kNull, Sound::kPlasma, 8, Sound::kNone, S::kNull,  // kPlasma
     0, Sound::kNone, S::kNull, S::kNull, S::kPlasexp, S::kNull, Sound::kFirxpl,
     25*kFracUnit, 13*kFracUnit, 8*kFracUnit, 100, 5, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {-1, S::kBfgshot, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kBfg
     0, Sound::kNone, S::kNull, S::kNull, S::kBfgland, S::kNull, Sound::kRxplod,
     25*kFracUnit, 13*kFracUnit, 8*kFracUnit, 100, 100, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {-1, S::kArachPlaz, 1000, S::kNull, Sound::kPlasma, 8, Sound::kNone, S::kNull,  // kArachplaz
     0, Sound::kNone, S::kNull, S::kNull, S::kArachPlex, S::kNull, Sound::kFirxpl,
     25*kFracUnit, 13*kFracUnit, 8*kFracUnit, 100, 5, Sound::kNone,
     kNoblockmap | kMissile | kDropoff | kNogravity, S::kNull},
    {-1, S::kPuff1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kPuff
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNogravity, S::kNull},
    {-1, S::kBlood1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kBlood
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap, S::kNull},
    {-1, S::kTfog, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kTfog
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNogravity, S::kNull},
    {-1, S::kIfog, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kIfog
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNogravity, S::kNull},
    {14, S::kNull, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kTeleportman
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNosector, S::kNull},
    {-1, S::kBfgexp, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kExtrabfg
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap | kNogravity, S::kNull},
    {2018, S::kArm1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc0
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2019, S::kArm2, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc1
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2014, S::kBon1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc2
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {2015, S::kBon2, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc3
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {5, S::kBkey, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc4
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kNotdmatch, S::kNull},
    {13, S::kRkey, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc5
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kNotdmatch, S::kNull},
    {6, S::kYkey, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc6
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kNotdmatch, S::kNull},
    {39, S::kYskull, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc7
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kNotdmatch, S::kNull},
    {38, S::kRskull, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc8
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kNotdmatch, S::kNull},
    {40, S::kBskull, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc9
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kNotdmatch, S::kNull},
    {2011, S::kStim, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc10
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2012, S::kMedi, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc11
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2013, S::kSoul, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc12
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {2022, S::kPinv, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kInv
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {2023, S::kPstr, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc13
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {2024, S::kPins, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kIns
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {2025, S::kSuit, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc14
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2026, S::kPmap, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc15
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {2045, S::kPvis, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc16
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {83, S::kMega, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMega
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial | kCountitem, S::kNull},
    {2007, S::kClip, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kClip
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2048, S::kAmmo, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc17
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2010, S::kRock, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc18
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2046, S::kBrok, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc19
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2047, S::kCell, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc20
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {17, S::kCelp, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc21
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2008, S::kShel, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc22
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2049, S::kSbox, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc23
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {8, S::kBpak, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc24
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2006, S::kBfug, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc25
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2002, S::kMgun, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kChaingun
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2005, S::kCsaw, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc26
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2003, S::kLaun, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc27
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2004, S::kPlas, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc28
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {2001, S::kShot, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kShotgun
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {82, S::kShot2, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kSupershotgun
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSpecial, S::kNull},
    {85, S::kTechlamp, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc29
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {86, S::kTech2lamp, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc30
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {2028, S::kColu, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc31
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {30, S::kTallgrncol, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc32
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {31, S::kShrtgrncol, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc33
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {32, S::kTallredcol, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc34
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {33, S::kShrtredcol, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc35
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {37, S::kSkullcol, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc36
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {36, S::kHeartcol, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc37
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {41, S::kEvileye, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc38
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {42, S::kFloatskull, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc39
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {43, S::kTorchtree, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc40
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {44, S::kBluetorch, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc41
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {45, S::kGreentorch, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc42
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {46, S::kRedtorch, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc43
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {55, S::kBtorchshrt, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc44
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {56, S::kGtorchshrt, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc45
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {57, S::kRtorchshrt, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc46
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {47, S::kStalagtite, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc47
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {48, S::kTechpillar, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc48
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {34, S::kCandlestik, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc49
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {35, S::kCandelabra, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc50
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {49, S::kBloodytwitch, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc51
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 68*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {50, S::kMeat2, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc52
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 84*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {51, S::kMeat3, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc53
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 84*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {52, S::kMeat4, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc54
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 68*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {53, S::kMeat5, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc55
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 52*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {59, S::kMeat2, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc56
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 84*kFracUnit, 100, 0, Sound::kNone,
     kSpawnceiling | kNogravity, S::kNull},
    {60, S::kMeat4, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc57
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 68*kFracUnit, 100, 0, Sound::kNone,
     kSpawnceiling | kNogravity, S::kNull},
    {61, S::kMeat3, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc58
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 52*kFracUnit, 100, 0, Sound::kNone,
     kSpawnceiling | kNogravity, S::kNull},
    {62, S::kMeat5, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc59
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 52*kFracUnit, 100, 0, Sound::kNone,
     kSpawnceiling | kNogravity, S::kNull},
    {63, S::kBloodytwitch, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc60
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 68*kFracUnit, 100, 0, Sound::kNone,
     kSpawnceiling | kNogravity, S::kNull},
    {22, S::kHeadDie6, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc61
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {15, S::kPlayDie7, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc62
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {18, S::kPossDie5, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc63
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {21, S::kSargDie6, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc64
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {23, S::kSkullDie6, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc65
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {20, S::kTrooDie5, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc66
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {19, S::kSposDie5, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc67
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {10, S::kPlayXdie9, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc68
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {12, S::kPlayXdie9, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc69
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {28, S::kHeadsonstick, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc70
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {24, S::kGibs, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc71
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     0, S::kNull},
    {27, S::kHeadonastick, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc72
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {29, S::kHeadcandles, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc73
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {25, S::kDeadstick, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc74
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {26, S::kLivestick, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc75
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {54, S::kBigtree, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc76
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 32*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {70, S::kBbar1, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc77
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kSolid, S::kNull},
    {73, S::kHangnoguts, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc78
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 88*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {74, S::kHangbnobrain, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc79
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 88*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {75, S::kHangtlookdn, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc80
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 64*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {76, S::kHangtskull, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc81
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 64*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {77, S::kHangtlookup, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc82
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 64*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {78, S::kHangtnobrain, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc83
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 16*kFracUnit, 64*kFracUnit, 100, 0, Sound::kNone,
     kSolid | kSpawnceiling | kNogravity, S::kNull},
    {79, S::kColongibs, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc84
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap, S::kNull},
    {80, S::kSmallpool, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc85
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap, S::kNull},
    {81, S::kBrainstem, 1000, S::kNull, Sound::kNone, 8, Sound::kNone, S::kNull,  // kMisc86
     0, Sound::kNone, S::kNull, S::kNull, S::kNull, S::kNull, Sound::kNone,
     0, 20*kFracUnit, 16*kFracUnit, 100, 0, Sound::kNone,
     kNoblockmap, S::kNull},
};

const SoundInfo kSounds[size_t(Sound::kCount)] = {
    {"none", 0},
    {"pistol", 64},
    {"shotgn", 64},
    {"sgcock", 64},
    {"dshtgn", 64},
    {"dbopn", 64},
    {"dbcls", 64},
    {"dbload", 64},
    {"plasma", 64},
    {"bfg", 64},
    {"sawup", 64},
    {"sawidl", 118},
    {"sawful", 64},
    {"sawhit", 64},
    {"rlaunc", 64},
    {"rxplod", 70},
    {"firsht", 70},
    {"firxpl", 70},
    {"pstart", 100},
    {"pstop", 100},
    {"doropn", 100},
    {"dorcls", 100},
    {"stnmov", 119},
    {"swtchn", 78},
    {"swtchx", 78},
    {"plpain", 96},
    {"dmpain", 96},
    {"popain", 96},
    {"vipain", 96},
    {"mnpain", 96},
    {"pepain", 96},
    {"slop", 78},
    {"itemup", 78},
    {"wpnup", 78},
    {"oof", 96},
    {"telept", 32},
    {"posit1", 98},
    {"posit2", 98},
    {"posit3", 98},
    {"bgsit1", 98},
    {"bgsit2", 98},
    {"sgtsit", 98},
    {"cacsit", 98},
    {"brssit", 94},
    {"cybsit", 92},
    {"spisit", 90},
    {"bspsit", 90},
    {"kntsit", 90},
    {"vilsit", 90},
    {"mansit", 90},
    {"pesit", 90},
    {"sklatk", 70},
    {"sgtatk", 70},
    {"skepch", 70},
    {"vilatk", 70},
    {"claw", 70},
    {"skeswg", 70},
    {"pldeth", 32},
    {"pdiehi", 32},
    {"podth1", 70},
    {"podth2", 70},
    {"podth3", 70},
    {"bgdth1", 70},
    {"bgdth2", 70},
    {"sgtdth", 70},
    {"cacdth", 70},
    {"skldth", 70},
    {"brsdth", 32},
    {"cybdth", 32},
    {"spidth", 32},
    {"bspdth", 32},
    {"vildth", 32},
    {"kntdth", 32},
    {"pedth", 32},
    {"skedth", 32},
    {"posact", 120},
    {"bgact", 120},
    {"dmact", 120},
    {"bspact", 100},
    {"bspwlk", 100},
    {"vilact", 100},
    {"noway", 78},
    {"barexp", 60},
    {"punch", 64},
    {"hoof", 70},
    {"metal", 70},
    {"chgun", 64, Sound::kPistol, 150, 0},
    {"tink", 60},
    {"bdopn", 100},
    {"bdcls", 100},
    {"itmbk", 100},
    {"flame", 32},
    {"flamst", 32},
    {"getpow", 60},
    {"bospit", 70},
    {"boscub", 70},
    {"bossit", 70},
    {"bospn", 70},
    {"bosdth", 70},
    {"manatk", 70},
    {"mandth", 70},
    {"sssit", 70},
    {"ssdth", 70},
    {"keenpn", 70},
    {"keendt", 70},
    {"skeact", 70},
    {"skesit", 70},
    {"skeatk", 70},
    {"radio", 60},
};

ThingType thing_type_for_editor_number(int editor_number) {
  if (editor_number >= 1 && editor_number <= 4) return ThingType::kPlayer;
  const ThingInfo* begin = kThingTypes;
  const ThingInfo* end = kThingTypes + size_t(ThingType::kCount);
  const ThingInfo* it = std::find_if(begin, end, [&](const ThingInfo& t) { return t.editor_number == editor_number; });
  return it == end ? ThingType::kCount : ThingType(it - begin);
}

}  // namespace p3d::play
