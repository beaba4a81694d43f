# Writes build/generated/holebench/version.h at every build, from `git describe`,
# so that each record names the code version it was produced by.
set(HOLEBENCH_GENERATED_DIR ${PROJECT_BINARY_DIR}/generated)
add_custom_target(holebench_version_header
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
          -DOUTPUT=${HOLEBENCH_GENERATED_DIR}/holebench/version.h
          -DPROJECT_VERSION=${PROJECT_VERSION} -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
          -P ${PROJECT_SOURCE_DIR}/cmake/WriteVersionHeader.cmake
  BYPRODUCTS ${HOLEBENCH_GENERATED_DIR}/holebench/version.h
  COMMENT "holebench version header")
