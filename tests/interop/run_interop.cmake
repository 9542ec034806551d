# ctest interop.mcap: antkit's MCAP files held against the official readers under node
# (check_mcap.mjs: @mcap/core, @foxglove/schemas), from a committed recording (data/logs/):
#   export mcap            the channels and counts, and the same bytes twice (no clock in them);
#                          a 5000-step log on one thread and on three, the same bytes
#   replay --mcap          an identical replay: exit 0, recorded and replayed side by side
#   replay --mcap (edited) cmd[1] of step 40 edited: exit 1, one ERROR log at step 40
#   export mcap (bad log)  exit 2, a located error, no file
#   bag export             a ROS 2 bag's poses, the map and a check's result (both checks)
#   stc --mcap             an STC tour: the map, the spanning tree, a pose a step
#   cover --mcap           a coverage run: the map, every robot each tick, its check
#   check stc --mcap       a tour with a repeat at position 3: exit 1, one ERROR log at step 3
#   explore --mcap         paper 001's pair: the map, both robots each tick, the explored map
#   buffon --mcap          paper 000's two visits: the arena, each visit's poses and trail
# Fails when the node packages are not installed (run `scripts/bootstrap.sh --node-packages` or
# `npm ci`); skipped only when node itself is absent.
# Inputs: -DANTKIT=... -DNODE=... (empty when not found) -DSRC=<checkout> -DOUT=<scratch dir>
if(NOT NODE)
  message("interop: SKIPPED: node (Node.js 20) is not installed")
  return()
endif()
if(NOT EXISTS ${SRC}/node_modules/@mcap/core/package.json
   OR NOT EXISTS ${SRC}/node_modules/@foxglove/schemas/package.json)
  message(FATAL_ERROR "interop: ${SRC}/node_modules is missing or incomplete: run "
                      "`scripts/bootstrap.sh --node-packages` "
                      "(or `npm ci` in the checkout)")
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(log ${SRC}/data/logs/khepera_buffon_circle8.jsonl)
set(edited ${SRC}/data/logs/khepera_buffon_circle8_cmd_edited.jsonl)

function(run expect_rc)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "interop: exit ${rc}, expected ${expect_rc}: ${ARGN}\n${out}${err}")
  endif()
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

set(check ${NODE} ${CMAKE_CURRENT_LIST_DIR}/check_mcap.mjs)
# 120 steps: a pose, a step and its bytes each; the trail every second step (at most 100 over a
# run); the header and the stop on /log; the header's arena circle:d=8 once.
run(0 ${ANTKIT} export mcap ${log} --out ${OUT}/export.mcap)
run(0 ${ANTKIT} export mcap ${log} --out ${OUT}/export2.mcap)
run(0 ${CMAKE_COMMAND} -E compare_files ${OUT}/export.mcap ${OUT}/export2.mcap)
run(0 ${check} ${OUT}/export.mcap /pose=120 /trail=60 /antkit/step=120 /antkit/io=120 /log=2
    /arena=1)
# 5000 steps (five chunks of 1024 steps and a part): formatted on one thread and on three, the
# same bytes, every chunk read by the official reader; the trail every 50th step.
run(0 ${NODE} ${CMAKE_CURRENT_LIST_DIR}/long_log.mjs ${log} ${OUT}/long.jsonl 5000)
run(0 ${ANTKIT} export mcap ${OUT}/long.jsonl --out ${OUT}/long1.mcap --threads 1)
run(0 ${ANTKIT} export mcap ${OUT}/long.jsonl --out ${OUT}/long3.mcap --threads 3)
run(0 ${CMAKE_COMMAND} -E compare_files ${OUT}/long1.mcap ${OUT}/long3.mcap)
run(0 ${check} ${OUT}/long3.mcap /pose=5000 /trail=100 /antkit/step=5000 /antkit/io=5000 /log=2
    /arena=1)
run(0 ${ANTKIT} replay ${log} --mcap ${OUT}/replay.mcap)
run(0 ${check} ${OUT}/replay.mcap /recorded/pose=120 /recorded/step=120 /recorded/io=120
    /replayed/step=120 /log=3 /arena=1)
run(1 ${ANTKIT} replay ${edited} --mcap ${OUT}/diverged.mcap)
run(0 ${check} ${OUT}/diverged.mcap /recorded/step=120 /replayed/step=41 /log=3 error@40)
# A malformed log: exit 2, FILE:LINE:COL on stderr, nothing written.
file(WRITE ${OUT}/bad.jsonl "{\"schema\":1,\"robot\":\"khepera\"}\n")
run(2 ${ANTKIT} export mcap ${OUT}/bad.jsonl --out ${OUT}/bad.mcap)
if(NOT last_err MATCHES "bad.jsonl:1:[0-9]+:")
  message(FATAL_ERROR "interop: no located error for a malformed log: ${last_err}")
