# The ground-truth fence: fails when a file under FENCED_DIR includes FORBIDDEN, directly or
# through another of the project's headers. "A method never sees the ground truth" (the
# brief): methods/ may include core/hole_labels.h (the labels' vocabulary) but never
# core/case.h (the complete model, the removed faces, the labels of the case).
#
# Usage: cmake -DROOT=<dir> -DFENCED_DIR=<dir> -DFORBIDDEN=<path> -P check_include_fence.cmake
#   ROOT        the folder quoted includes are resolved against (the project's source root)
#   FENCED_DIR  the folder whose .h, .hpp and .cpp files may not reach FORBIDDEN
#   FORBIDDEN   the header, as it is written in an include ("core/case.h")
# A quoted include that names no file under ROOT (a generated header, a library's) is not
# followed. On a violation, prints each offending file with the chain of includes that
# reaches FORBIDDEN, and exits with an error.
cmake_minimum_required(VERSION 3.22)
foreach(argument ROOT FENCED_DIR FORBIDDEN)
  if(NOT DEFINED ${argument})
    message(FATAL_ERROR "check_include_fence.cmake: -D${argument}=... is required")
  endif()
endforeach()

# The project headers `file` includes with quotes, as written ("core/mesh.h"), that exist
# under ROOT.
function(quoted_includes file result)
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  set(names "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*$" "\\1" name "${line}")
    if(EXISTS "${ROOT}/${name}")
      list(APPEND names "${name}")
    endif()
  endforeach()
  set(${result} "${names}" PARENT_SCOPE)
endfunction()

# Breadth-first over the includes of `start` (a path); sets `chain` to the includes from
# start to FORBIDDEN ("a -> b -> core/case.h"), or to "" where FORBIDDEN is not reached.
function(chain_to_forbidden start chain)
  quoted_includes("${start}" queue)
  set(seen "")
  foreach(name IN LISTS queue)
    set(via_${name} "${name}")
  endforeach()
  while(queue)
    list(POP_FRONT queue name)
    if(name IN_LIST seen)
      continue()
    endif()
    list(APPEND seen "${name}")
    if(name STREQUAL FORBIDDEN)
      set(${chain} "${via_${name}}" PARENT_SCOPE)
      return()
    endif()
    quoted_includes("${ROOT}/${name}" next)
    foreach(child IN LISTS next)
      if(NOT child IN_LIST seen AND NOT DEFINED via_${child})
        set(via_${child} "${via_${name}} -> ${child}")
        list(APPEND queue "${child}")
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
