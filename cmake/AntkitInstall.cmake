include(CMakePackageConfigHelpers)

install(TARGETS antkit_kernel antkit_io antkit_maps antkit_geometry antkit_algorithms antkit_c
                antkit_stc_floor antkit_devices antkit_testing antkit_experiments
        EXPORT antkitTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS antkit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(dir IN ITEMS kernel/include io/include maps/include geometry/include algorithms/include
                    c/include devices/include testing/include experiments/include)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
file(GLOB _antkit_family_includes LIST_DIRECTORIES true ${PROJECT_SOURCE_DIR}/algorithms/*/include)
foreach(dir IN LISTS _antkit_family_includes)
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

install(EXPORT antkitTargets NAMESPACE antkit:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/antkit)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/antkitConfig.cmake.in
  ${PROJECT_BINARY_DIR}/antkitConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/antkit)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/antkitConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/antkitConfig.cmake ${PROJECT_BINARY_DIR}/antkitConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/antkit)