endif()
if(EXISTS ${OUT}/bad.mcap)
  message(FATAL_ERROR "interop: a malformed log left ${OUT}/bad.mcap")
endif()
# A ROS 2 bag back out (antkit bag export): bags written by the independent writers
# (tests/support/write_bags.mjs), two robots meeting head on over a 4 x 2 free map (plain PGM):
# exit 1 (the check fails; the file is whole), the map and the visits as foxglove.Grid.
run(0 ${NODE} ${SRC}/tests/support/write_bags.mjs ${OUT}/bags)
file(WRITE ${OUT}/bags/free.yaml "image: free.pgm\nresolution: 0.5\norigin: [-1.0, -2.0, 0.0]\n"
                                 "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
file(WRITE ${OUT}/bags/free.pgm "P2\n4 2\n255\n254 254 254 254\n254 254 254 254\n")
run(1 ${ANTKIT} bag export ${OUT}/bags/cover_collide.mcap --map ${OUT}/bags/free.yaml
    --topic /r0/pose --topic /r1/pose --check cover --sensor 1 --out ${OUT}/bag_cover.mcap)
run(0 ${check} ${OUT}/bag_cover.mcap /map=1 /visits=1 /log=2 /robot0/pose=2 /robot0/trail=2
    /robot1/pose=2 /robot1/trail=2)
run(0 ${ANTKIT} bag export ${OUT}/bags/tour.mcap --map ${OUT}/bags/free.yaml --topic /pose
    --check stc --out ${OUT}/bag_tour.mcap)
run(0 ${check} ${OUT}/bag_tour.mcap /map=1 /visits=1 /log=2 /robot0/pose=4)
# An STC tour (antkit stc --mcap): the map and the tree at time 0, a pose a step (32 x 32 free:
# 1024 sub-cells, ending beside the start), the trail every 11th step, the run and the verdict.
run(0 ${ANTKIT} stc --map ${SRC}/data/maps/movingai/empty-32-32.map --variant ant
    --mcap ${OUT}/stc.mcap)
run(0 ${check} ${OUT}/stc.mcap /map=1 /tree=1 /pose=1024 /trail=94 /log=2)
# A coverage run (antkit cover --mcap): three robots, 40 ticks at most; the map, each robot's pose
# every tick, and the run's own check on /log (the ticks it ran are the trace's).
run(0 ${ANTKIT} cover --map ${SRC}/data/maps/movingai/empty-32-32.map --algo pm --robots 3
    --limit 40 --mcap ${OUT}/cover.mcap)
run(0 ${check} ${OUT}/cover.mcap /map=1 /log=2)
# A checked tour (antkit check stc --mcap): a 4 x 2 free map, a tour back on (1, 0) at position 3:
# exit 1 (the rule is broken; the file is whole), a pose a position, the ERROR at position 3.
file(WRITE ${OUT}/free.txt "....\n....\n")
file(WRITE ${OUT}/repeat.json "[[0,0],[1,0],[2,0],[1,0],[2,0],[3,0],[3,1],[2,1],[1,1],[0,1]]")
run(1 ${ANTKIT} check stc --map ${OUT}/free.txt --path ${OUT}/repeat.json
    --mcap ${OUT}/check_stc.mcap)
run(0 ${check} ${OUT}/check_stc.mcap /map=1 /pose=10 /trail=10 /log=2 error@3)
# A two-robot LOS exploration (antkit explore --mcap): 367 steps in the 32 x 32 rooms, so 368
# ticks; the map at 0, the explored map at the end, both robots each tick.
run(0 ${ANTKIT} explore --map ${SRC}/data/maps/movingai/room-32-32-4.map --algo fast-wall-follow
    --mcap ${OUT}/explore.mcap)
run(0 ${check} ${OUT}/explore.mcap /map=1 /explored=1 /robotA/pose=368 /robotB/pose=368
    /robotA/trail=93 /robotB/trail=93)
# A Buffon run (antkit buffon --mcap): trial 0's two visits of 2000 steps, one after the other:
# the arena at 0, 2001 poses each, the trail at positions 0, 21, ..., 1995 and the last.
run(0 ${ANTKIT} buffon --arena circle:d=20 --steps 2000 --mcap ${OUT}/buffon.mcap)
run(0 ${check} ${OUT}/buffon.mcap /arena=1 /visit1/pose=2001 /visit2/pose=2001 /visit1/trail=97
    /visit2/trail=97)
