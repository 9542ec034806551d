# Writes the registry's list (devices/src/registry.hpp) from the robots' own files: every line of
# DIR/*.cpp that starts with ANTKIT_SERIAL_ROBOT(place, function) or ANTKIT_DEVICE(place,
# function), ordered by place, into OUT (rewritten only when its text changes, so that nothing
# rebuilds for an edit elsewhere). Refuses a line it cannot read, two robots at one place and one
# function twice.
#   cmake -DDIR=devices/src -DOUT=registry_list.cpp -P registry_list.cmake
cmake_minimum_required(VERSION 3.25)
file(GLOB sources ${DIR}/*.cpp)
list(SORT sources)
set(entries "")
set(places "")
set(functions "")
foreach(source IN LISTS sources)
  file(STRINGS ${source} lines REGEX "^ANTKIT_(SERIAL_ROBOT|DEVICE)[ (]")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^ANTKIT_(SERIAL_ROBOT|DEVICE)\\(([0-9]+), *([A-Za-z_][A-Za-z_0-9]*)\\)")
      message(FATAL_ERROR "${source}: cannot read the registry line '${line}': expected "
                          "ANTKIT_SERIAL_ROBOT(place, function) or ANTKIT_DEVICE(place, function)")
    endif()
    set(kind ${CMAKE_MATCH_1})
    set(place ${CMAKE_MATCH_2})
    set(function ${CMAKE_MATCH_3})
    if(place IN_LIST places)
      message(FATAL_ERROR "${source}: ${function} takes place ${place}, which another robot has")
    endif()
    if(function IN_LIST functions)
      message(FATAL_ERROR "${source}: ${function} is registered twice")
    endif()
    list(APPEND places ${place})
    list(APPEND functions ${function})
    # Zero-padded, so that a text sort is the places' order.
    string(LENGTH "${place}" digits)
    if(digits GREATER 6)
      message(FATAL_ERROR "${source}: place ${place} has more than 6 digits")
    endif()
    math(EXPR pad "6 - ${digits}")
    string(REPEAT "0" ${pad} zeros)
    get_filename_component(file ${source} NAME)
    list(APPEND entries "${zeros}${place}|${kind}|${function}|${file}")
  endforeach()
endforeach()
list(SORT entries)

set(declarations "")
set(rows "")
foreach(entry IN LISTS entries)
  string(REPLACE "|" ";" fields "${entry}")
  list(GET fields 1 kind)
  list(GET fields 2 function)
  list(GET fields 3 file)
  list(GET fields 0 padded)
  math(EXPR place "${padded}")
  string(APPEND declarations "ANTKIT_${kind}(${place}, ${function}); // ${file}\n")
  if(kind STREQUAL "SERIAL_ROBOT")
    string(APPEND rows "      {&${function}, nullptr}, // ${place}\n")
  else()
    string(APPEND rows "      {nullptr, &${function}}, // ${place}\n")
  endif()
endforeach()

set(text "// The registry's list, written by the build from the robots' own files
// (devices/registry_list.cmake reads their ANTKIT_SERIAL_ROBOT and ANTKIT_DEVICE lines): do not
// edit; add a robot in its own file (devices/src/registry.hpp).
#include \"registry.hpp\"

namespace antkit::devices::detail {

${declarations}
std::span<const RegistryEntry> registry_entries() {
  static constexpr RegistryEntry kEntries[] = {
${rows}  };
  return kEntries;
}

} // namespace antkit::devices::detail
")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
