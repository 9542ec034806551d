/* The control loop a firmware runs: sensors in, the antkit controller's step, wheels out (issue
 * 27). It is the whole of the robot's coverage logic: the controller keeps two bytes of state and
 * the marks on the floor are its only memory, so the loop needs no map and no allocation. The
 * position it tracks is only for the log: the controller never reads it.
 *
 * Copy this file and board.h into your firmware, implement board.h for your robot (board_epuck2.c
 * is a start for the e-puck2), and compile antkit's c/src/antkit.cpp with it (the flags of
 * mcu/CMakeLists.txt: -fno-exceptions -fno-rtti, C++20). */
#include "stc_loop.h"

#include "board.h"

void stc_tour(int32_t width, int32_t height, int32_t start_x, int32_t start_y, stc_tour_log* log) {
  static const int32_t dx[4] = {1, 0, -1, 0}; /* east, north, west, south; y grows southward */
  static const int32_t dy[4] = {0, -1, 0, 1};
  antkit_ant_edge_stc controller;
  antkit_ant_edge_stc_init(&controller, antkit_stc_quadrant(start_x, start_y));
  antkit_stc_tour_hash_begin(&log->hash, width, height, start_x, start_y);
  antkit_stc_tour_hash_add(&log->hash, start_x, start_y);
  log->x = start_x;
  log->y = start_y;
  log->moves = 0;
  log->refused = 0;
  for (;;) {
    antkit_edge_reading seen;
    antkit_stc_command command;
    board_read_edges(&seen);
    command = antkit_ant_edge_stc_step(&controller, &seen);
    if (command.move == ANTKIT_STOP) break; /* the tour is closed */
    if (!board_move(command.move, command.mark)) {
      log->refused = 1;
      break;
    }
    log->x += dx[command.move];
    log->y += dy[command.move];
    antkit_stc_tour_hash_add(&log->hash, log->x, log->y);
    ++log->moves;
  }
  board_stop();
}
