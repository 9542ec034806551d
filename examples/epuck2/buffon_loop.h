/* The Buffon example's control loop (buffon_loop.c). */
#ifndef ANTKIT_EXAMPLE_BUFFON_LOOP_H
#define ANTKIT_EXAMPLE_BUFFON_LOOP_H

#include <antkit/c/antkit.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct buffon_visit_log {
  antkit_trace_hash hash; /* the behaviour's state words, step by step (for a robot's own log) */
  uint32_t steps;
  uint32_t crossings; /* visit 2: the Buffon count BC, the detector's low-to-high transitions */
} buffon_visit_log;

/* One visit of paper 000's Buffon measurement (Section 4): the exploration behaviour of visit
 * `visit` (1 or 2) of trial `trial`, keyed as `antkit buffon` keys it (seed, experiment 4, trial,
 * visit), run for `steps` steps. Visit 1 lays the trail as it goes; visit 2 feeds the trail sensor
 * to the pheromone detector and counts the crossings. The area estimate is then
 * A = 2 L1 L2 / (pi BC), with L1 and L2 the trails' lengths from the robot's odometry (the
 * erosion correction is `antkit buffon-from-logs`'s). */
void buffon_visit(uint64_t seed, uint64_t trial, int visit, uint32_t steps, buffon_visit_log* log);

#ifdef __cplusplus
}
#endif

#endif
