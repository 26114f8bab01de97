// Random level generators for tests and benchmarks, and the .map writer.
//
// Content is a pure function of (seed, cell coordinates), and cells are filled
// in a spiral from the origin, so a smaller map is exactly the middle of a larger
// one: the same camera sees the same surroundings at every size.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/map/source.h"

namespace p3d::map {

struct GenerateOptions {
  size_t walls = 1000;  // target wall count (soups: exact; rooms: at least this many)
  uint64_t seed = 1;
  // Texture names and images; walls and flats pick among them. At least one.
  std::vector<Texture> textures;
};

// Non-crossing plain segments, about two per 128-unit cell, under one default sector.
Source generate_soup(const GenerateOptions& options);

// A grid of rooms (own floor, ceiling and light; some with a pillar) joined by
// doorways through 16-unit-thick walls.
Source generate_rooms(const GenerateOptions& options);

// Rooms and figures a compiler splitting only along walls struggles with, `walls` walls
// each, every vertex rounded to the 1/256 grid: "circle" (radius 1,000,000 at 100,000
// walls, scaled as walls squared: rounding bends a few vertices inward), "ellipse"
// (the same, 2.5 times wider than high), "jitter" (a circle whose vertices move in or out
// by up to a sixteenth of a wall), "star" (spikes half the radius deep), "fan" (plain
// segments meeting at the centre), "spiral" (a corridor winding round about sqrt(walls)
// / 16 times), "comb" (a room with a tooth for every four walls), "rings" (nested rooms
// of sqrt(walls) / 32 circles, each a sector). The player starts inside.
Source generate_shape(const std::string& kind, const GenerateOptions& options);
const std::vector<std::string>& shape_kinds();

// A .grid tile map as text. kind "maze": a labyrinth of corridors with rooms carved
// in and some loops; kind "caves": random solid tiles (30%); kind "arena": one open
// hall with sparse pillars (1%), for long sight lines. cols and rows at least 8.
// textures name the texture files (the first five texture walls, then floor, ceiling).
struct GridOptions {
  std::string kind = "maze";
  int cols = 64, rows = 64;
  int cell = 64;
  uint64_t seed = 1;
  std::vector<std::string> texture_files;  // 7 files: 5 wall textures, floor, ceiling
};
std::string generate_grid_text(const GridOptions& options);

// Small procedural textures for generated maps when no files are at hand.
std::vector<Texture> builtin_textures();

// The .map text of a source; texture_files[i] is the file written for texture i.
std::string to_map_text(const Source& source, const std::vector<std::string>& texture_files);

}  // namespace p3d::map
