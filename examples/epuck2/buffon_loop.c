/* The Buffon control loop a firmware runs: IR readings in, the antkit behaviour's step, wheel
 * speeds out; in visit 2 the trail sensor in, the detector's count out (issue 27). The behaviour
 * keeps 160 bytes of state and the detector 8; the loop needs no map and no allocation.
 *
 * Copy this file and buffon_board.h into your firmware, implement buffon_board.h for your robot
 * (buffon_board_epuck2.c is a start for the e-puck2), and compile antkit's c/src/antkit.cpp with
 * it (the flags of mcu/CMakeLists.txt: -fno-exceptions -fno-rtti, C++20). The behaviour's step is
 * the one `antkit buffon` runs; scripts/run-on-mcu.sh rs runs these calls on an emulated
 * Cortex-M4 and prints the host's hash. */
#include "buffon_loop.h"

#include "buffon_board.h"

enum { kBuffonExperiment = 4 }; /* the experiment word of `antkit buffon`'s streams */

void buffon_visit(uint64_t seed, uint64_t trial, int visit, uint32_t steps, buffon_visit_log* log) {
  antkit_buffon_behaviour behaviour;
  antkit_buffon_detector detector;
  uint32_t s;
  antkit_buffon_behaviour_init(&behaviour, seed, kBuffonExperiment, trial, (uint64_t)visit);
  antkit_buffon_detector_init(&detector);
  antkit_trace_hash_init(&log->hash, seed);
  log->steps = 0;
  log->crossings = 0;
  /* Visit 2 reads the trail where it starts and after every step, as `antkit buffon` does. */
  if (visit == 2 && antkit_buffon_detector_update(&detector, buffon_board_read_trail()))
    ++log->crossings;
  for (s = 0; s < steps; ++s) {
    antkit_ir_reading ir;
    antkit_wheel_command wheels;
    int32_t r, w_left, w_right;
    buffon_board_read_ir(&ir);
    wheels = antkit_buffon_behaviour_step(&behaviour, &ir);
    buffon_board_step(wheels, visit == 1);
    if (visit == 2 && antkit_buffon_detector_update(&detector, buffon_board_read_trail()))
      ++log->crossings;
    antkit_buffon_behaviour_state(&behaviour, &r, &w_left, &w_right);
    antkit_trace_hash_add_i32(&log->hash, r);
    antkit_trace_hash_add_i32(&log->hash, w_left);
    antkit_trace_hash_add_i32(&log->hash, w_right);
    ++log->steps;
  }
  buffon_board_stop();
}
