/* The example's control loop (stc_loop.c). */
#ifndef ANTKIT_EXAMPLE_STC_LOOP_H
#define ANTKIT_EXAMPLE_STC_LOOP_H

#include <antkit/c/antkit.h>

typedef struct stc_tour_log {
  antkit_trace_hash hash; /* the tour's trace hash, as `antkit stc` prints it */
  int32_t x, y;           /* where the robot believes it stands (dead reckoning in sub-cells) */
  int64_t moves;
  int refused; /* non-zero: the board could not make a move the controller asked for */
} stc_tour_log;

/* Covers the free cells connected to the start with ant-like STC (ant-edge: the robot lights
 * the edge behind it, as paper 002's robot does), from sub-cell (start_x, start_y) of an arena of
 * width x height sub-cells, facing east. Returns when the tour is closed (the robot stands next to
 * its start) or the board refuses a move. */
void stc_tour(int32_t width, int32_t height, int32_t start_x, int32_t start_y, stc_tour_log* log);

#endif
