/* Chocolate Doom's conversion of music lumps to MIDI, hashed: for each file given, the
 * MIDI file Chocolate's I_SDL_RegisterSong hands to SDL_mixer (the lump as it is when
 * it is a MIDI file under 96 KiB, else src/mus2mid.c's conversion), one line each:
 *   NAME INPUT_BYTES INPUT_XXH3 OUTPUT_BYTES OUTPUT_XXH3      (XXH3-64 in hex; "fail" if mus2mid fails)
 * Each file is converted in a child process of its own: mus2mid keeps the channels'
 * velocities in statics, and a fresh process starts them at 127 as our converter does.
 * Built against a Chocolate Doom checkout by tools/peers/music_hashes.sh. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include <xxhash.h>

#include "memio.h"
#include "mus2mid.h"

/* memio.c allocates through Chocolate's zone allocator. */
void *Z_Malloc(int size, int tag, void *ptr) {
  (void)tag;
  (void)ptr;
  return malloc((size_t)size);
}
void Z_Free(void *ptr) { free(ptr); }

static void convert(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) { perror(path); exit(2); }
  fseek(f, 0, SEEK_END);
  const long len = ftell(f);
  fseek(f, 0, SEEK_SET);
  uint8_t *lump = malloc((size_t)len + 1);
  if (fread(lump, 1, (size_t)len, f) != (size_t)len) { perror(path); exit(2); }
  fclose(f);
  const char *name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
  printf("%s %ld %016llx ", name, len, (unsigned long long)XXH3_64bits(lump, (size_t)len));
  if (len > 4 && !memcmp(lump, "MThd", 4) && len < 96 * 1024) { /* I_SDL_RegisterSong's IsMid */
    printf("%ld %016llx\n", len, (unsigned long long)XXH3_64bits(lump, (size_t)len));
    return;
  }
  MEMFILE *in = mem_fopen_read(lump, (size_t)len), *out = mem_fopen_write();
  if (mus2mid(in, out)) {
    printf("fail\n");
    return;
  }
  void *midi;
  size_t midi_len;
  mem_get_buf(out, &midi, &midi_len);
  printf("%zu %016llx\n", midi_len, (unsigned long long)XXH3_64bits(midi, midi_len));
}

int main(int argc, char **argv) {
  for (int i = 1; i < argc; ++i) {
    fflush(stdout);
    const pid_t child = fork();
    if (child == 0) {
      convert(argv[i]);
      fflush(stdout);
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 1;
  }
  return 0;
}
