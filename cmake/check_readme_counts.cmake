# ctest docs.counts: the counts README.md states are counted from their sources (issue 45), so a
# scenario or a map added without the README following fails here:
#   "the N scenarios of `determinism/scenarios.cpp`"  the golden lines of determinism/golden.txt
#                                                    (teeth/ lines aside)
#   "(N maps, `antkit_determinism"                   data/maps/movingai/*.map + data/maps/ros/*.yaml
#   cmake -DROOT=<checkout> [-DREADME=<file>] -P check_readme_counts.cmake
if(NOT DEFINED README)
  set(README ${ROOT}/README.md)
endif()
file(READ ${README} text)
string(REGEX REPLACE "[ \n]+" " " text "${text}")
set(errors "")
function(expect what pattern count)
  if(NOT text MATCHES "${pattern}")
    set(errors "${errors}  ${what}: README no longer says it (pattern '${pattern}')\n" PARENT_SCOPE)
  elseif(NOT CMAKE_MATCH_1 EQUAL count)
    set(errors "${errors}  ${what}: README says ${CMAKE_MATCH_1}, the source has ${count}\n" PARENT_SCOPE)
  endif()
endfunction()

file(STRINGS ${ROOT}/determinism/golden.txt golden REGEX "^[^# ]")
list(FILTER golden EXCLUDE REGEX "^teeth/")
list(LENGTH golden scenarios)
expect("golden scenarios" "the ([0-9]+) scenarios of `determinism/scenarios.cpp`" ${scenarios})
file(GLOB maps ${ROOT}/data/maps/movingai/*.map ${ROOT}/data/maps/ros/*.yaml)
list(LENGTH maps map_count)
expect("shared maps" "\\(([0-9]+) maps, `antkit_determinism" ${map_count})
if(errors)
  message(FATAL_ERROR "${README}'s counts disagree with their sources:\n${errors}")
endif()
message(STATUS "README counts: ${scenarios} golden scenarios, ${map_count} shared maps")
