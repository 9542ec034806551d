# Compile flags every antkit target gets, through the INTERFACE target antkit_options (not exported:
# a consumer of the installed package keeps its own flags, but the kernel's headers still carry
# -ffp-contract=off through antkit::kernel, see kernel/CMakeLists.txt).
add_library(antkit_options INTERFACE)
target_compile_options(antkit_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wnon-virtual-dtor
  -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wimplicit-fallthrough
  -ffp-contract=off)
# GCC 12 at -O2 reports -Wrestrict inside std::string's operator+ (GCC bug 105329) and
# -Wnull-dereference inside std::streambuf: both are in libstdc++, not in antkit, so they are off.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(antkit_options INTERFACE -Wno-restrict)
endif()
if(ANTKIT_SANITIZE)
  list(JOIN ANTKIT_SANITIZE "," _antkit_san)
  target_compile_options(antkit_options INTERFACE -fsanitize=${_antkit_san} -fno-omit-frame-pointer
                                                  -fno-sanitize-recover=all)
  target_link_options(antkit_options INTERFACE -fsanitize=${_antkit_san})
endif()
if(ANTKIT_LIBFUZZER)
  # Coverage instrumentation for every antkit library, so that libFuzzer sees inside the parsers (the
  # fuzz targets themselves add -fsanitize=fuzzer, which also links the fuzzer's main).
  target_compile_options(antkit_options INTERFACE -fsanitize=fuzzer-no-link)
endif()
if(ANTKIT_CHECKED_ARITHMETIC)
  target_compile_definitions(antkit_options INTERFACE ANTKIT_CHECKED_ARITHMETIC=1)
endif()

# Warnings in third-party headers (CGAL, CLI11, Eigen) are not ours: include them as SYSTEM.
