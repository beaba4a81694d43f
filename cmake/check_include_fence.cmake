# The ground-truth fence: fails when a file under FENCED_DIR includes FORBIDDEN, directly or
# through another of the project's headers. "A method never sees the ground truth" (the
# brief): methods/ may include core/hole_labels.h (the labels' vocabulary) but never
# core/case.h (the complete model, the removed faces, the labels of the case).
#
# Usage: cmake -DROOT=<dir> -DFENCED_DIR=<dir> -DFORBIDDEN=<path> -P check_include_fence.cmake
#   ROOT        the folder quoted includes are resolved against (the project's source root)
#   FENCED_DIR  the folder whose .h, .hpp and .cpp files may not reach FORBIDDEN
#   FORBIDDEN   the header, as it is written in an include ("core/case.h")
# Includes with quotes or angle brackets are followed, resolved against the including file's
# folder, then ROOT; one that names no file there (a generated header, a library's) is not
# followed. On a violation, prints each offending file with the chain of includes that
# reaches FORBIDDEN, and exits with an error.
cmake_minimum_required(VERSION 3.22)
foreach(argument ROOT FENCED_DIR FORBIDDEN)
  if(NOT DEFINED ${argument})
    message(FATAL_ERROR "check_include_fence.cmake: -D${argument}=... is required")
  endif()
endforeach()

# The project headers `file` includes, with quotes or angle brackets, as absolute paths: each
# name resolved against the including file's folder first (a relative include), then ROOT.
# A name that resolves to no file (a library's header, a generated one) is not followed.
function(project_includes file result)
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  get_filename_component(folder "${file}" DIRECTORY)
  set(paths "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*$" "\\1" name
                         "${line}")
    foreach(base IN ITEMS "${folder}" "${ROOT}")
      get_filename_component(path "${base}/${name}" ABSOLUTE)
      if(EXISTS "${path}" AND NOT IS_DIRECTORY "${path}")
        list(APPEND paths "${path}")
        break()
      endif()
    endforeach()
  endforeach()
  set(${result} "${paths}" PARENT_SCOPE)
endfunction()

# A path as the messages show it: relative to ROOT.
function(shown_path path result)
  file(RELATIVE_PATH relative "${ROOT}" "${path}")
  set(${result} "${relative}" PARENT_SCOPE)
endfunction()

# Breadth-first over the includes of `start` (a path); sets `chain` to the includes from
# start to FORBIDDEN ("a -> b -> core/case.h"), or to "" where FORBIDDEN is not reached.
function(chain_to_forbidden start chain)
  get_filename_component(forbidden_path "${ROOT}/${FORBIDDEN}" ABSOLUTE)
  # key_<i>, via_<i>: the i-th path queued and the chain of includes to it (variables named
  # by index: paths hold '/'); the start itself is queued first, with an empty chain.
  set(seen "")
  set(key_0 "${start}")
  set(via_0 "")
  set(next_index 1)
  set(position 0)
  while(position LESS next_index)
    set(path "${key_${position}}")
    set(via "${via_${position}}")
    math(EXPR position "${position} + 1")
    if(path IN_LIST seen)
      continue()
    endif()
    list(APPEND seen "${path}")
    if(path STREQUAL forbidden_path)
      set(${chain} "${via}" PARENT_SCOPE)
      return()
    endif()
    project_includes("${path}" children)
    foreach(child IN LISTS children)
      if(NOT child IN_LIST seen)
        shown_path("${child}" shown)
        if(via STREQUAL "")
          set(via_${next_index} "${shown}")
        else()
          set(via_${next_index} "${via} -> ${shown}")
        endif()
        set(key_${next_index} "${child}")
        math(EXPR next_index "${next_index} + 1")
      endif()
    endforeach()
  endwhile()
  set(${chain} "" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE fenced_files "${FENCED_DIR}/*.h" "${FENCED_DIR}/*.hpp" "${FENCED_DIR}/*.cpp")
if(NOT fenced_files)
  message(FATAL_ERROR "check_include_fence.cmake: no source file under ${FENCED_DIR}")
endif()
list(SORT fenced_files)
set(violations 0)
foreach(file IN LISTS fenced_files)
  chain_to_forbidden("${file}" chain)
  if(chain)
    file(RELATIVE_PATH shown "${ROOT}" "${file}")
    message(NOTICE "${shown} reaches ${FORBIDDEN}: ${chain}")
    math(EXPR violations "${violations} + 1")
  endif()
endforeach()
list(LENGTH fenced_files checked)
if(violations GREATER 0)
  message(FATAL_ERROR
          "${violations} of ${checked} files under ${FENCED_DIR} include ${FORBIDDEN}")
endif()
message(STATUS "${checked} files under ${FENCED_DIR}: none includes ${FORBIDDEN}")
