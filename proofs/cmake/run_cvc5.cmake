# ctest driver: re-solves one Z3 proof's checks with cvc5, a second, independent SMT solver (issue
# 41), so that a bug in one solver is not a single point of failure. Runs the proof with
# ANTKIT_SMT2_DIR set (prove.hpp then writes every check that counts as an SMT-LIB 2 file: the
# context and the negated claim), requires the proof itself to pass, then requires cvc5 to answer
# `unsat` on every file. `sat` (the solvers disagree), an error or any other answer fails the test
# and names the claim. A check cvc5 does not decide within TLIMIT_MS fails too, unless the claim is
# listed in UNSOLVED (proofs/cvc5_unsolved.txt: "proof: claim" lines, each with why), where the
# ones cvc5 leaves to Z3 alone are written down; a listed claim that cvc5 now decides is reported,
# so the list can shrink.
#   cmake -DPROOF=exe -DNAME=name [-DARGS=...] -DDIR=dir -DCVC5=cvc5 [-DTLIMIT_MS=n]
#         [-DUNSOLVED=file] -P run_cvc5.cmake
cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
if(NOT DEFINED TLIMIT_MS)
  set(TLIMIT_MS 60000)
endif()
set(unsolved "")
if(DEFINED UNSOLVED AND EXISTS ${UNSOLVED})
  file(STRINGS ${UNSOLVED} lines REGEX "^${NAME}: ")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^${NAME}: ([^#]*[^ #]) *(#.*)?$" "\\1" claim "${line}")
    list(APPEND unsolved "${claim}")
  endforeach()
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
set(left 0)
foreach(f IN LISTS files)
  # The claim's name, from the file's first line "; NAME" (file(STRINGS) keeps the ';' escaped).
  file(READ ${f} first LIMIT 4096)
  string(REGEX REPLACE "\n.*" "" first "${first}")
  string(REGEX REPLACE "^; " "" claim "${first}")
  execute_process(COMMAND ${CVC5} --lang=smt2 --tlimit-per=${TLIMIT_MS} ${f}
                  OUTPUT_VARIABLE answer ERROR_VARIABLE answer_err RESULT_VARIABLE crc)
  string(STRIP "${answer}" answer)
  if(answer STREQUAL "unsat")
    if(claim IN_LIST unsolved)
      message(STATUS "now re-proved, drop it from the list: ${NAME}: ${claim}")
    endif()
  elseif(answer STREQUAL "unknown" AND claim IN_LIST unsolved)
    math(EXPR left "${left} + 1")
    message(STATUS "left to Z3 (listed): ${claim}")
  else()
    math(EXPR failed "${failed} + 1")
    message(STATUS "NOT RE-PROVED ${f}: ${claim}: cvc5 says '${answer}' ${answer_err}")
  endif()
endforeach()
if(failed GREATER 0)
  message(FATAL_ERROR "cvc5 did not re-prove ${failed} of ${n} checks")
endif()
math(EXPR done "${n} - ${left}")
message(STATUS "cvc5 re-proved ${done} of ${n} checks (unsat); ${left} listed as left to Z3")
