# cli.shell_budget: every file of cli/ but main.cpp stays within the shell's budget of lines (a
# command parses its options, calls one library function and prints: CONTRIBUTING.md). A file
# over it is named with its count, and the test fails.
#
#   cmake -DDIR=<cli folder> -DBUDGET=250 [-DEXEMPT=main.cpp] -P shell_budget.cmake
if(NOT DEFINED DIR OR NOT DEFINED BUDGET)
  message(FATAL_ERROR "usage: cmake -DDIR=cli -DBUDGET=N [-DEXEMPT=main.cpp] -P shell_budget.cmake")
endif()
file(GLOB files ${DIR}/*.cpp ${DIR}/*.hpp)
list(SORT files)
set(over "")
set(checked 0)
foreach(f IN LISTS files)
  get_filename_component(name ${f} NAME)
  if(DEFINED EXEMPT AND name STREQUAL EXEMPT)
    continue()
  endif()
  math(EXPR checked "${checked} + 1")
  file(READ ${f} content)
  string(REGEX MATCHALL "\n" newlines "${content}") # lines as wc -l counts them
  list(LENGTH newlines count)
  if(count GREATER BUDGET)
    string(APPEND over "  cli/${name}: ${count} lines, over the budget of ${BUDGET}\n")
  endif()
endforeach()
if(checked EQUAL 0)
  message(FATAL_ERROR "no .cpp or .hpp file in ${DIR}")
endif()
if(over)
  message(FATAL_ERROR "cli/ files over the shell's budget (move what is not parsing options, "
                      "calling one library function and printing into its library):\n${over}")
endif()
message(STATUS "${checked} cli/ files within ${BUDGET} lines")
