/* board.h on a computer: antkit's simulated floor (antkit_stc_floor) stands in for the e-puck2's
 * wheels and camera, so that the unchanged loop of stc_loop.c can be run on a desk and its tour
 * compared with `antkit stc --variant ant-edge`'s (tests/examples does, on shared maps).
 *
 *   epuck2_sim MAP.map X Y    prints {"hash": ..., "moves": ..., "covered": ..., "repeats": ...,
 *                             "refused": ...} for the tour from sub-cell (X, Y)
 *
 * MAP is a MovingAI map ('.', 'G' and 'S' free, any other character blocked, as antkit reads it).
 * Exit status 2 for a map it cannot read or a start it cannot use. */
#include "board.h"
#include "stc_loop.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static antkit_stc_floor g_floor;

void board_read_edges(antkit_edge_reading* reading) {
  antkit_stc_floor_read_edges(&g_floor, reading);
}

int board_move(int direction, int mark) {
  antkit_stc_command command;
  command.move = (uint8_t)direction;
  command.mark = (uint8_t)(mark != 0);
  return antkit_stc_floor_apply(&g_floor, command);
}

void board_stop(void) {}

static int fail(const char* where, const char* why) {
  fprintf(stderr, "epuck2_sim: error: %s: %s\n", where, why);
  return 2;
}

int main(int argc, char** argv) {
  FILE* in;
  char line[20000];
  long width = 0, height = 0, y = 0;
  size_t bytes;
  void* buffer;
  int32_t sx, sy;
  stc_tour_log log;
  if (argc != 4) return fail("usage", "epuck2_sim MAP.map X Y");
  in = fopen(argv[1], "r");
  if (!in) return fail(argv[1], "cannot open");
  while (fgets(line, sizeof line, in) && strncmp(line, "map", 3) != 0) {
    if (strncmp(line, "height ", 7) == 0) height = strtol(line + 7, NULL, 10);
    if (strncmp(line, "width ", 6) == 0) width = strtol(line + 6, NULL, 10);
  }
  bytes = antkit_stc_floor_bytes((int32_t)width, (int32_t)height, ANTKIT_MARKER_EDGE);
  if (bytes == 0) return fail(argv[1], "no width and height in [2, 16384] before its map line");
  buffer = malloc(bytes + 8);
  if (!buffer ||
      antkit_stc_floor_init(&g_floor, buffer, bytes, (int32_t)width, (int32_t)height,
                            ANTKIT_MARKER_EDGE) != 0)
    return fail(argv[1], "cannot lay out the floor");
  for (y = 0; y < height && fgets(line, sizeof line, in); ++y) {
    long x;
    for (x = 0; x < width && line[x] != '\0' && line[x] != '\n'; ++x)
      if (line[x] == '.' || line[x] == 'G' || line[x] == 'S')
        antkit_stc_floor_set_free(&g_floor, (int32_t)x, (int32_t)y);
  }
  fclose(in);
  if (y != height) return fail(argv[1], "fewer rows than its height");
  sx = (int32_t)strtol(argv[2], NULL, 10);
  sy = (int32_t)strtol(argv[3], NULL, 10);
  if (antkit_stc_floor_start(&g_floor, sx, sy) != 0)
    return fail("start", "not a sub-cell of a free cell of the map");
  stc_tour((int32_t)width, (int32_t)height, sx, sy, &log);
  printf("{\"hash\": \"%016" PRIx64 "\", \"moves\": %" PRId64 ", \"covered\": %" PRId64
         ", \"repeats\": %" PRId64 ", \"refused\": %s}\n",
         antkit_trace_hash_finish(&log.hash), log.moves, antkit_stc_floor_covered(&g_floor),
         antkit_stc_floor_repeats(&g_floor), log.refused ? "true" : "false");
  free(buffer);
  return 0;
}
