/* antkit's C API for firmware (C99): the controllers a robot runs, and the trace hash.
 *
 * Each controller is a fixed-size struct, an init function and a step function that takes the
 * robot's readings and returns its command. Nothing here allocates, blocks or throws. The ant and
 * ant-edge state is the 2-byte struct you pass and nothing else, so a firmware can keep it in a
 * static, copy it, or store it in backup RAM; online STC and the simulated floor also keep a
 * pointer to the buffer you give them (their memory), which must stay where it is. The step
 * functions are the very C++ code `antkit stc` runs (the structs hold the C++ objects' bytes),
 * compiled freestanding; scripts/run-on-mcu.sh runs them on an emulated Cortex-M4 and prints the
 * same tour hash as the host (issue 27). examples/epuck2/stc_loop.c is a complete control loop
 * for an e-puck2.
 *
 * Conventions (algorithms/stc/include/antkit/stc/subcell.hpp):
 *   - Directions, counter-clockwise as drawn on a map with y downward: 0 east, 1 north (y - 1),
 *     2 west, 3 south (y + 1). Bit d of a mask refers to direction d.
 *   - The floor is cut into robot-sized sub-cells; each 2 x 2 block is a cell. A sub-cell's
 *     quadrant q names its place in its cell: 0 SE, 1 NE, 2 NW, 3 SW (antkit_stc_quadrant).
 *   - Marks: bit q of a cell's mask is set when its sub-cell q is marked (ant), or the cell's 12
 *     edge bits as ant.hpp documents them (ant-edge: the paper's robot lights the edge behind it).
 *
 * Build: link the antkit_c library (host), or compile c/src/antkit.cpp with the freestanding flags
 * of mcu/CMakeLists.txt (-fno-exceptions -fno-rtti; no heap, no iostream) into your firmware.
 */
#ifndef ANTKIT_C_ANTKIT_H
#define ANTKIT_C_ANTKIT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define ANTKIT_C_API_VERSION 1

/* ---- commands ------------------------------------------------------------------------------- */

/* What a controller asks of its body: drive one sub-cell in direction `move` (ANTKIT_EAST ..
 * ANTKIT_SOUTH), or ANTKIT_STOP (the tour is closed). `mark` non-zero: leave the variant's marker
 * on the sub-cell being left (ant: mark that sub-cell; ant-edge: light the edge behind the robot,
 * the one opposite `move`), before moving. */
enum { ANTKIT_EAST = 0, ANTKIT_NORTH = 1, ANTKIT_WEST = 2, ANTKIT_SOUTH = 3, ANTKIT_STOP = 4 };

typedef struct antkit_stc_command {
  uint8_t move;
  uint8_t mark;
} antkit_stc_command;

/* The quadrant (0 SE, 1 NE, 2 NW, 3 SW) of sub-cell (x, y). */
int antkit_stc_quadrant(int32_t x, int32_t y);

/* ---- ant-like STC (paper 002): marks on the floor are the robot's only memory -------------- */

/* Two bytes: the quadrant the robot stands in, and whether it has stopped. */
typedef struct antkit_ant_stc {
  uint8_t opaque[2];
} antkit_ant_stc;

/* What the robot reads before each step, for its own cell and the four neighbour cells (the
 * paper's five cells in the camera's view). free_neighbours: bit d set when the neighbour cell in
 * direction d is free (all four sub-cells free and inside the arena). here, neighbour[d]: bit q
 * set when sub-cell q of that cell is marked (a neighbour that is not free reads 0). */
typedef struct antkit_mark_reading {
  uint8_t free_neighbours;
  uint8_t here;
  uint8_t neighbour[4];
} antkit_mark_reading;

/* Starts a tour from the sub-cell of quadrant start_quadrant (its cell must be free). */
void antkit_ant_stc_init(antkit_ant_stc* state, int start_quadrant);
antkit_stc_command antkit_ant_stc_step(antkit_ant_stc* state, const antkit_mark_reading* reading);

/* ---- ant-edge STC: the same decision read from lit edges (the paper's real robot) ----------- */

typedef struct antkit_ant_edge_stc {
  uint8_t opaque[2];
} antkit_ant_edge_stc;

/* here, neighbour[d]: the cell's 12 edge bits (ant.hpp): bit e its sub-cell e's cross box, bit
 * 4 + e e's turn box, bit 8 + e e's own exterior edge in direction e. */
typedef struct antkit_edge_reading {
  uint8_t free_neighbours;
  uint16_t here;
  uint16_t neighbour[4];
} antkit_edge_reading;

void antkit_ant_edge_stc_init(antkit_ant_edge_stc* state, int start_quadrant);
antkit_stc_command antkit_ant_edge_stc_step(antkit_ant_edge_stc* state,
                                            const antkit_edge_reading* reading);

/* ---- online STC: the robot senses free neighbour cells and remembers the cells it has seen --- */

/* Its memory grows with the cells it sees: a table of tiles of 16 x 16 cells (256 bytes each) in a
 * buffer you give it. A robot that reaches a new cell when every tile is taken stops there
 * (ANTKIT_STOP; antkit_online_stc_overflowed says why). An arena of W x H cells needs at most
 * (W / 16 + 2) x (H / 16 + 2) tiles, wherever the robot starts. */
