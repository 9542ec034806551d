# ctest driver for a Z3 proof whose checks cvc5 re-solves (proof.z3.<name> for the names in
# ANTKIT_CVC5_RECHECK): empties DIR, runs the proof with ANTKIT_SMT2_DIR=DIR (prove.hpp writes every
# check that counts there as SMT-LIB 2), passes its output through and fails as it fails. Only when
# the proof passes does it write DIR/passed, which proof.cvc5.<name> (run_cvc5.cmake, this test's
# fixture) requires: the files cvc5 reads are then exactly those of a passing run of this build's
# proof, and the proof is run once, not once for each solver.
#   cmake -DPROOF=exe [-DARGS=...] -DDIR=dir -P run_z3_dump.cmake
foreach(var PROOF DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_z3_dump.cmake: ${var} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${CMAKE_COMMAND} -E env ANTKIT_SMT2_DIR=${DIR} ${PROOF} ${args}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the proof failed (exit ${rc})")
endif()
file(WRITE ${DIR}/passed "")
