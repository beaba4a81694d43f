# Compile settings shared by every holebench target, as an interface target
# (no global flag edits).
add_library(holebench_options INTERFACE)
add_library(holebench::options ALIAS holebench_options)
target_compile_features(holebench_options INTERFACE cxx_std_17)
target_compile_options(holebench_options INTERFACE -Wall -Wextra -Wno-unused-parameter)
if(HOLEBENCH_FUZZ)
  # Every holebench object instrumented for libFuzzer's coverage and checked by ASan and UBSan
  # (a UB report stops the fuzzer like a crash); the fuzz targets link -fsanitize=fuzzer.
  target_compile_options(holebench_options INTERFACE
                         -fsanitize=fuzzer-no-link,address,undefined
                         -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
  target_link_options(holebench_options INTERFACE -fsanitize=address,undefined)
endif()
if(HOLEBENCH_SANITIZE)
  target_compile_options(holebench_options INTERFACE -fsanitize=address,undefined
                                                     -fno-omit-frame-pointer)
  target_link_options(holebench_options INTERFACE -fsanitize=address,undefined)
endif()

# Debian's OpenImageIO target lists /usr/include/opencv4, which only exists with
# libopencv-core-dev. scripts/setup.sh installs it; drop the path if it is missing
# so that a machine without it still configures.
if(TARGET OpenImageIO::OpenImageIO)
  get_target_property(_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
  set(_oiio_kept "")
  foreach(_dir IN LISTS _oiio_includes)
    if(EXISTS "${_dir}" OR _dir MATCHES "^\\$<")
      list(APPEND _oiio_kept "${_dir}")
    endif()
  endforeach()
  set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES
                                                            "${_oiio_kept}")
endif()

# Helper: a module library with the project's options.
function(holebench_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  add_library(holebench::${name} ALIAS ${name})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC holebench::options ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
endfunction()
