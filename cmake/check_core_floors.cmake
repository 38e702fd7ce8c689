# ctest core_floors: core's floors are enforced by the build (core/CMakeLists.txt).
#   cmake -DBUILD=<build folder> -DCORE=<source>/core -DPROBES=name:expect:header,... -P check_core_floors.cmake
# Each probe is a target of tests/CMakeLists.txt that compiles one throw-away source linked to
# one floor's library. "compiles": it must build. "fails": it must not, and the compiler must
# say that the header it includes was not found (not any other error: that would prove nothing).
# Then no file of core may include with "../": such a path would reach a higher floor's folder
# past the include roots.
cmake_minimum_required(VERSION 3.16)
if(NOT BUILD OR NOT CORE OR NOT PROBES)
  message(FATAL_ERROR "usage: cmake -DBUILD=<build> -DCORE=<core> -DPROBES=... -P check_core_floors.cmake")
endif()

set(failures 0)
string(REPLACE "," ";" probes "${PROBES}")
foreach(probe ${probes})
  string(REPLACE ":" ";" parts "${probe}")
  list(GET parts 0 target)
  list(GET parts 1 expect)
  list(GET parts 2 header)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD} --target ${target}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(log "${out}${err}")
  if(expect STREQUAL "compiles")
    if(rc EQUAL 0)
      message(STATUS "ok: ${target} includes ${header} and compiles")
    else()
      message(SEND_ERROR "${target} includes ${header}, of its own floor or one below, and did not compile:\n${log}")
      math(EXPR failures "${failures} + 1")
    endif()
  else()
    string(FIND "${log}" "${header}: No such file or directory" found)
    if(rc EQUAL 0)
      message(SEND_ERROR "${target} includes ${header}, of a higher floor, and compiled: the floors are not enforced")
      math(EXPR failures "${failures} + 1")
    elseif(found EQUAL -1)
      message(SEND_ERROR "${target} did not compile, but not because ${header} is out of its reach:\n${log}")
      math(EXPR failures "${failures} + 1")
    else()
      message(STATUS "ok: ${target} includes ${header}, of a higher floor, and the compiler does not find it")
    endif()
  endif()
endforeach()

file(GLOB_RECURSE sources ${CORE}/*.h ${CORE}/*.cpp)
foreach(source ${sources})
  file(STRINGS ${source} climbing REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]*\\.\\./")
  if(climbing)
    file(RELATIVE_PATH name ${CORE} ${source})
    message(SEND_ERROR "core/${name}: ${climbing}: an include climbs out of its folder; name the folder from a floor's root")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} check(s) of core's floors failed (above)")
endif()
message(STATUS "core's floors hold: every probe as expected, no include climbs out of its folder")
