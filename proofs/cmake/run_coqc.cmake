# ctest driver for one Coq file: check it with coqc (outputs into OUT_DIR, never the source tree),
# require every `Print Assumptions` in it to report no axioms, and, when GOLDEN exists, require the
# text its `Compute` commands print to equal GOLDEN (whitespace-normalised: Coq's line breaking is
# not part of the vector). The golden file is what C++ tests read, so a change in the model that
# moves a vector fails here until the golden file, and then the C++ test, follow.
#   cmake -DCOQC=... -DSRC=file.v -DOUT_DIR=dir -DGOLDEN=file.out -P run_coqc.cmake
#
# A file may build on another of proofs/coq: `Require Import StcTour.` (a name with no prefix, one
# per line). Such files are compiled first, dependencies before dependants, into a directory of
# this test's own (ctest runs the proofs in parallel, and StcTour's own test writes its .vo
# beside), which the file then sees under the empty logical prefix (-Q dir "").
cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
get_filename_component(name ${SRC} NAME_WE)
get_filename_component(src_dir ${SRC} DIRECTORY)
set(lib_dir ${OUT_DIR}/${name}.lib)
file(REMOVE_RECURSE ${lib_dir})
file(MAKE_DIRECTORY ${lib_dir})
set_property(GLOBAL PROPERTY antkit_coq_compiled "")
function(antkit_coq_compile_deps file)
  file(STRINGS ${file} requires REGEX "^Require (Import|Export) [A-Za-z0-9_]+\\.")
  foreach(line IN LISTS requires)
    string(REGEX REPLACE "^Require (Import|Export) ([A-Za-z0-9_]+)\\..*" "\\2" dep "${line}")
    get_property(compiled GLOBAL PROPERTY antkit_coq_compiled)
    if(NOT EXISTS ${src_dir}/${dep}.v OR dep IN_LIST compiled)
      continue()
    endif()
    antkit_coq_compile_deps(${src_dir}/${dep}.v)
    execute_process(COMMAND ${COQC} -q -no-glob -Q ${lib_dir} "" -o ${lib_dir}/${dep}.vo
                            ${src_dir}/${dep}.v
                    OUTPUT_QUIET ERROR_VARIABLE dep_err RESULT_VARIABLE dep_rc)
    if(NOT dep_rc EQUAL 0)
      message(FATAL_ERROR "coqc failed on ${dep}.v, which ${file} requires:\n${dep_err}")
    endif()
    set_property(GLOBAL APPEND PROPERTY antkit_coq_compiled ${dep})
  endforeach()
endfunction()
antkit_coq_compile_deps(${SRC})
execute_process(COMMAND ${COQC} -q -no-glob -Q ${lib_dir} "" -o ${OUT_DIR}/${name}.vo ${SRC}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
file(WRITE ${OUT_DIR}/${name}.out "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "coqc failed on ${SRC} (${rc}):\n${out}\n${err}")
endif()
if(err MATCHES "[A-Za-z]")
  message(FATAL_ERROR "coqc printed warnings or errors on ${SRC}:\n${err}")
endif()
# `Print Assumptions` prints "Axioms:" followed by the list when a theorem rests on any.
if(out MATCHES "Axioms:")
  message(FATAL_ERROR "a theorem of ${SRC} rests on axioms:\n${out}")
endif()
if(EXISTS ${GOLDEN})
  file(READ ${GOLDEN} want)
  string(REGEX REPLACE "[ \t\r\n]+" " " want_n "${want}")
  string(REGEX REPLACE "[ \t\r\n]+" " " got_n "${out}")
  string(STRIP "${want_n}" want_n)
  string(STRIP "${got_n}" got_n)
  if(NOT want_n STREQUAL got_n)
    message(FATAL_ERROR "the vectors ${SRC} computes differ from ${GOLDEN}\n"
                        "--- golden\n${want}\n--- coqc (full output in ${OUT_DIR}/${name}.out)\n${out}")
  endif()
endif()
message(STATUS "${name}: checked by coqc\n${out}")
