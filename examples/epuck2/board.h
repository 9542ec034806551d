/* The robot's side of the example loop (stc_loop.c): what it senses and how it moves. Two boards
 * implement it: board_epuck2.c on an e-puck2 (motors and LEDs through the e-puck2 library), and
 * board_sim.c on a computer (antkit's simulated floor, so that the loop's tour can be compared
 * with `antkit stc`'s). */
#ifndef ANTKIT_EXAMPLE_BOARD_H
#define ANTKIT_EXAMPLE_BOARD_H

#include <antkit/c/antkit.h>

/* The lit edges of the robot's cell and of its four neighbours, and which neighbours are free
 * (antkit_edge_reading documents the bits). On a robot this is the camera's job: paper 002 reads
 * UV-lit edges with a downward camera (antkit's devices/stc_floor implements that pipeline on the
 * host, from the image to this reading). */
void board_read_edges(antkit_edge_reading* reading);

/* Turns to face `direction` (ANTKIT_EAST .. ANTKIT_SOUTH) and drives one sub-cell, lighting the
 * edge behind the robot as it leaves when `mark` is non-zero. Returns 0 if it could not (a bumper,
 * a stall), non-zero once it stands in the next sub-cell. */
int board_move(int direction, int mark);

/* Stops the wheels and the lights. */
void board_stop(void);

#endif
