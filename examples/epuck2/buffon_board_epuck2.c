/* buffon_board.h on an e-puck2 (STM32F407, ChibiOS): the IR proximity sensors and the wheels
 * through the e-puck2 library (epuck2_library.h lists the calls); the trail's marker and sensor
 * are yours.
 *
 * IR: the e-puck2's eight proximity sensors sit at about +-17, +-49, +-90 and +-150 degrees
 * (IR0 front-right, IR1 right-front, IR2 right, IR3 back-right, IR4 back-left, IR5 left, IR6
 * left-front, IR7 front-left). The behaviour's six front readings, left to right, are IR5, IR6,
 * IR7, IR0, IR1, IR2, each scaled from the calibrated value (0 far, about kProxContact at
 * contact) to [0, 65536]. The paper's Khepera sensors are not at these angles: the behaviour runs
 * all the same, but its walks are the e-puck2's, not `antkit buffon`'s simulated Khepera's.
 *
 * Wheels: speed 1.0 (65536) is kStepsPerSecondAtOne motor steps per second (1000 steps per wheel
 * turn of 41 mm, so 1.0 is about 26 mm/s, a step of kStepMs moves at most 1.25 x 26 x 0.25 mm).
 *
 * The trail: paper 000's robot lays a pheromone; a robot may draw a line (a pen or a UV LED on
 * phosphorescent floor) and read it with a ground sensor. trail_marker_set() and
 * trail_sensor_read() are those two, for your hardware. */
#include "buffon_board.h"
#include "buffon_loop.h"
#include "epuck2_library.h"

enum {
  kProxContact = 3000,        /* calibrated proximity at contact (check on your robot) */
  kStepsPerSecondAtOne = 200, /* motor steps per second at wheel speed 1.0 */
  kStepMs = 250               /* one behaviour step */
};

/* Yours: the trail's marker and sensor (see above). */
void trail_marker_set(int on);
int trail_sensor_read(void);

static int32_t scale_prox(int value) {
  if (value <= 0) return 0;
  if (value >= kProxContact) return 65536;
  return (int32_t)(((int64_t)value * 65536) / kProxContact);
}

void buffon_board_read_ir(antkit_ir_reading* reading) {
  static const unsigned sensor[6] = {5, 6, 7, 0, 1, 2}; /* left (+90) to right (-90) */
  int i;
  for (i = 0; i < 6; ++i) reading->ir[i] = scale_prox(get_calibrated_prox(sensor[i]));
}

int buffon_board_read_trail(void) {
  return trail_sensor_read();
}

static int wheel_speed(int32_t q16) {
  return (int)(((int64_t)q16 * kStepsPerSecondAtOne) / 65536);
}

void buffon_board_step(antkit_wheel_command wheels, int lay_trail) {
  trail_marker_set(lay_trail);
  left_motor_set_speed(wheel_speed(wheels.left));
  right_motor_set_speed(wheel_speed(wheels.right));
  chThdSleepMilliseconds(kStepMs);
}

void buffon_board_stop(void) {
  left_motor_set_speed(0);
  right_motor_set_speed(0);
  trail_marker_set(0);
}

/* The firmware's main: both visits of trial 0 with seed 1, 5000 steps each (about 21 minutes per
 * visit at kStepMs), the robot put back at its start between them. */
int main(void) {
  buffon_visit_log visit1, visit2;
  halInit();
  chSysInit();
  motors_init();
  proximity_start();
  calibrate_ir();
  buffon_visit(1, 0, 1, 5000, &visit1);
  chThdSleepMilliseconds(60000); /* a minute to carry the robot back to its start */
  buffon_visit(1, 0, 2, 5000, &visit2);
  for (;;) chThdSleepMilliseconds(1000); /* done: visit2.crossings is the Buffon count BC */
}
