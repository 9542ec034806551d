# ctest driver for one Coq Interval file of proofs/interval: check it with coqc against the tables
# generated from the shipped C++ arrays, and require what its `Print Assumptions` list to be on the
# allow-list, name for name.
#   cmake -DCOQC=... -DSRC=File.v -DTABLES_DIR=dir -DLIB_DIR=dir -DOUT_DIR=dir
#         [-DALLOWED=allowed_assumptions.txt] -P run_coqc_interval.cmake
#
# Why an allow-list and not run_coqc.cmake's "no axioms at all": Coq Interval's theorems rest on the
# standard library's classical reals (ClassicalDedekindReals.sig_forall_dec and sig_not_dec,
# FunctionalExtensionality.functional_extensionality_dep, Classical_Prop.classic) and, because its
# interval arithmetic computes with Bignums over Coq's primitive 63-bit integers, on the kernel's
# primitive integer operations (PrimInt63.*) and their specifications (Uint63.*_spec). ALLOWED
# lists exactly those; anything else a theorem rests on (a new assumption, a section variable,
# an assumed positivity) fails the test. Without ALLOWED, any assumption fails it, as in
# run_coqc.cmake.
#
# The directories are seen under the empty logical prefix: TABLES_DIR holds AntkitAngleTables.vo
# (the build writes and compiles it), LIB_DIR IntervalAngle.vo and AngleBounds.vo (compiled by the
# build), OUT_DIR the .vo of the parts a file builds on (SineEntries.vo ..., written by the tests
# that check them, which ctest runs first: fixtures) and receives this file's.
#
# A tooth (proof.teeth.interval_*) runs the same check on a broken input and passes only when coqc
# refuses it with Interval's own failure, MUST_FAIL (a regular expression):
#   -DGEN=gen_tables -DBUMP_TABLE=kSineQ30 -DBUMP_INDEX=849   tables with one entry one unit off,
#                                                              written and compiled in OUT_DIR
#   -DPATCH_FROM=... -DPATCH_TO=...                            IntervalAngle.v with one text
#                                                              replaced (a tightened bound),
#                                                              compiled in OUT_DIR
#   -DFROM_INDEX=n                                             the file's theorem stated on a
#                                                              window from index n: eight
#                                                              entries or eight intervals
#                                                              (`each_... P n (List.firstn k
#                                                              (List.skipn n table))`), the same
#                                                              predicate and tactic
# A tooth's window starts at the planted fault (the bumped entry, the worst interval), and the
# window is first proved on the shipped input (the control), so the refusal is the fault's and
# comes in seconds instead of after the whole table, which proof.coq.interval.* checks anyway.
# That the whole-table theorem covers every index is the kernel's business (each_pair and
# each_entry are Fixpoints over the whole list).
cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
get_filename_component(name ${SRC} NAME_WE)
get_filename_component(src_dir ${SRC} DIRECTORY)
file(MAKE_DIRECTORY ${OUT_DIR})

