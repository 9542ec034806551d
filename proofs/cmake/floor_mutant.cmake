# ctest driver for one source mutant of the shipped STC floor (proof.teeth.floor_mutant.<name>):
# copies floor.hpp into the build tree with one slip a person could make (FIND replaced by
# REPLACE), compiles a checker (the Z3 proof proofs/z3/stc_floor.cpp or the tie
# proofs/tie/ant_stc_tie.cpp, one translation unit) with the mutated header first on the include
# path, runs it, and passes ONLY if the checker reports the slip (exits non-zero and prints
# CAUGHT, a regular expression: "FAILED" for the proof, "MISMATCH" for the tie).
#
#   cmake -DHEADER=.../floor.hpp -DWORK=dir -DFIND=text -DREPLACE=text -DCXX=c++ -DSOURCE=x.cpp
#         -DINCLUDES="a|b" -DLIBS="-lz3" -DARGS="..." -DCAUGHT=regex -P floor_mutant.cmake
#
# FIND must occur exactly once in floor.hpp: a pattern that is gone (floor.hpp was edited) fails
# the test loudly rather than compiling the original and calling it a mutant.
foreach(var HEADER WORK FIND CXX SOURCE CAUGHT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "floor_mutant.cmake: ${var} is not set")
  endif()
endforeach()

file(READ ${HEADER} text)
string(FIND "${text}" "${FIND}" first)
if(first EQUAL -1)
  message(FATAL_ERROR "mutant pattern not found in ${HEADER}: \"${FIND}\" (floor.hpp changed; "
                      "update the mutant in proofs/CMakeLists.txt)")
endif()
string(FIND "${text}" "${FIND}" last REVERSE)
if(NOT first EQUAL last)
  message(FATAL_ERROR "mutant pattern occurs more than once in ${HEADER}: \"${FIND}\"")
endif()
string(REPLACE "${FIND}" "${REPLACE}" mutated "${text}")
if(mutated STREQUAL text)
  message(FATAL_ERROR "the replacement leaves floor.hpp unchanged")
endif()

set(include_dir ${WORK}/include)
file(MAKE_DIRECTORY ${include_dir}/antkit/stc)
file(WRITE ${include_dir}/antkit/stc/floor.hpp "${mutated}")
message(STATUS "mutant: \"${FIND}\" -> \"${REPLACE}\"")

set(flags -std=c++20 -O1 -I${include_dir})
string(REPLACE "|" ";" INCLUDES "${INCLUDES}")
foreach(dir IN LISTS INCLUDES)
  list(APPEND flags -I${dir})
endforeach()
separate_arguments(libs UNIX_COMMAND "${LIBS}")
execute_process(COMMAND ${CXX} ${flags} ${SOURCE} -o ${WORK}/checker ${libs}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the mutant does not compile (a test of nothing):\n${out}${err}")
endif()

separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${WORK}/checker ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
string(REGEX MATCH "[^\n]*(${CAUGHT})[^\n]*" line "${out}")
if(rc EQUAL 0)
  message(FATAL_ERROR "the mutant SURVIVED: the checker passes with the slip in floor.hpp")
elseif(NOT line)
  message(FATAL_ERROR "the checker failed (exit ${rc}) without reporting the slip (no "
                      "\"${CAUGHT}\"):\n${out}${err}")
endif()
message(STATUS "caught (exit ${rc}): ${line}")
