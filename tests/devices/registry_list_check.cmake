# devices.registry_list (ctest): the build's reading of the robots' registration lines
# (devices/registry_list.cmake) on made-up sources in a scratch directory: the list it writes is in
# the places' order whatever the files' order, a file it cannot read, two robots at one place and
# one function twice are refused naming the file, and an unchanged list is not rewritten.
#   cmake -DSCRIPT=devices/registry_list.cmake -DWORK=dir -P registry_list_check.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Runs the script over DIR's files; sets rc and err in the caller.
function(run dir)
  execute_process(COMMAND ${CMAKE_COMMAND} -DDIR=${dir} -DOUT=${dir}/out/registry_list.cpp -P
                          ${SCRIPT}
                  RESULT_VARIABLE r ERROR_VARIABLE e OUTPUT_QUIET)
  set(rc ${r} PARENT_SCOPE)
  set(err "${e}" PARENT_SCOPE)
endfunction()
function(expect_refused dir what)
  run(${dir})
  if(rc EQUAL 0)
    message(FATAL_ERROR "${dir}: accepted; expected a refusal matching '${what}'")
  endif()
  string(REGEX REPLACE "[ \t\r\n]+" " " flat "${err}") # CMake folds its messages' lines
  if(NOT flat MATCHES "${what}")
    message(FATAL_ERROR "${dir}: refused, but not with '${what}':\n${err}")
  endif()
  if(EXISTS ${dir}/out/registry_list.cpp)
    message(FATAL_ERROR "${dir}: a refused list was written")
  endif()
endfunction()

# Accepted: places out of the files' order, a serial robot and a device, a line that only mentions
# the macros (not at a line's start) ignored.
set(ok ${WORK}/ok)
file(WRITE ${ok}/a_robot_zeta.cpp "ANTKIT_SERIAL_ROBOT(30, zeta_description) {\n  return kZeta;\n}\n")
file(WRITE ${ok}/b_device_alpha.cpp "// ANTKIT_DEVICE(1, not_registered)\nANTKIT_DEVICE(5, alpha_device) {\n}\n")
file(WRITE ${ok}/c_robot_mid.cpp "ANTKIT_SERIAL_ROBOT(12,mid_description) {\n}\n")
run(${ok})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "a good tree refused:\n${err}")
endif()
file(READ ${ok}/out/registry_list.cpp list)
string(FIND "${list}" "{nullptr, &alpha_device}, // 5" at_alpha)
string(FIND "${list}" "{&mid_description, nullptr}, // 12" at_mid)
string(FIND "${list}" "{&zeta_description, nullptr}, // 30" at_zeta)
if(at_alpha LESS 0 OR at_mid LESS 0 OR at_zeta LESS 0)
  message(FATAL_ERROR "the list lacks a robot:\n${list}")
endif()
if(NOT (at_alpha LESS at_mid AND at_mid LESS at_zeta))
  message(FATAL_ERROR "the list is not in the places' order:\n${list}")
endif()
if(list MATCHES "not_registered")
  message(FATAL_ERROR "a commented-out line was registered:\n${list}")
endif()
# Unchanged: not rewritten (its time stays), so nothing rebuilds.
file(TIMESTAMP ${ok}/out/registry_list.cpp before "%s")
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
run(${ok})
file(TIMESTAMP ${ok}/out/registry_list.cpp after "%s")
if(NOT before STREQUAL after)
  message(FATAL_ERROR "an unchanged list was rewritten")
endif()

set(bad ${WORK}/unreadable)
file(WRITE ${bad}/robot_x.cpp "ANTKIT_SERIAL_ROBOT(ten, x_description) {\n}\n")
expect_refused(${bad} "robot_x\\.cpp: cannot read the registry line")
set(bad ${WORK}/one_place)
file(WRITE ${bad}/robot_x.cpp "ANTKIT_SERIAL_ROBOT(10, x_description) {\n}\n")
file(WRITE ${bad}/device_y.cpp "ANTKIT_DEVICE(10, y_device) {\n}\n")
expect_refused(${bad} "robot_x\\.cpp: x_description takes place 10, which another robot has")
set(bad ${WORK}/twice)
file(WRITE ${bad}/robot_x.cpp "ANTKIT_SERIAL_ROBOT(10, x_description) {\n}\n")
file(WRITE ${bad}/robot_y.cpp "ANTKIT_SERIAL_ROBOT(20, x_description) {\n}\n")
expect_refused(${bad} "robot_y\\.cpp: x_description is registered twice")
file(REMOVE_RECURSE ${WORK})
message(STATUS "registry_list.cmake: order, refusals and no rewrite checked")
