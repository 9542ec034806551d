# The include graph against the layer table (cmake/AntkitLayers.cmake): every #include <antkit/X/...>
# in a layer's sources must name a header folder of that layer or of a layer it may use.
#   cmake -DROOT=<source tree> -P cmake/check_layers.cmake
# Prints each arrow against the table as "FILE: #include <antkit/X/...>: layer A may not use layer
# B (A may use: ...)" and exits 1 when there is one; "layers: N includes in M files, all in order"
# otherwise. A layer's sources are its top-level folder (python/: the compiled module). Also
# refuses a kernel line naming float or double.
cmake_minimum_required(VERSION 3.25)
if(NOT ROOT)
  message(FATAL_ERROR "give -DROOT=<source tree>")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/AntkitLayers.cmake)

set(owner_of_header "")
foreach(layer IN LISTS ANTKIT_LAYERS)
  foreach(h IN LISTS ANTKIT_LAYER_HEADERS_${layer})
    set(owner_${h} ${layer})
  endforeach()
endforeach()

set(bad 0)
set(count 0)
set(files 0)
# Each file once, in the layer of its top-level folder.
set(done "")
foreach(layer IN LISTS ANTKIT_LAYERS)
  set(sources "")
  foreach(dir IN LISTS ANTKIT_LAYER_DIRS_${layer})
    file(GLOB_RECURSE found ${ROOT}/${dir}/*.hpp ${ROOT}/${dir}/*.cpp ${ROOT}/${dir}/*.h
                            ${ROOT}/${dir}/*.c)
    list(APPEND sources ${found})
  endforeach()
  foreach(f IN LISTS sources)
    if(f IN_LIST done)
      continue()
    endif()
    list(APPEND done ${f})
    math(EXPR files "${files} + 1")
    file(STRINGS ${f} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]antkit/")
    foreach(line IN LISTS includes)
      math(EXPR count "${count} + 1")
      string(REGEX MATCH "antkit/([A-Za-z0-9_]+)/" _ "${line}")
      set(folder ${CMAKE_MATCH_1})
      set(used "${owner_${folder}}")
      file(RELATIVE_PATH rel ${ROOT} ${f})
      string(STRIP "${line}" line)
      if(NOT used)
        message("${rel}: ${line}: antkit/${folder}/ belongs to no layer (cmake/AntkitLayers.cmake)")
        math(EXPR bad "${bad} + 1")
      elseif(NOT used STREQUAL layer AND NOT used IN_LIST ANTKIT_LAYER_USES_${layer})
        string(REPLACE ";" ", " may "${ANTKIT_LAYER_USES_${layer}}")
        if(NOT may)
          set(may "no other layer")
        endif()
        message("${rel}: ${line}: layer ${layer} may not use layer ${used} (${layer} may use: "
                "${may})")
        math(EXPR bad "${bad} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()

# The kernel is integers and fixed point only (DESIGN.md, determinism rule 1): the words float and
# double appear nowhere in it, comments included; conversions for reporting live above it.
set(words 0)
file(GLOB_RECURSE kernel_files ${ROOT}/kernel/*.hpp ${ROOT}/kernel/*.cpp)
foreach(f IN LISTS kernel_files)
  file(STRINGS ${f} lines REGEX "(^|[^A-Za-z_])(float|double)([^A-Za-z_]|$)")
  file(RELATIVE_PATH rel ${ROOT} ${f})
  foreach(line IN LISTS lines)
    string(STRIP "${line}" line)
    message("${rel}: \"${line}\": the kernel names floating point")
    math(EXPR words "${words} + 1")
  endforeach()
endforeach()

if(bad GREATER 0 OR words GREATER 0)
  message(FATAL_ERROR "layers: ${bad} include(s) against the layer order, of ${count} in ${files} "
                      "files; ${words} kernel line(s) naming floating point")
endif()
message("layers: ${count} includes in ${files} files, all in order; the kernel names no floating "
        "point")
