// Doom's thing table as data (Doom's info tables, in our layout): every state a
// thing can be in (its sprite, frame, tics, action and next state) and every type
// of thing (its states, health, speed, size, sounds and flags), for Doom and Doom
// II alike. The numbers are Doom's facts; a demo plays in sync only if each of
// them is Doom's. The rules that act on them read these tables; nothing here acts.
#pragma once

#include <cstdint>
#include <span>

#include "engine/play/fixed.h"

namespace p3d::play {

// Doom's sprites, in its order (a sprite is a lump-name prefix: kSpriteNames).
enum class Sprite : uint16_t {
  kTroo, kShtg, kPung, kPisg, kPisf, kShtf, kSht2, kChgg, kChgf, kMisg, kMisf, kSawg, kPlsg, kPlsf, kBfgg,
  kBfgf, kBlud, kPuff, kBal1, kBal2, kPlss, kPlse, kMisl, kBfs1, kBfe1, kBfe2, kTfog, kIfog, kPlay, kPoss,
  kSpos, kVile, kFire, kFatb, kFbxp, kSkel, kManf, kFatt, kCpos, kSarg, kHead, kBal7, kBoss, kBos2, kSkul,
  kSpid, kBspi, kApls, kApbx, kCybr, kPain, kSswv, kKeen, kBbrn, kBosf, kArm1, kArm2, kBar1, kBexp, kFcan,
  kBon1, kBon2, kBkey, kRkey, kYkey, kBsku, kRsku, kYsku, kStim, kMedi, kSoul, kPinv, kPstr, kPins, kMega,
  kSuit, kPmap, kPvis, kClip, kAmmo, kRock, kBrok, kCell, kCelp, kShel, kSbox, kBpak, kBfug, kMgun, kCsaw,
  kLaun, kPlas, kShot, kSgn2, kColu, kSmt2, kGor1, kPol2, kPol5, kPol4, kPol3, kPol1, kPol6, kGor2, kGor3,
  kGor4, kGor5, kSmit, kCol1, kCol2, kCol3, kCol4, kCand, kCbra, kCol6, kTre1, kTre2, kElec, kCeye, kFsku,
  kCol5, kTblu, kTgrn, kTred, kSmbt, kSmgt, kSmrt, kHdb1, kHdb2, kHdb3, kHdb4, kHdb5, kHdb6, kPob1, kPob2,
  kBrs1, kTlmp, kTlp2, kCount,
};

// What a state does when it is entered: monsters' (kLook, kChase...), weapons' (kWeaponReady,
// kFirePistol...) and the world's (kExplode...).
enum class Action : uint8_t {
  kNone, kLight0, kWeaponReady, kLower, kRaise, kPunch, kReFire, kFirePistol, kLight1, kFireShotgun, kLight2,
  kFireShotgun2, kCheckReload, kOpenShotgun2, kLoadShotgun2, kCloseShotgun2, kFireCGun, kGunFlash,
  kFireMissile, kSaw, kFirePlasma, kBFGsound, kFireBFG, kBFGSpray, kExplode, kPain, kPlayerScream, kFall,
  kXScream, kLook, kChase, kFaceTarget, kPosAttack, kScream, kSPosAttack, kVileChase, kVileStart,
  kVileTarget, kVileAttack, kStartFire, kFire, kFireCrackle, kTracer, kSkelWhoosh, kSkelFist, kSkelMissile,
  kFatRaise, kFatAttack1, kFatAttack2, kFatAttack3, kBossDeath, kCPosAttack, kCPosRefire, kTroopAttack,
  kSargAttack, kHeadAttack, kBruisAttack, kSkullAttack, kMetal, kSpidRefire, kBabyMetal, kBspiAttack, kHoof,
  kCyberAttack, kPainAttack, kPainDie, kKeenDie, kBrainPain, kBrainScream, kBrainDie, kBrainAwake,
  kBrainSpit, kSpawnSound, kSpawnFly, kBrainExplode, kCount,
};

// Every state, named after Doom's (S_TROO_STND is kTrooStnd).
enum class StateId : uint16_t {
  kNull, kLightdone, kPunch, kPunchdown, kPunchup, kPunch1, kPunch2, kPunch3, kPunch4, kPunch5, kPistol,
  kPistoldown, kPistolup, kPistol1, kPistol2, kPistol3, kPistol4, kPistolflash, kSgun, kSgundown, kSgunup,
  kSgun1, kSgun2, kSgun3, kSgun4, kSgun5, kSgun6, kSgun7, kSgun8, kSgun9, kSgunflash1, kSgunflash2, kDsgun,
  kDsgundown, kDsgunup, kDsgun1, kDsgun2, kDsgun3, kDsgun4, kDsgun5, kDsgun6, kDsgun7, kDsgun8, kDsgun9,
  kDsgun10, kDsnr1, kDsnr2, kDsgunflash1, kDsgunflash2, kChain, kChaindown, kChainup, kChain1, kChain2,
  kChain3, kChainflash1, kChainflash2, kMissile, kMissiledown, kMissileup, kMissile1, kMissile2, kMissile3,
  kMissileflash1, kMissileflash2, kMissileflash3, kMissileflash4, kSaw, kSawb, kSawdown, kSawup, kSaw1,
  kSaw2, kSaw3, kPlasma, kPlasmadown, kPlasmaup, kPlasma1, kPlasma2, kPlasmaflash1, kPlasmaflash2, kBfg,
  kBfgdown, kBfgup, kBfg1, kBfg2, kBfg3, kBfg4, kBfgflash1, kBfgflash2, kBlood1, kBlood2, kBlood3, kPuff1,
  kPuff2, kPuff3, kPuff4, kTball1, kTball2, kTballx1, kTballx2, kTballx3, kRball1, kRball2, kRballx1,
  kRballx2, kRballx3, kPlasball, kPlasball2, kPlasexp, kPlasexp2, kPlasexp3, kPlasexp4, kPlasexp5, kRocket,
  kBfgshot, kBfgshot2, kBfgland, kBfgland2, kBfgland3, kBfgland4, kBfgland5, kBfgland6, kBfgexp, kBfgexp2,
  kBfgexp3, kBfgexp4, kExplode1, kExplode2, kExplode3, kTfog, kTfog01, kTfog02, kTfog2, kTfog3, kTfog4,
  kTfog5, kTfog6, kTfog7, kTfog8, kTfog9, kTfog10, kIfog, kIfog01, kIfog02, kIfog2, kIfog3, kIfog4, kIfog5,
  kPlay, kPlayRun1, kPlayRun2, kPlayRun3, kPlayRun4, kPlayAtk1, kPlayAtk2, kPlayPain, kPlayPain2, kPlayDie1,
  kPlayDie2, kPlayDie3, kPlayDie4, kPlayDie5, kPlayDie6, kPlayDie7, kPlayXdie1, kPlayXdie2, kPlayXdie3,
  kPlayXdie4, kPlayXdie5, kPlayXdie6, kPlayXdie7, kPlayXdie8, kPlayXdie9, kPossStnd, kPossStnd2, kPossRun1,
  kPossRun2, kPossRun3, kPossRun4, kPossRun5, kPossRun6, kPossRun7, kPossRun8, kPossAtk1, kPossAtk2,
  kPossAtk3, kPossPain, kPossPain2, kPossDie1, kPossDie2, kPossDie3, kPossDie4, kPossDie5, kPossXdie1,
  kPossXdie2, kPossXdie3, kPossXdie4, kPossXdie5, kPossXdie6, kPossXdie7, kPossXdie8, kPossXdie9,
  kPossRaise1, kPossRaise2, kPossRaise3, kPossRaise4, kSposStnd, kSposStnd2, kSposRun1, kSposRun2, kSposRun3,
  kSposRun4, kSposRun5, kSposRun6, kSposRun7, kSposRun8, kSposAtk1, kSposAtk2, kSposAtk3, kSposPain,
  kSposPain2, kSposDie1, kSposDie2, kSposDie3, kSposDie4, kSposDie5, kSposXdie1, kSposXdie2, kSposXdie3,
  kSposXdie4, kSposXdie5, kSposXdie6, kSposXdie7, kSposXdie8, kSposXdie9, kSposRaise1, kSposRaise2,
  kSposRaise3, kSposRaise4, kSposRaise5, kVileStnd, kVileStnd2, kVileRun1, kVileRun2, kVileRun3, kVileRun4,
  kVileRun5, kVileRun6, kVileRun7, kVileRun8, kVileRun9, kVileRun10, kVileRun11, kVileRun12, kVileAtk1,
  kVileAtk2, kVileAtk3, kVileAtk4, kVileAtk5, kVileAtk6, kVileAtk7, kVileAtk8, kVileAtk9, kVileAtk10,
  kVileAtk11, kVileHeal1, kVileHeal2, kVileHeal3, kVilePain, kVilePain2, kVileDie1, kVileDie2, kVileDie3,
  kVileDie4, kVileDie5, kVileDie6, kVileDie7, kVileDie8, kVileDie9, kVileDie10, kFire1, kFire2, kFire3,
  kFire4, kFire5, kFire6, kFire7, kFire8, kFire9, kFire10, kFire11, kFire12, kFire13, kFire14, kFire15,
  kFire16, kFire17, kFire18, kFire19, kFire20, kFire21, kFire22, kFire23, kFire24, kFire25, kFire26, kFire27,
  kFire28, kFire29, kFire30, kSmoke1, kSmoke2, kSmoke3, kSmoke4, kSmoke5, kTracer, kTracer2, kTraceexp1,
  kTraceexp2, kTraceexp3, kSkelStnd, kSkelStnd2, kSkelRun1, kSkelRun2, kSkelRun3, kSkelRun4, kSkelRun5,
  kSkelRun6, kSkelRun7, kSkelRun8, kSkelRun9, kSkelRun10, kSkelRun11, kSkelRun12, kSkelFist1, kSkelFist2,
  kSkelFist3, kSkelFist4, kSkelMiss1, kSkelMiss2, kSkelMiss3, kSkelMiss4, kSkelPain, kSkelPain2, kSkelDie1,
  kSkelDie2, kSkelDie3, kSkelDie4, kSkelDie5, kSkelDie6, kSkelRaise1, kSkelRaise2, kSkelRaise3, kSkelRaise4,
  kSkelRaise5, kSkelRaise6, kFatshot1, kFatshot2, kFatshotx1, kFatshotx2, kFatshotx3, kFattStnd, kFattStnd2,
  kFattRun1, kFattRun2, kFattRun3, kFattRun4, kFattRun5, kFattRun6, kFattRun7, kFattRun8, kFattRun9,
  kFattRun10, kFattRun11, kFattRun12, kFattAtk1, kFattAtk2, kFattAtk3, kFattAtk4, kFattAtk5, kFattAtk6,
  kFattAtk7, kFattAtk8, kFattAtk9, kFattAtk10, kFattPain, kFattPain2, kFattDie1, kFattDie2, kFattDie3,
  kFattDie4, kFattDie5, kFattDie6, kFattDie7, kFattDie8, kFattDie9, kFattDie10, kFattRaise1, kFattRaise2,
  kFattRaise3, kFattRaise4, kFattRaise5, kFattRaise6, kFattRaise7, kFattRaise8, kCposStnd, kCposStnd2,
  kCposRun1, kCposRun2, kCposRun3, kCposRun4, kCposRun5, kCposRun6, kCposRun7, kCposRun8, kCposAtk1,
  kCposAtk2, kCposAtk3, kCposAtk4, kCposPain, kCposPain2, kCposDie1, kCposDie2, kCposDie3, kCposDie4,
  kCposDie5, kCposDie6, kCposDie7, kCposXdie1, kCposXdie2, kCposXdie3, kCposXdie4, kCposXdie5, kCposXdie6,
  kCposRaise1, kCposRaise2, kCposRaise3, kCposRaise4, kCposRaise5, kCposRaise6, kCposRaise7, kTrooStnd,
  kTrooStnd2, kTrooRun1, kTrooRun2, kTrooRun3, kTrooRun4, kTrooRun5, kTrooRun6, kTrooRun7, kTrooRun8,
  kTrooAtk1, kTrooAtk2, kTrooAtk3, kTrooPain, kTrooPain2, kTrooDie1, kTrooDie2, kTrooDie3, kTrooDie4,
  kTrooDie5, kTrooXdie1, kTrooXdie2, kTrooXdie3, kTrooXdie4, kTrooXdie5, kTrooXdie6, kTrooXdie7, kTrooXdie8,
  kTrooRaise1, kTrooRaise2, kTrooRaise3, kTrooRaise4, kTrooRaise5, kSargStnd, kSargStnd2, kSargRun1,
  kSargRun2, kSargRun3, kSargRun4, kSargRun5, kSargRun6, kSargRun7, kSargRun8, kSargAtk1, kSargAtk2,
  kSargAtk3, kSargPain, kSargPain2, kSargDie1, kSargDie2, kSargDie3, kSargDie4, kSargDie5, kSargDie6,
  kSargRaise1, kSargRaise2, kSargRaise3, kSargRaise4, kSargRaise5, kSargRaise6, kHeadStnd, kHeadRun1,
  kHeadAtk1, kHeadAtk2, kHeadAtk3, kHeadPain, kHeadPain2, kHeadPain3, kHeadDie1, kHeadDie2, kHeadDie3,
  kHeadDie4, kHeadDie5, kHeadDie6, kHeadRaise1, kHeadRaise2, kHeadRaise3, kHeadRaise4, kHeadRaise5,
  kHeadRaise6, kBrball1, kBrball2, kBrballx1, kBrballx2, kBrballx3, kBossStnd, kBossStnd2, kBossRun1,
  kBossRun2, kBossRun3, kBossRun4, kBossRun5, kBossRun6, kBossRun7, kBossRun8, kBossAtk1, kBossAtk2,
  kBossAtk3, kBossPain, kBossPain2, kBossDie1, kBossDie2, kBossDie3, kBossDie4, kBossDie5, kBossDie6,
  kBossDie7, kBossRaise1, kBossRaise2, kBossRaise3, kBossRaise4, kBossRaise5, kBossRaise6, kBossRaise7,
  kBos2Stnd, kBos2Stnd2, kBos2Run1, kBos2Run2, kBos2Run3, kBos2Run4, kBos2Run5, kBos2Run6, kBos2Run7,
  kBos2Run8, kBos2Atk1, kBos2Atk2, kBos2Atk3, kBos2Pain, kBos2Pain2, kBos2Die1, kBos2Die2, kBos2Die3,
  kBos2Die4, kBos2Die5, kBos2Die6, kBos2Die7, kBos2Raise1, kBos2Raise2, kBos2Raise3, kBos2Raise4,
  kBos2Raise5, kBos2Raise6, kBos2Raise7, kSkullStnd, kSkullStnd2, kSkullRun1, kSkullRun2, kSkullAtk1,
  kSkullAtk2, kSkullAtk3, kSkullAtk4, kSkullPain, kSkullPain2, kSkullDie1, kSkullDie2, kSkullDie3,
  kSkullDie4, kSkullDie5, kSkullDie6, kSpidStnd, kSpidStnd2, kSpidRun1, kSpidRun2, kSpidRun3, kSpidRun4,
  kSpidRun5, kSpidRun6, kSpidRun7, kSpidRun8, kSpidRun9, kSpidRun10, kSpidRun11, kSpidRun12, kSpidAtk1,
  kSpidAtk2, kSpidAtk3, kSpidAtk4, kSpidPain, kSpidPain2, kSpidDie1, kSpidDie2, kSpidDie3, kSpidDie4,
  kSpidDie5, kSpidDie6, kSpidDie7, kSpidDie8, kSpidDie9, kSpidDie10, kSpidDie11, kBspiStnd, kBspiStnd2,
  kBspiSight, kBspiRun1, kBspiRun2, kBspiRun3, kBspiRun4, kBspiRun5, kBspiRun6, kBspiRun7, kBspiRun8,
  kBspiRun9, kBspiRun10, kBspiRun11, kBspiRun12, kBspiAtk1, kBspiAtk2, kBspiAtk3, kBspiAtk4, kBspiPain,
  kBspiPain2, kBspiDie1, kBspiDie2, kBspiDie3, kBspiDie4, kBspiDie5, kBspiDie6, kBspiDie7, kBspiRaise1,
  kBspiRaise2, kBspiRaise3, kBspiRaise4, kBspiRaise5, kBspiRaise6, kBspiRaise7, kArachPlaz, kArachPlaz2,
  kArachPlex, kArachPlex2, kArachPlex3, kArachPlex4, kArachPlex5, kCyberStnd, kCyberStnd2, kCyberRun1,
  kCyberRun2, kCyberRun3, kCyberRun4, kCyberRun5, kCyberRun6, kCyberRun7, kCyberRun8, kCyberAtk1, kCyberAtk2,
  kCyberAtk3, kCyberAtk4, kCyberAtk5, kCyberAtk6, kCyberPain, kCyberDie1, kCyberDie2, kCyberDie3, kCyberDie4,
  kCyberDie5, kCyberDie6, kCyberDie7, kCyberDie8, kCyberDie9, kCyberDie10, kPainStnd, kPainRun1, kPainRun2,
  kPainRun3, kPainRun4, kPainRun5, kPainRun6, kPainAtk1, kPainAtk2, kPainAtk3, kPainAtk4, kPainPain,
  kPainPain2, kPainDie1, kPainDie2, kPainDie3, kPainDie4, kPainDie5, kPainDie6, kPainRaise1, kPainRaise2,
  kPainRaise3, kPainRaise4, kPainRaise5, kPainRaise6, kSswvStnd, kSswvStnd2, kSswvRun1, kSswvRun2, kSswvRun3,
  kSswvRun4, kSswvRun5, kSswvRun6, kSswvRun7, kSswvRun8, kSswvAtk1, kSswvAtk2, kSswvAtk3, kSswvAtk4,
  kSswvAtk5, kSswvAtk6, kSswvPain, kSswvPain2, kSswvDie1, kSswvDie2, kSswvDie3, kSswvDie4, kSswvDie5,
  kSswvXdie1, kSswvXdie2, kSswvXdie3, kSswvXdie4, kSswvXdie5, kSswvXdie6, kSswvXdie7, kSswvXdie8, kSswvXdie9,
  kSswvRaise1, kSswvRaise2, kSswvRaise3, kSswvRaise4, kSswvRaise5, kKeenstnd, kCommkeen, kCommkeen2,
  kCommkeen3, kCommkeen4, kCommkeen5, kCommkeen6, kCommkeen7, kCommkeen8, kCommkeen9, kCommkeen10,
  kCommkeen11, kCommkeen12, kKeenpain, kKeenpain2, kBrain, kBrainPain, kBrainDie1, kBrainDie2, kBrainDie3,
  kBrainDie4, kBraineye, kBraineyesee, kBraineye1, kSpawn1, kSpawn2, kSpawn3, kSpawn4, kSpawnfire1,
  kSpawnfire2, kSpawnfire3, kSpawnfire4, kSpawnfire5, kSpawnfire6, kSpawnfire7, kSpawnfire8, kBrainexplode1,
  kBrainexplode2, kBrainexplode3, kArm1, kArm1a, kArm2, kArm2a, kBar1, kBar2, kBexp, kBexp2, kBexp3, kBexp4,
  kBexp5, kBbar1, kBbar2, kBbar3, kBon1, kBon1a, kBon1b, kBon1c, kBon1d, kBon1e, kBon2, kBon2a, kBon2b,
  kBon2c, kBon2d, kBon2e, kBkey, kBkey2, kRkey, kRkey2, kYkey, kYkey2, kBskull, kBskull2, kRskull, kRskull2,
  kYskull, kYskull2, kStim, kMedi, kSoul, kSoul2, kSoul3, kSoul4, kSoul5, kSoul6, kPinv, kPinv2, kPinv3,
  kPinv4, kPstr, kPins, kPins2, kPins3, kPins4, kMega, kMega2, kMega3, kMega4, kSuit, kPmap, kPmap2, kPmap3,
  kPmap4, kPmap5, kPmap6, kPvis, kPvis2, kClip, kAmmo, kRock, kBrok, kCell, kCelp, kShel, kSbox, kBpak,
  kBfug, kMgun, kCsaw, kLaun, kPlas, kShot, kShot2, kColu, kStalag, kBloodytwitch, kBloodytwitch2,
  kBloodytwitch3, kBloodytwitch4, kDeadtorso, kDeadbottom, kHeadsonstick, kGibs, kHeadonastick, kHeadcandles,
  kHeadcandles2, kDeadstick, kLivestick, kLivestick2, kMeat2, kMeat3, kMeat4, kMeat5, kStalagtite,
  kTallgrncol, kShrtgrncol, kTallredcol, kShrtredcol, kCandlestik, kCandelabra, kSkullcol, kTorchtree,
  kBigtree, kTechpillar, kEvileye, kEvileye2, kEvileye3, kEvileye4, kFloatskull, kFloatskull2, kFloatskull3,
  kHeartcol, kHeartcol2, kBluetorch, kBluetorch2, kBluetorch3, kBluetorch4, kGreentorch, kGreentorch2,
  kGreentorch3, kGreentorch4, kRedtorch, kRedtorch2, kRedtorch3, kRedtorch4, kBtorchshrt, kBtorchshrt2,
  kBtorchshrt3, kBtorchshrt4, kGtorchshrt, kGtorchshrt2, kGtorchshrt3, kGtorchshrt4, kRtorchshrt,
  kRtorchshrt2, kRtorchshrt3, kRtorchshrt4, kHangnoguts, kHangbnobrain, kHangtlookdn, kHangtskull,
  kHangtlookup, kHangtnobrain, kColongibs, kSmallpool, kBrainstem, kTechlamp, kTechlamp2, kTechlamp3,
  kTechlamp4, kTech2lamp, kTech2lamp2, kTech2lamp3, kTech2lamp4, kCount,
};

// Every type of thing, named after Doom's (MT_TROOP is kTroop).
enum class ThingType : uint8_t {
  kPlayer, kPossessed, kShotguy, kVile, kFire, kUndead, kTracer, kSmoke, kFatso, kFatshot, kChainguy, kTroop,
  kSergeant, kShadows, kHead, kBruiser, kBruisershot, kKnight, kSkull, kSpider, kBaby, kCyborg, kPain,
  kWolfss, kKeen, kBossbrain, kBossspit, kBosstarget, kSpawnshot, kSpawnfire, kBarrel, kTroopshot, kHeadshot,
  kRocket, kPlasma, kBfg, kArachplaz, kPuff, kBlood, kTfog, kIfog, kTeleportman, kExtrabfg, kMisc0, kMisc1,
  kMisc2, kMisc3, kMisc4, kMisc5, kMisc6, kMisc7, kMisc8, kMisc9, kMisc10, kMisc11, kMisc12, kInv, kMisc13,
  kIns, kMisc14, kMisc15, kMisc16, kMega, kClip, kMisc17, kMisc18, kMisc19, kMisc20, kMisc21, kMisc22,
  kMisc23, kMisc24, kMisc25, kChaingun, kMisc26, kMisc27, kMisc28, kShotgun, kSupershotgun, kMisc29, kMisc30,
  kMisc31, kMisc32, kMisc33, kMisc34, kMisc35, kMisc36, kMisc37, kMisc38, kMisc39, kMisc40, kMisc41, kMisc42,
  kMisc43, kMisc44, kMisc45, kMisc46, kMisc47, kMisc48, kMisc49, kMisc50, kMisc51, kMisc52, kMisc53, kMisc54,
  kMisc55, kMisc56, kMisc57, kMisc58, kMisc59, kMisc60, kMisc61, kMisc62, kMisc63, kMisc64, kMisc65, kMisc66,
  kMisc67, kMisc68, kMisc69, kMisc70, kMisc71, kMisc72, kMisc73, kMisc74, kMisc75, kMisc76, kMisc77, kMisc78,
  kMisc79, kMisc80, kMisc81, kMisc82, kMisc83, kMisc84, kMisc85, kMisc86, kCount,
};

// Doom's sound effects; the lump of kPistol is DSPISTOL.
enum class Sound : uint8_t {
  kNone, kPistol, kShotgn, kSgcock, kDshtgn, kDbopn, kDbcls, kDbload, kPlasma, kBfg, kSawup, kSawidl,
  kSawful, kSawhit, kRlaunc, kRxplod, kFirsht, kFirxpl, kPstart, kPstop, kDoropn, kDorcls, kStnmov, kSwtchn,
  kSwtchx, kPlpain, kDmpain, kPopain, kVipain, kMnpain, kPepain, kSlop, kItemup, kWpnup, kOof, kTelept,
  kPosit1, kPosit2, kPosit3, kBgsit1, kBgsit2, kSgtsit, kCacsit, kBrssit, kCybsit, kSpisit, kBspsit, kKntsit,
  kVilsit, kMansit, kPesit, kSklatk, kSgtatk, kSkepch, kVilatk, kClaw, kSkeswg, kPldeth, kPdiehi, kPodth1,
  kPodth2, kPodth3, kBgdth1, kBgdth2, kSgtdth, kCacdth, kSkldth, kBrsdth, kCybdth, kSpidth, kBspdth, kVildth,
  kKntdth, kPedth, kSkedth, kPosact, kBgact, kDmact, kBspact, kBspwlk, kVilact, kNoway, kBarexp, kPunch,
  kHoof, kMetal, kChgun, kTink, kBdopn, kBdcls, kItmbk, kFlame, kFlamst, kGetpow, kBospit, kBoscub, kBossit,
  kBospn, kBosdth, kManatk, kMandth, kSssit, kSsdth, kKeenpn, kKeendt, kSkeact, kSkesit, kSkeatk, kRadio,
  kCount,
};

// A thing's flags, with Doom's bit values (DEHACKED patches name them by value).
enum ThingFlag : uint32_t {
  kSpecial = 1,
  kSolid = 2,
  kShootable = 4,
  kNosector = 8,
  kNoblockmap = 16,
  kAmbush = 32,
  kJusthit = 64,
  kJustattacked = 128,
  kSpawnceiling = 256,
  kNogravity = 512,
  kDropoff = 0x400,
  kPickup = 0x800,
  kNoclip = 0x1000,
  kSlide = 0x2000,
  kFloat = 0x4000,
  kTeleport = 0x8000,
  kMissile = 0x10000,
  kDropped = 0x20000,
  kShadow = 0x40000,
  kNoblood = 0x80000,
  kCorpse = 0x100000,
  kInfloat = 0x200000,
  kCountkill = 0x400000,
  kCountitem = 0x800000,
  kSkullfly = 0x1000000,
  kNotdmatch = 0x2000000,
  kTranslation = 0xc000000,
};
constexpr int kTranslationShift = 26;  // the kTranslation bits pick a green-to-other-colour map

constexpr int kInfiniteTics = -1;  // a state that lasts until something changes it

struct StateInfo {
  Sprite sprite;
  uint8_t frame;   // 0 is frame A
  bool bright;     // drawn at full light
  int16_t tics;    // kInfiniteTics: stays
  Action action;
  StateId next;
  int16_t misc1 = 0, misc2 = 0;  // an action's arguments (the weapon flashes' offsets)
};

struct ThingInfo {
  int16_t editor_number;  // in a map's THINGS; -1: only spawned by the game (missiles, puffs...)
  StateId spawn;
  int16_t health;
  StateId see;
  Sound see_sound;
  int16_t reaction_time;
  Sound attack_sound;
  StateId pain;
  int16_t pain_chance;  // out of 256
  Sound pain_sound;
  StateId melee, missile, death, extreme_death;
  Sound death_sound;
  Fixed speed;  // map units a step for monsters; 16.16 units a tic for missiles
  Fixed radius, height;
  int32_t mass, damage;
  Sound active_sound;
  uint32_t flags;  // ThingFlag bits
  StateId raise;   // where an Arch-vile's resurrection starts; kNull: cannot be raised
};

struct SoundInfo {
  char name[7];     // the lump is "DS" + name
  int8_t priority;  // higher wins a channel
  Sound link = Sound::kNone;  // played in its place (kChgun plays kPistol)
  int16_t link_pitch = -1, link_volume = 0;  // the link's pitch and volume change
};

extern const char kSpriteNames[size_t(Sprite::kCount)][5];
extern const StateInfo kStates[size_t(StateId::kCount)];
extern const ThingInfo kThingTypes[size_t(ThingType::kCount)];
extern const SoundInfo kSounds[size_t(Sound::kCount)];

inline const StateInfo& state_info(StateId s) { return kStates[size_t(s)]; }
inline const ThingInfo& thing_info(ThingType t) { return kThingTypes[size_t(t)]; }
// The type placed by an editor number, or kCount for none (player starts are type
// kPlayer with numbers 1 to 4).
ThingType thing_type_for_editor_number(int editor_number);

}  // namespace p3d::play
