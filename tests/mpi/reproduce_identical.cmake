# ctest mpi.reproduce.identical (issues 15 and 18): `mpirun --oversubscribe -n K antkit reproduce`
# for K = 1, 2 and 4 writes byte for byte the files of a run without MPI: the trials are split
# across the ranks and gathered to rank 0, which alone writes. Papers 001 and 002 (every map and
# the noise curve) and a shortened paper 000 would be too slow here; paper 000's and 004's trials
# go through the same run_units.
#   cmake -DANTKIT=... -DMPIEXEC=... -DWORK=... -DMAPS=... -P reproduce_identical.cmake
set(args reproduce --quick --only los,stc --maps ${MAPS} --format json)
file(REMOVE_RECURSE ${WORK})

function(listing dir out)
  file(GLOB_RECURSE files RELATIVE ${dir} ${dir}/*)
  list(SORT files)
  set(${out} ${files} PARENT_SCOPE)
endfunction()

execute_process(COMMAND ${ANTKIT} ${args} --out ${WORK}/plain RESULT_VARIABLE status
                OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the run without MPI exited ${status}: ${err}")
endif()
listing(${WORK}/plain reference)
list(LENGTH reference count)
if(count LESS 10)
  message(FATAL_ERROR "the run without MPI wrote ${count} files: ${reference}")
endif()
foreach(k 1 2 4)
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe -n ${k} ${ANTKIT} ${args}
                          --threads 1 --out ${WORK}/ranks${k}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "mpirun -n ${k} exited ${status}: ${err}")
  endif()
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