typedef struct antkit_online_stc {
  uint64_t opaque[16];
} antkit_online_stc;

/* free_neighbours: bit d set when the neighbour cell in direction d is free. */
typedef struct antkit_cell_reading {
  uint8_t free_neighbours;
} antkit_cell_reading;

/* The buffer bytes for `tiles` tiles (and the table that finds them). */
size_t antkit_online_stc_bytes(size_t tiles);
/* Starts a tour from the sub-cell of quadrant start_quadrant; buffer 8-byte aligned. 0, or -1 when
 * the buffer holds no tile or is not aligned. */
int antkit_online_stc_init(antkit_online_stc* state, void* buffer, size_t bytes,
                           int start_quadrant);
antkit_stc_command antkit_online_stc_step(antkit_online_stc* state,
                                          const antkit_cell_reading* reading);
/* Non-zero when the tour stopped because the memory was full. */
int antkit_online_stc_overflowed(const antkit_online_stc* state);
/* Tiles in use, and how many the buffer holds. */
size_t antkit_online_stc_tiles(const antkit_online_stc* state);
size_t antkit_online_stc_capacity(const antkit_online_stc* state);

/* ---- a simulated floor, to run a firmware loop on a computer -------------------------------- */

/* antkit's STC floor (algorithms/stc/include/antkit/stc/floor.hpp: the world `antkit stc` steps):
 * free and blocked sub-cells, the marks or lit edges the robot leaves, its position, and which
 * sub-cells it entered. A firmware author runs the robot's loop against it on a desk (or on the
 * chip: scripts/run-on-mcu.sh) and compares the tour with `antkit stc`'s. It lives in a buffer you
 * give it: antkit_stc_floor_bytes says how large. */
enum { ANTKIT_MARKER_SUBCELL = 1, ANTKIT_MARKER_EDGE = 2 };

typedef struct antkit_stc_floor {
  uint64_t opaque[40];
} antkit_stc_floor;

/* The bytes of buffer a floor of width x height sub-cells needs (2 bits per sub-cell, and per
 * cell with a one-cell border 1 byte for ANTKIT_MARKER_SUBCELL or 2 for ANTKIT_MARKER_EDGE);
 * 0 when the size is not in [2, 16384]. */
size_t antkit_stc_floor_bytes(int32_t width, int32_t height, int marker);
/* Lays the floor out in buffer (8-byte aligned), every sub-cell blocked; 0, or -1 when the size
 * or the marker is invalid or the buffer too small. */
int antkit_stc_floor_init(antkit_stc_floor* floor, void* buffer, size_t size, int32_t width,
                          int32_t height, int marker);
/* Frees sub-cell (x, y) (before antkit_stc_floor_start; outside the map: ignored). */
void antkit_stc_floor_set_free(antkit_stc_floor* floor, int32_t x, int32_t y);
/* Clears the marks and puts the robot on sub-cell (x, y): 0, or -1 unless its cell is free. */
int antkit_stc_floor_start(antkit_stc_floor* floor, int32_t x, int32_t y);
/* What the robot reads where it stands (read_cells: on any floor; marks and edges: on the floor of
 * that marker). */
void antkit_stc_floor_read_cells(antkit_stc_floor* floor, antkit_cell_reading* reading);
void antkit_stc_floor_read_marks(antkit_stc_floor* floor, antkit_mark_reading* reading);
void antkit_stc_floor_read_edges(antkit_stc_floor* floor, antkit_edge_reading* reading);
/* Carries out a command (mark, then move): 1 moved, 0 refused (ANTKIT_STOP, or a move into a
 * blocked sub-cell or off the map). */
int antkit_stc_floor_apply(antkit_stc_floor* floor, antkit_stc_command command);
void antkit_stc_floor_position(const antkit_stc_floor* floor, int32_t* x, int32_t* y);
/* Sub-cells entered at least once (the start included), and entries into one entered before. */
int64_t antkit_stc_floor_covered(const antkit_stc_floor* floor);
int64_t antkit_stc_floor_repeats(const antkit_stc_floor* floor);

/* ---- Buffon's needle: the exploration behaviour and the pheromone detector (paper 000) ------ */

/* The exploration behaviour of paper 000's Section 4.2 (algorithms/buffon/exploration.hpp: the
 * equations and the choices where the paper is silent), the very C++ step `antkit buffon` runs.
 * Numbers are Q15.16 fixed point: 65536 is 1.0. Its random terms come from its own keyed stream,
 * named by (seed, experiment, trial, robot) with purpose 0; `antkit buffon`'s visit v of trial t
 * is (seed, 4, t, v). 160 bytes of state, copied freely (nothing points into it). */
typedef struct antkit_buffon_behaviour {
  uint64_t opaque[20];
} antkit_buffon_behaviour;

/* The six front IR readings I_0 (left, +90 degrees) .. I_5 (right, -90 degrees), each in [0, 65536]
 * (1 - distance / range for the nearest wall within the sensor's range, 0 when none). */
