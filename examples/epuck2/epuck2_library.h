/* The calls of the e-puck2's firmware library that board_epuck2.c makes, declared here so that the
 * example compiles without that library (CI compiles it for the Cortex-M4; it is not run on a
 * robot). In a real firmware, include the library's own headers instead: GCtronic's
 * e-puck2_main-processor project, src/motors.h, src/leds.h and src/sensors/proximity.h, and
 * ChibiOS's ch.h and hal.h (where chThdSleepMilliseconds is a macro over chThdSleep). Check these
 * against the version you build with. */
#ifndef ANTKIT_EXAMPLE_EPUCK2_LIBRARY_H
#define ANTKIT_EXAMPLE_EPUCK2_LIBRARY_H

#include <stdint.h>

/* ChibiOS */
void halInit(void);
void chSysInit(void);
void chThdSleepMilliseconds(uint32_t milliseconds);

/* motors.h: stepper motors, speed in steps per second (about -1100 .. 1100), 1000 steps per turn
 * of a wheel; the position counters count steps. */
void motors_init(void);
void left_motor_set_speed(int speed);
void right_motor_set_speed(int speed);
int32_t left_motor_get_pos(void);
int32_t right_motor_get_pos(void);
void left_motor_set_pos(int32_t counter_value);
void right_motor_set_pos(int32_t counter_value);

/* leds.h: the four red LEDs of the ring (LED5 is the rear one). */
typedef enum { LED1, LED3, LED5, LED7, NUM_LED } led_name_t;
void set_led(led_name_t led_number, unsigned int value);

/* sensors/proximity.h: the eight IR proximity sensors (IR0 front-right .. IR7 front-left, see
 * buffon_board_epuck2.c); calibrated values grow from about 0 (nothing) to a few thousand
 * (contact). */
void proximity_start(void);
void calibrate_ir(void);
int get_calibrated_prox(unsigned int sensor_number);

#endif
