# ctest driver: re-solves one Z3 proof's checks with cvc5, a second, independent SMT solver (issue
# 41), so that a bug in one solver is not a single point of failure. Runs the proof with
# ANTKIT_SMT2_DIR set (prove.hpp then writes every check that counts as an SMT-LIB 2 file: the
# context and the negated claim), requires the proof itself to pass, then requires cvc5 to answer
# `unsat` on every file. `sat` (the solvers disagree), an error or any other answer fails the test
# and names the claim. A check cvc5 does not decide within TLIMIT_MS fails too, unless the claim is
# listed in UNSOLVED (proofs/cvc5_unsolved.txt: "proof: claim" lines, each with why), where the
# ones cvc5 leaves to Z3 alone are written down; a listed claim that cvc5 now decides is reported,
# so the list can shrink. A listed claim gets LISTED_TLIMIT_MS (2 s), not the full limit: the list
# already records that cvc5 does not decide it within 60 s, and spending that minute again on each
# listed claim was most of these tests' time (495 of 925 s); 2 s still notices one that became easy.
# Without PROOF it re-solves the files a passing run of proof.z3.<name> left in DIR
# (run_z3_dump.cmake, its fixture, so that the proof does not run twice).
# With CACHE (the proof cache's directory, proofs/z3/proof_cache.hpp), a file whose text cvc5 of
# this very version has answered `unsat` before is not solved again: the marker cvc5-<SHA-256 of
# the version and the file's text> in CACHE says it was. Only `unsat` is remembered; anything else
# is solved every time.
#   cmake [-DPROOF=exe [-DARGS=...]] -DNAME=name -DDIR=dir -DCVC5=cvc5 [-DTLIMIT_MS=n]
#         [-DLISTED_TLIMIT_MS=n] [-DUNSOLVED=file] [-DCACHE=dir] -P run_cvc5.cmake
cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
if(NOT DEFINED TLIMIT_MS)
  set(TLIMIT_MS 60000)
endif()
if(NOT DEFINED LISTED_TLIMIT_MS)
  set(LISTED_TLIMIT_MS 2000)
endif()
set(unsolved "")
if(DEFINED UNSOLVED AND EXISTS ${UNSOLVED})
  file(STRINGS ${UNSOLVED} lines REGEX "^${NAME}: ")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^${NAME}: ([^#]*[^ #]) *(#.*)?$" "\\1" claim "${line}")
    list(APPEND unsolved "${claim}")
  endforeach()
endif()
if(DEFINED PROOF)
  file(REMOVE_RECURSE ${DIR})
  file(MAKE_DIRECTORY ${DIR})
  separate_arguments(args UNIX_COMMAND "${ARGS}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ANTKIT_SMT2_DIR=${DIR} ${PROOF} ${args}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the Z3 proof itself failed (${rc}):\n${out}\n${err}")
  endif()
elseif(NOT EXISTS ${DIR}/passed)
  message(FATAL_ERROR "no passing run of the Z3 proof has written ${DIR} (proof.z3.${NAME}, "
                      "this test's fixture, writes it: run it first)")
endif()
file(GLOB files ${DIR}/*.smt2)
list(LENGTH files n)
if(n EQUAL 0)
  message(FATAL_ERROR "the proof wrote no SMT-LIB file to re-check")
endif()
set(failed 0)
set(left 0)
set(cached 0)
if(CACHE)
  execute_process(COMMAND ${CVC5} --version OUTPUT_VARIABLE cvc5_version RESULT_VARIABLE vrc)
  if(NOT vrc EQUAL 0 OR cvc5_version STREQUAL "")
    set(CACHE "") # no version to key on: solve everything
  else()
    file(MAKE_DIRECTORY ${CACHE})
  endif()
endif()
foreach(f IN LISTS files)
  if(CACHE)
    file(READ ${f} text)
    string(SHA256 key "cvc5 ${cvc5_version}\n${text}")
    set(marker ${CACHE}/cvc5-${key})
    if(EXISTS ${marker})
      math(EXPR cached "${cached} + 1")
      continue()
    endif()
  endif()
  # The claim's name, from the file's first line "; NAME" (file(STRINGS) keeps the ';' escaped).
  file(READ ${f} first LIMIT 4096)
  string(REGEX REPLACE "\n.*" "" first "${first}")
  string(REGEX REPLACE "^; " "" claim "${first}")
  if(claim IN_LIST unsolved)
    # A listed claim is stopped from outside (cvc5 1.0.3's own limit can abort inside CaDiCaL
    # instead of answering unknown when it falls mid-search): no answer means "still undecided".
    set(limit ${LISTED_TLIMIT_MS})
    math(EXPR seconds "${limit} / 1000")
    execute_process(COMMAND ${CVC5} --lang=smt2 ${f} TIMEOUT ${seconds}
                    OUTPUT_VARIABLE answer ERROR_VARIABLE answer_err RESULT_VARIABLE crc)
  else()
    set(limit ${TLIMIT_MS})
    execute_process(COMMAND ${CVC5} --lang=smt2 --tlimit-per=${limit} ${f}
                    OUTPUT_VARIABLE answer ERROR_VARIABLE answer_err RESULT_VARIABLE crc)
  endif()
  string(STRIP "${answer}" answer)
  if(claim IN_LIST unsolved AND NOT answer MATCHES "^(un)?sat$")
    set(answer "unknown") # stopped, or aborted: still undecided
  endif()
  if(answer STREQUAL "unsat")
    if(claim IN_LIST unsolved)
      message(STATUS "now re-proved, drop it from the list: ${NAME}: ${claim}")
    endif()
    if(CACHE)
      file(WRITE ${marker}.${NAME}.tmp "unsat\n") # one writer per name: proofs may share a text
      file(RENAME ${marker}.${NAME}.tmp ${marker})
    endif()
  elseif(answer STREQUAL "unknown" AND claim IN_LIST unsolved)
    math(EXPR left "${left} + 1")
    message(STATUS "left to Z3 (listed; undecided in ${limit} ms): ${claim}")
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
if(cached GREATER 0)
  message(STATUS "of them ${cached} from the proof cache (${CACHE}): the same text answered unsat "
                 "by this cvc5 in an earlier run")
endif()
