/* A C consumer of the installed antkit::c: ant-like STC over the C API's simulated floor, a 6 x 4
 * sub-cell room with every sub-cell free, from its north-west corner. main.cpp compares the tour's
 * hash and coverage with the C++ run_stc's. */
#include <antkit/c/antkit.h>

uint64_t consumer_c_tour_hash(int64_t* covered) {
  static uint64_t buffer[64];
  antkit_stc_floor floor;
  antkit_ant_stc ant;
  antkit_trace_hash hash;
  int32_t x, y;
  if (antkit_stc_floor_bytes(6, 4, ANTKIT_MARKER_SUBCELL) > sizeof buffer ||
      antkit_stc_floor_init(&floor, buffer, sizeof buffer, 6, 4, ANTKIT_MARKER_SUBCELL) != 0)
    return 0;
  for (y = 0; y < 4; ++y)
    for (x = 0; x < 6; ++x) antkit_stc_floor_set_free(&floor, x, y);
  if (antkit_stc_floor_start(&floor, 0, 0) != 0) return 0;
  antkit_ant_stc_init(&ant, antkit_stc_quadrant(0, 0));
  antkit_stc_tour_hash_begin(&hash, 6, 4, 0, 0);
  antkit_stc_tour_hash_add(&hash, 0, 0);
  for (;;) {
    antkit_mark_reading reading;
    antkit_stc_command command;
    antkit_stc_floor_read_marks(&floor, &reading);
    command = antkit_ant_stc_step(&ant, &reading);
    if (command.move == ANTKIT_STOP || !antkit_stc_floor_apply(&floor, command)) break;
    antkit_stc_floor_position(&floor, &x, &y);
    antkit_stc_tour_hash_add(&hash, x, y);
  }
  *covered = antkit_stc_floor_covered(&floor);
  return antkit_trace_hash_finish(&hash);
}
