/* The robot's side of the Buffon example loop (buffon_loop.c): six IR readings and the trail
 * sensor in, wheel speeds and the trail marker out. buffon_board_epuck2.c implements it on an
 * e-puck2. */
#ifndef ANTKIT_EXAMPLE_BUFFON_BOARD_H
#define ANTKIT_EXAMPLE_BUFFON_BOARD_H

#include <antkit/c/antkit.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The six front IR readings I_0 (left, +90 degrees) .. I_5 (right, -90 degrees), each in
 * [0, 65536]: 0 when no wall is within the sensor's range, growing to 65536 at contact
 * (antkit_ir_reading). */
void buffon_board_read_ir(antkit_ir_reading* reading);

/* Non-zero when the sensor under the robot's centre sees visit 1's trail (the pheromone). */
int buffon_board_read_trail(void);

/* Runs the wheels at the controller's speeds (Q15.16, about -1.25 .. 1.25, antkit_wheel_command)
 * for one step's time, laying the trail under the robot when `lay_trail` is non-zero. */
void buffon_board_step(antkit_wheel_command wheels, int lay_trail);

/* Stops the wheels and the marker. */
void buffon_board_stop(void);

#ifdef __cplusplus
}
#endif

#endif
