/* LD_PRELOAD shim for timing Chocolate/Crispy Doom demos: SDL_GetTicks() runs
 * TICKS_DILATE times faster than real time. The ports count a timedemo in 1/35 s
 * "realtics", too coarse for a demo that renders in well under a second; at 100x a
 * realtic is 0.286 ms. Only the game's own calls are affected (SDL uses its copy). */
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

static uint64_t start_ns, dilation = 1;

static uint64_t monotonic_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

__attribute__((constructor)) static void init(void) {
  const char* text = getenv("TICKS_DILATE");
  if (text && atoi(text) > 0) dilation = (uint64_t)atoi(text);
  start_ns = monotonic_ns();
}

/* Never 0: the ports take a zero base time for "not started". */
uint32_t SDL_GetTicks(void) { return (uint32_t)(1 + (monotonic_ns() - start_ns) * dilation / 1000000u); }
