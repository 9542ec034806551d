# ctest mpi.campaign.identical and mpi.reproduce.identical (issues 15 and 18): `mpirun
# --oversubscribe -n K antkit ARGS` for K = 1, 2 and 4 writes byte for byte the files of a run of
# `antkit ARGS` without MPI: the work is split across the ranks by the keyed streams and gathered to
# rank 0, which alone writes.
#   cmake -DANTKIT=... -DMPIEXEC=... -DWORK=... -DARGS="a|b|..." -DSTATUS=0|1 -DMIN_FILES=N
#         -P identical.cmake
# With -DMAKE_OUT=1 the output directories are made first (for a command whose --out must exist).
# STATUS is the exit status every run must have (1: the campaign plants a failing rule, so that
# shrunk failures are found on every rank and gathered); ARGS must include --format json, whose
# "ranks" rank 0 reports.
string(REPLACE "|" ";" ARGS "${ARGS}") # '|' separates the arguments (a ';' would not survive ctest)
file(REMOVE_RECURSE ${WORK})

function(listing dir out)
  file(GLOB_RECURSE files RELATIVE ${dir} ${dir}/*)
  list(SORT files)
  set(${out} ${files} PARENT_SCOPE)
endfunction()

function(expect_status status what err)
  if(STATUS EQUAL 0 AND NOT status EQUAL 0)
    message(FATAL_ERROR "${what} exited ${status}, not 0: ${err}")
  elseif(NOT STATUS EQUAL 0 AND status EQUAL 0)
    message(FATAL_ERROR "${what} exited 0, not ${STATUS}: ${err}")
  endif()
endfunction()

if(MAKE_OUT)
  file(MAKE_DIRECTORY ${WORK}/plain ${WORK}/ranks1 ${WORK}/ranks2 ${WORK}/ranks4)
endif()
execute_process(COMMAND ${ANTKIT} ${ARGS} --out ${WORK}/plain RESULT_VARIABLE status
                OUTPUT_QUIET ERROR_VARIABLE err)
expect_status("${status}" "the run without MPI" "${err}")
listing(${WORK}/plain reference)
list(LENGTH reference count)
if(count LESS MIN_FILES)
  message(FATAL_ERROR "the run without MPI wrote ${count} files: ${reference}")
endif()
foreach(k 1 2 4)
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe -n ${k} ${ANTKIT} ${ARGS}
                          --out ${WORK}/ranks${k}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_status("${status}" "mpirun -n ${k}" "${err}")
  string(FIND "${out}" "\"ranks\": ${k}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "mpirun -n ${k}: rank 0 did not report ${k} ranks: ${out} ${err}")
  endif()
  listing(${WORK}/ranks${k} files)
  if(NOT files STREQUAL reference)
    message(FATAL_ERROR "mpirun -n ${k} wrote ${files}, the run without MPI ${reference}")
  endif()
  foreach(f IN LISTS reference)
    file(SHA256 ${WORK}/plain/${f} a)
    file(SHA256 ${WORK}/ranks${k}/${f} b)
    if(NOT a STREQUAL b)
      message(FATAL_ERROR "mpirun -n ${k}: ${f} differs from the run without MPI")
    endif()
  endforeach()
  message(STATUS "mpirun -n ${k}: ${count} files, byte-identical to the run without MPI")
endforeach()
