#!/usr/bin/env bash
# Installs the Debian packages this project builds with, if any are missing.
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config dpkg-dev help2man lintian file libsdl2-dev libglm-dev libstb-dev libcli11-dev libgtest-dev libdeflate-dev libmimalloc-dev libxxhash-dev freedoom
          libfluidsynth-dev fluid-soundfont-gm freedm chocolate-doom
          clang lld libfuzzer-14-dev libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