typedef struct antkit_ir_reading {
  int32_t ir[6];
} antkit_ir_reading;

/* Wheel speeds m_l, m_r, Q15.16 in about [-1.25, 1.25] (the paper's units; your body scales them to
 * its own: `antkit buffon`'s Khepera moves 0.1683 robot diameters per step at speed 1). */
typedef struct antkit_wheel_command {
  int32_t left;
  int32_t right;
} antkit_wheel_command;

void antkit_buffon_behaviour_init(antkit_buffon_behaviour* state, uint64_t seed,
                                  uint64_t experiment, uint64_t trial, uint64_t robot);
antkit_wheel_command antkit_buffon_behaviour_step(antkit_buffon_behaviour* state,
                                                  const antkit_ir_reading* reading);

/* The behaviour's state words that `antkit buffon`'s trace hash and a robot's log record after each
 * step: r, w_l and w_r (Q15.16). Any pointer may be null. */
void antkit_buffon_behaviour_state(const antkit_buffon_behaviour* state, int32_t* r,
                                   int32_t* w_left, int32_t* w_right);

/* Randomized Search (paper 000, Section 8.1; algorithms/buffon/checkpoints.hpp) is this behaviour
 * started as visit 3, antkit_buffon_behaviour_init(&b, seed, 4, trial, 3), on a robot that marks
 * the floor under its body and counts the marks it lays on unmarked floor: the estimate is that
 * count times the mark's area. scripts/run-on-mcu.sh rs runs it through these functions. */

/* Visit 2's pheromone detector (algorithms/buffon/detector.hpp): a leaky integrator of the
 * pheromone bit under the robot's centre with a hysteresis threshold. Each low-to-high transition
 * is one Buffon count. */
typedef struct antkit_buffon_detector {
  uint64_t opaque[1];
} antkit_buffon_detector;

void antkit_buffon_detector_init(antkit_buffon_detector* state);
/* Feeds one reading of the pheromone (non-zero: on the trail); 1 when it counts a crossing. */
int antkit_buffon_detector_update(antkit_buffon_detector* state, int pheromone);

/* ---- paper 004's Random Wanderer, for a robot that only steps and turns ------------------- */

/* algorithms/uniform/step_turn.hpp: each step draws 0, 1 or 2 from the robot's keyed stream
 * (seed, 6, trial, robot, 3); 0 turns left 45 degrees, 2 turns right 45 degrees, 1 moves one cell
 * forward when the cell ahead is free and waits otherwise. Fed the front-free flags of `antkit
 * cover --algo rw`'s robot, it emits that robot's commands (scripts/run-on-mcu.sh wanderer runs it
 * through these functions). 64 bytes of state, copied freely. */
typedef struct antkit_step_turn_wanderer {
  uint64_t opaque[8];
} antkit_step_turn_wanderer;

enum {
  ANTKIT_WANDER_WAIT = 0,
  ANTKIT_WANDER_TURN_LEFT = 1,  /* 45 degrees counter-clockwise */
  ANTKIT_WANDER_TURN_RIGHT = 2, /* 45 degrees clockwise */
  ANTKIT_WANDER_FORWARD = 3     /* one cell ahead */
};

void antkit_step_turn_wanderer_init(antkit_step_turn_wanderer* state, uint64_t seed, uint64_t trial,
                                    uint64_t robot);
/* front_free non-zero: the cell ahead can be entered. Returns an ANTKIT_WANDER_* action. */
int antkit_step_turn_wanderer_step(antkit_step_turn_wanderer* state, int front_free);
/* The steps taken so far (with the last action, the whole state). */
uint64_t antkit_step_turn_wanderer_steps(const antkit_step_turn_wanderer* state);

/* ---- the trace hash (kernel/include/antkit/kernel/hash.hpp) --------------------------------- */

/* A 64-bit hash over a canonical little-endian byte stream; the same value on every CPU. */
typedef struct antkit_trace_hash {
  uint64_t opaque[4];
} antkit_trace_hash;

void antkit_trace_hash_init(antkit_trace_hash* hash, uint64_t seed);
void antkit_trace_hash_add_u8(antkit_trace_hash* hash, uint8_t value);
void antkit_trace_hash_add_u32(antkit_trace_hash* hash, uint32_t value);
void antkit_trace_hash_add_i32(antkit_trace_hash* hash, int32_t value);
void antkit_trace_hash_add_u64(antkit_trace_hash* hash, uint64_t value);
/* The hash of everything added so far (the hash stays usable). */
uint64_t antkit_trace_hash_finish(const antkit_trace_hash* hash);

/* An STC tour's trace hash, as `antkit stc` prints it: begin with the arena's size in sub-cells
 * and the start, then add every position of the tour, the start first. */
void antkit_stc_tour_hash_begin(antkit_trace_hash* hash, int32_t width, int32_t height,
                                int32_t start_x, int32_t start_y);
void antkit_stc_tour_hash_add(antkit_trace_hash* hash, int32_t x, int32_t y);

#ifdef __cplusplus
}
#endif

#endif /* ANTKIT_C_ANTKIT_H */
