/* board.h on an e-puck2 (STM32F407, ChibiOS): the wheels and the rear LED through the e-puck2
 * library (epuck2_library.h lists the calls), the edge reading from your camera code.
 *
 * Geometry, from the e-puck2's datasheet (GCtronic): wheels of 41 mm diameter, 1000 motor steps
 * per turn (7.76 steps per mm), 53 mm between the wheels. A sub-cell is the robot's size; this
 * example takes 80 mm (the robot is 70 mm across): 621 steps straight on, and a quarter turn on
 * the spot is 41.6 mm of travel for each wheel, 323 steps. The robot starts on its start sub-cell
 * facing east (the map's x axis).
 *
 * The reading: paper 002's robot reads the floor's UV-lit edges with a camera looking down. That
 * pipeline (image, cell grid, edges) is the part this example does not write for you: implement
 * camera_read_edges() (antkit's devices/stc_floor does it on the host from a rendered or recorded
 * image, and documents each step). */
#include "board.h"
#include "epuck2_library.h"
#include "stc_loop.h"

enum {
  kStepsPerSubCell = 621,
  kStepsPerQuarterTurn = 323,
  kSpeed = 500, /* steps per second */
  kLitSteps = 120 /* the rear LED stays on for the first 15 mm of a marking move */
};

/* Yours: the camera pipeline (see above). */
void camera_read_edges(antkit_edge_reading* reading);

static int g_heading = ANTKIT_EAST;

static int32_t magnitude(int32_t v) {
  return v < 0 ? -v : v;
}

/* Runs the wheels at +-kSpeed until the left one has turned `steps` steps; the LED on for the
 * first lit_steps of them. */
static void drive(int left_sign, int right_sign, int32_t steps, int32_t lit_steps) {
  left_motor_set_pos(0);
  right_motor_set_pos(0);
  if (lit_steps > 0) set_led(LED5, 1);
  left_motor_set_speed(left_sign * kSpeed);
  right_motor_set_speed(right_sign * kSpeed);
  while (magnitude(left_motor_get_pos()) < steps) {
    if (lit_steps > 0 && magnitude(left_motor_get_pos()) >= lit_steps) set_led(LED5, 0);
    chThdSleepMilliseconds(2);
  }
  left_motor_set_speed(0);
  right_motor_set_speed(0);
  set_led(LED5, 0);
}

void board_read_edges(antkit_edge_reading* reading) {
  camera_read_edges(reading);
}

int board_move(int direction, int mark) {
  const int turn = (direction - g_heading) & 3; /* quarter turns counter-clockwise */
  if (turn == 1) drive(-1, 1, kStepsPerQuarterTurn, 0);
  if (turn == 2) drive(-1, 1, 2 * kStepsPerQuarterTurn, 0);
  if (turn == 3) drive(1, -1, kStepsPerQuarterTurn, 0);
  g_heading = direction;
  drive(1, 1, kStepsPerSubCell, mark ? kLitSteps : 0);
  return 1;
}

void board_stop(void) {
  left_motor_set_speed(0);
  right_motor_set_speed(0);
  set_led(LED5, 0);
}

/* The firmware's main: the arena's size and the start are the deployment's (here a 4 m x 3 m
 * room of 80 mm sub-cells, started in its north-west corner). */
int main(void) {
  stc_tour_log log;
  halInit();
  chSysInit();
  motors_init();
  stc_tour(50, 37, 0, 0, &log);
  for (;;) chThdSleepMilliseconds(1000); /* done: log.hash is the tour's trace hash */
}
