#!/usr/bin/env bash
# Writes tests/golden/music.hashes: Chocolate Doom's own conversion to MIDI of every
# input tests/wad/mus_test.cpp converts (the music lumps of freedoom1, freedoom2 and
# freedm as they are, the same re-scored as MUS, and random MUS scores), hashed.
#
#   tools/peers/music_hashes.sh CHOCOLATE_SRC [BUILD]
#
# CHOCOLATE_SRC is a Chocolate Doom checkout: its src/mus2mid.c and src/memio.c are
# compiled with tools/peers/mus2mid_hashes.c into a program in a temporary directory
# (nothing of Chocolate's enters the repository). BUILD (default build/) holds
# engine_tests, whose disabled test MusGolden.WriteInputs writes the inputs.
# CHOCOLATE_COMMIT names the checkout's commit when it is no git work tree.
set -euo pipefail
cd "$(dirname "$0")/../.."
src=${1:?usage: tools/peers/music_hashes.sh CHOCOLATE_SRC [BUILD]}
build=${2:-build}
commit=${CHOCOLATE_COMMIT:-$(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo unknown)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# doomtype.h includes the config.h that Chocolate's configure writes.
printf '#define HAVE_DECL_STRCASECMP 1\n#define HAVE_DECL_STRNCASECMP 1\n' >"$work/config.h"
cc -O2 -I"$work" -I"$src/src" $(pkg-config --cflags sdl2) tools/peers/mus2mid_hashes.c "$src/src/mus2mid.c" \
  "$src/src/memio.c" $(pkg-config --libs libxxhash) -o "$work/mus2mid_hashes"
mkdir "$work/inputs"
P3D_MUS_INPUTS="$work/inputs" "$build/tests/engine_tests" --gtest_also_run_disabled_tests \
  --gtest_filter=MusGolden.DISABLED_WriteInputs >/dev/null
version() { dpkg-query -W -f='${Version}' "$1" 2>/dev/null || echo "not installed"; }
{
  echo "# Chocolate Doom's conversion of music lumps to MIDI (git $commit): the MIDI file its"
  echo "# I_SDL_RegisterSong hands to SDL_mixer, the lump itself when it is a MIDI file under 96 KiB,"
  echo "# else src/mus2mid.c's conversion, each input converted in a fresh process."
  echo "# Inputs: every D_ lump of freedoom1.wad, freedoom2.wad (freedoom $(version freedoom)) and"
  echo "# freedm.wad (freedm $(version freedm)); the same re-scored as MUS (tests/support/mus_writer.h's"
  echo "# midi_to_mus: Freedoom's music is all MIDI); random MUS scores (random_mus, seed and groups)."
  echo "# Made by tools/peers/music_hashes.sh (tools/peers/mus2mid_hashes.c compiled with Chocolate's"
  echo "# src/mus2mid.c and src/memio.c); tests/wad/mus_test.cpp converts the same inputs and compares."
  echo "# kind source lump input_bytes input_xxh3 output_bytes output_xxh3 (XXH3-64)"
  (cd "$work/inputs" && "$work/mus2mid_hashes" *) | sed 's/~/ /g' | LC_ALL=C sort
} >tests/golden/music.hashes
echo "wrote tests/golden/music.hashes: $(grep -vc '^#' tests/golden/music.hashes) conversions" \
  "($(grep -c ' fail$' tests/golden/music.hashes || true) failed)"