# (coqc is called directly everywhere: the empty logical prefix "" would be lost in a list.)
set(tables ${TABLES_DIR})
set(lib ${LIB_DIR})
if(DEFINED BUMP_TABLE)
  set(tables ${OUT_DIR}/tables)
  file(REMOVE_RECURSE ${tables})
  file(MAKE_DIRECTORY ${tables})
  execute_process(COMMAND ${GEN} ${tables}/AntkitAngleTables.v --bump ${BUMP_TABLE} ${BUMP_INDEX}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the tooth's table could not be written (${rc})")
  endif()
  execute_process(COMMAND ${COQC} -q -no-glob -Q ${tables} "" -o ${tables}/AntkitAngleTables.vo
                          ${tables}/AntkitAngleTables.v ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "coqc failed on the tooth's table:\n${err}")
  endif()
endif()
if(DEFINED PATCH_FROM)
  set(lib ${OUT_DIR}/lib)
  file(REMOVE_RECURSE ${lib})
  file(MAKE_DIRECTORY ${lib})
  file(READ ${src_dir}/IntervalAngle.v text)
  string(FIND "${text}" "${PATCH_FROM}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the tooth's text '${PATCH_FROM}' is not in IntervalAngle.v: update the tooth")
  endif()
  string(REPLACE "${PATCH_FROM}" "${PATCH_TO}" text "${text}")
  file(WRITE ${lib}/IntervalAngle.v "${text}")
  execute_process(COMMAND ${COQC} -q -no-glob -Q ${tables} "" -Q ${lib} ""
                          -o ${lib}/IntervalAngle.vo ${lib}/IntervalAngle.v
                  ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "coqc failed on the tooth's IntervalAngle.v:\n${err}")
  endif()
endif()

if(DEFINED FROM_INDEX)
  file(READ ${SRC} text)
  # Eight entries, or the eight intervals between nine.
  string(REGEX REPLACE "(each_entry [a-z_]+) 0 (k[A-Za-z0-9]+)[.]"
                       "\\1 ${FROM_INDEX} (List.firstn 8 (List.skipn ${FROM_INDEX} \\2))."
                       windowed "${text}")
  string(REGEX REPLACE "(each_pair [a-z_]+) 0 (k[A-Za-z0-9]+)[.]"
                       "\\1 ${FROM_INDEX} (List.firstn 9 (List.skipn ${FROM_INDEX} \\2))."
                       windowed "${windowed}")
  if(windowed STREQUAL text)
    message(FATAL_ERROR "no `each_pair P 0 table.` or `each_entry P 0 table.` in ${SRC} to start "
                        "at ${FROM_INDEX}: update the tooth")
  endif()
  set(SRC ${OUT_DIR}/window/${name}.v)
  file(WRITE ${SRC} "${windowed}")
  if(DEFINED MUST_FAIL)
    # The control: on the shipped tables and bounds the window is proved, so the refusal below is
    # the planted fault's and nothing else's.
    execute_process(COMMAND ${COQC} -q -no-glob -Q ${TABLES_DIR} "" -Q ${LIB_DIR} ""
                            -o ${OUT_DIR}/window/${name}.vo ${SRC}
                    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "the tooth's window fails on the shipped input too:\n${out}\n${err}")
    endif()
  endif()
endif()

# A tooth's OUT_DIR holds its own tables/ and lib/, which must not be seen twice (as tables.* and
# lib.*); the parts a file builds on are only needed outside the teeth.
file(REMOVE ${OUT_DIR}/${name}.vo)
if(DEFINED MUST_FAIL)
  execute_process(COMMAND ${COQC} -q -no-glob -Q ${tables} "" -Q ${lib} ""
                          -o ${OUT_DIR}/${name}.vo ${SRC}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
else()
  execute_process(COMMAND ${COQC} -q -no-glob -Q ${tables} "" -Q ${lib} "" -Q ${OUT_DIR} ""
                          -o ${OUT_DIR}/${name}.vo ${SRC}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
endif()
file(WRITE ${OUT_DIR}/${name}.out "${out}")

if(DEFINED MUST_FAIL)
  if(rc EQUAL 0)
    message(FATAL_ERROR "the tooth did not bite: coqc accepted ${SRC} on the broken input")
  endif()
  if(NOT err MATCHES "${MUST_FAIL}")
    message(FATAL_ERROR "coqc refused ${SRC} on the broken input, but not with '${MUST_FAIL}':\n"
                        "${err}")
  endif()
  message(STATUS "${name}: refused on the broken input, as it must be:\n${err}")
  return()
endif()

if(NOT rc EQUAL 0)
  message(FATAL_ERROR "coqc failed on ${SRC} (${rc}):\n${out}\n${err}")
endif()
if(err MATCHES "[A-Za-z]")
  message(FATAL_ERROR "coqc printed warnings or errors on ${SRC}:\n${err}")
endif()

# `Print Assumptions` prints "Closed under the global context", or a header line ("Axioms:", or
# another kind of assumption) followed by one entry per assumption, each starting in column 0 with
# its name, its type indented on the lines after.
set(allowed "")
if(DEFINED ALLOWED)
  file(STRINGS ${ALLOWED} allowed_lines)
  foreach(line IN LISTS allowed_lines)
    string(STRIP "${line}" line)
    if(line AND NOT line MATCHES "^#")
      list(APPEND allowed ${line})
    endif()
  endforeach()
endif()
string(REGEX REPLACE "[][;]" " " text "${out}")
string(REPLACE "\n" ";" lines "${text}")
set(in_list FALSE)
set(printed 0)
set(bad "")
foreach(line IN LISTS lines)
  if(line STREQUAL "")
    continue()
  elseif(line MATCHES "^Closed under the global context")
    math(EXPR printed "${printed} + 1")
    set(in_list FALSE)
  elseif(line STREQUAL "Axioms:")
    math(EXPR printed "${printed} + 1")
    set(in_list TRUE)
  elseif(in_list AND line MATCHES "^[ \t]")
    # the type of the entry above
  elseif(in_list AND line MATCHES "^[^ \t:]+")
    string(REGEX MATCH "^[^ \t:]+" assumption "${line}")
    if(NOT assumption IN_LIST allowed)
      string(APPEND bad "  ${line}\n")
    endif()
  else()
    # any other output: another kind of assumption (section variables, type-in-type, ...)
    set(in_list FALSE)
    string(APPEND bad "  ${line}\n")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "a theorem of ${SRC} rests on assumptions not allowed for Coq Interval "
                      "(${ALLOWED}):\n${bad}")
endif()
if(DEFINED ALLOWED AND printed EQUAL 0)
  message(FATAL_ERROR "${SRC} prints no assumptions: each checked theorem needs its "
                      "`Print Assumptions`")
endif()
message(STATUS "${name}: checked by coqc; ${printed} theorem(s) printed, on allowed assumptions only")
