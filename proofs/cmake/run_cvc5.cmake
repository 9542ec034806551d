# ctest driver: re-solves one Z3 proof's checks with cvc5, a second, independent SMT solver (issue
# 41), so that a bug in one solver is not a single point of failure. Runs the proof with
# ANTKIT_SMT2_DIR set (prove.hpp then writes every check that counts as an SMT-LIB 2 file: the
# context and the negated claim), requires the proof itself to pass, then requires cvc5 to answer
# `unsat` on every file. Any other answer (sat, unknown, a time-out, an error) fails the test and
# names the claim.
#   cmake -DPROOF=exe [-DARGS=...] -DDIR=dir -DCVC5=cvc5 [-DTLIMIT_MS=n] -P run_cvc5.cmake
if(NOT DEFINED TLIMIT_MS)
  set(TLIMIT_MS 120000)
endif()
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${CMAKE_COMMAND} -E env ANTKIT_SMT2_DIR=${DIR} ${PROOF} ${args}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the Z3 proof itself failed (${rc}):\n${out}\n${err}")
endif()
file(GLOB files ${DIR}/*.smt2)
list(LENGTH files n)
if(n EQUAL 0)
  message(FATAL_ERROR "the proof wrote no SMT-LIB file to re-check")
endif()
set(failed 0)
foreach(f IN LISTS files)
  file(STRINGS ${f} first LIMIT_COUNT 1)
  execute_process(COMMAND ${CVC5} --lang=smt2 --tlimit-per=${TLIMIT_MS} ${f}
                  OUTPUT_VARIABLE answer ERROR_VARIABLE answer_err RESULT_VARIABLE crc)
  string(STRIP "${answer}" answer)
  if(NOT answer STREQUAL "unsat")
    math(EXPR failed "${failed} + 1")
    message(STATUS "NOT RE-PROVED ${f} ${first}: cvc5 says '${answer}' ${answer_err}")
  endif()
endforeach()
if(failed GREATER 0)
  message(FATAL_ERROR "cvc5 did not re-prove ${failed} of ${n} checks")
endif()
message(STATUS "cvc5 re-proved all ${n} checks (each: unsat)")
