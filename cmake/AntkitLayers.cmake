# The layers and what each may use: the one statement of the layer order, which the build holds.
# ANTKIT_LAYER_USES_<layer> below is the table; README.md's "layer | may use" table must say the
# same (ctest layers.docs, cmake/check_layer_docs.cmake). Notes the table cannot carry:
#   io writes output files whole or not at all (atomic_file.hpp), for every layer that writes one;
#   maps reads and writes the grid map files (MovingAI, ROS, ASCII) into kernel grids, without CGAL
#   (the determinism matrix's builds link it); geometry is the only layer that includes CGAL (and
#   Eigen besides experiments); c is the C API for firmware (the Cortex-M image builds its source);
#   mpi uses MPI alone, and only cli uses mpi (cli/ranks.hpp hands the layers below a Runner that
#   carries the ranks); commands is what the two shells (cli, the `antkit` command, and python, the
#   Python package) share: each result's JSON and the choices a command makes from its options.
#
# DESIGN.md draws experiments above devices and testing: some experiments drive a robot and audit
# what it did (paper 002's run the marker-floor robot's pilot and camera from devices/stc_floor, and
# audit STC tours with testing's stc_audit). Tools (tests/, bench/, fuzz/, determinism/, proofs/,
# mcu/, examples/) may use any layer.
#
# Held three ways: antkit_check_layer_links() below refuses, at configure time, a layer target's
# link line against this table; the ctest layers.includes (cmake/check_layers.cmake) reads every
# #include <antkit/...> of every layer's sources and fails on an arrow against it (its tooth,
# layers.includes.teeth, plants two); and the compiler: every layer has include roots of its own
# (the kernel's is kernel/include, holding antkit/kernel/ alone), so a layer's target cannot find
# the header of a layer it does not link (the fences layers.fence.*, tests/layers/CMakeLists.txt).
set(ANTKIT_LAYERS kernel io maps geometry algorithms c mpi devices testing experiments commands
                  python cli)
set(ANTKIT_LAYER_USES_kernel "")
set(ANTKIT_LAYER_USES_io kernel)
set(ANTKIT_LAYER_USES_maps kernel io)
set(ANTKIT_LAYER_USES_geometry kernel)
set(ANTKIT_LAYER_USES_algorithms kernel)
set(ANTKIT_LAYER_USES_c kernel algorithms)
set(ANTKIT_LAYER_USES_mpi "")
set(ANTKIT_LAYER_USES_devices kernel io maps algorithms)
set(ANTKIT_LAYER_USES_testing kernel io maps geometry algorithms)
set(ANTKIT_LAYER_USES_experiments kernel io maps geometry algorithms devices testing)
set(ANTKIT_LAYER_USES_commands kernel io maps geometry algorithms devices testing)
set(ANTKIT_LAYER_USES_python kernel io maps geometry algorithms devices testing commands)
set(ANTKIT_LAYER_USES_cli kernel io maps geometry algorithms mpi devices testing experiments commands)
# The source folders of each layer (a file belongs to the layer of the longest folder that holds it).
foreach(layer IN LISTS ANTKIT_LAYERS)
  set(ANTKIT_LAYER_DIRS_${layer} ${layer})
endforeach()
# The header folders (antkit/<name>/) each layer owns.
set(ANTKIT_LAYER_HEADERS_kernel kernel)
set(ANTKIT_LAYER_HEADERS_io io)
set(ANTKIT_LAYER_HEADERS_maps maps)
set(ANTKIT_LAYER_HEADERS_geometry geometry)
set(ANTKIT_LAYER_HEADERS_algorithms algorithms buffon frontier los stc uniform)
set(ANTKIT_LAYER_HEADERS_c c)
set(ANTKIT_LAYER_HEADERS_mpi mpi)
set(ANTKIT_LAYER_HEADERS_devices devices)
set(ANTKIT_LAYER_HEADERS_testing testing campaign)
set(ANTKIT_LAYER_HEADERS_experiments experiments)
set(ANTKIT_LAYER_HEADERS_commands commands)
set(ANTKIT_LAYER_HEADERS_python "")
set(ANTKIT_LAYER_HEADERS_cli "")
# The layer targets (for the link check).
set(ANTKIT_LAYER_TARGETS_kernel antkit_kernel)
set(ANTKIT_LAYER_TARGETS_io antkit_io)
set(ANTKIT_LAYER_TARGETS_maps antkit_maps)
set(ANTKIT_LAYER_TARGETS_geometry antkit_geometry)
set(ANTKIT_LAYER_TARGETS_algorithms antkit_algorithms)
set(ANTKIT_LAYER_TARGETS_c antkit_c)
set(ANTKIT_LAYER_TARGETS_mpi antkit_mpi)
set(ANTKIT_LAYER_TARGETS_devices antkit_devices antkit_stc_floor)
set(ANTKIT_LAYER_TARGETS_testing antkit_testing antkit_campaign)
set(ANTKIT_LAYER_TARGETS_experiments antkit_experiments)
set(ANTKIT_LAYER_TARGETS_commands antkit_commands)
set(ANTKIT_LAYER_TARGETS_python antkit_python)
set(ANTKIT_LAYER_TARGETS_cli antkit)

# The layer a target belongs to, or "" for a target outside the layers (third-party, options).
function(antkit_layer_of_target target out)
  foreach(layer IN LISTS ANTKIT_LAYERS)
    if(target IN_LIST ANTKIT_LAYER_TARGETS_${layer})
      set(${out} ${layer} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(${out} "" PARENT_SCOPE)
endfunction()

# Refuses (FATAL_ERROR) a layer target that links another layer's target against the table.
function(antkit_check_layer_links)
  foreach(layer IN LISTS ANTKIT_LAYERS)
    foreach(target IN LISTS ANTKIT_LAYER_TARGETS_${layer})
      if(NOT TARGET ${target})
        continue()
      endif()
      get_target_property(type ${target} TYPE)
      if(type STREQUAL "INTERFACE_LIBRARY")
        get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
      else()
        get_target_property(links ${target} LINK_LIBRARIES)
      endif()
      foreach(link IN LISTS links)
        string(REGEX REPLACE "^\\$<BUILD_INTERFACE:(.*)>$" "\\1" link "${link}")
        string(REGEX REPLACE "^antkit::" "antkit_" link "${link}")
        antkit_layer_of_target("${link}" used)
        if(used AND NOT used STREQUAL layer AND NOT used IN_LIST ANTKIT_LAYER_USES_${layer})
          message(FATAL_ERROR "layers: ${target} (layer ${layer}) links ${link} (layer ${used}); "
                              "${layer} may use: ${ANTKIT_LAYER_USES_${layer}} "
                              "(cmake/AntkitLayers.cmake)")
        endif()
      endforeach()
    endforeach()
  endforeach()
endfunction()
