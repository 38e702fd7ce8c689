# ctest capture_family_free: core/capture and core/record hold no family code (issue 54, point 1).
# A capture is decoded by the decoder of the family its header names (decode::decoderFor), a
# family's own files are read by its importer (decode::fileImporterFor), so capture/ and record/
# include no family's protocol folder and no family's file of decode/ (decode/hipnuc_...,
# decode/witlink_..., decode/can_...), only decode's interfaces:
#   cmake -DCORE=<source>/core -P check_capture_family_free.cmake
# Every broken rule is printed as FILE: include; then it fails.
cmake_minimum_required(VERSION 3.16)
if(NOT CORE)
  message(FATAL_ERROR "usage: cmake -DCORE=<source>/core -P check_capture_family_free.cmake")
endif()
set(failures 0)
file(GLOB_RECURSE sources ${CORE}/capture/*.h ${CORE}/capture/*.cpp ${CORE}/record/*.h ${CORE}/record/*.cpp)
foreach(source ${sources})
  file(STRINGS ${source} hits REGEX "^[ \t]*#[ \t]*include[ \t]*\"(core/)?(protocol/(hipnuc|witlink|can|modbus|nmea)|decode/(hipnuc|witlink|can|modbus)_)")
  foreach(hit ${hits})
    file(RELATIVE_PATH name ${CORE} ${source})
    message(SEND_ERROR "core/${name}: ${hit}: captures are decoded through decode::decoderFor and files imported through decode::fileImporterFor, never a family's own code")
    math(EXPR failures "${failures} + 1")
  endforeach()
endforeach()
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} include(s) of a family's code in core/capture or core/record")
endif()
message(STATUS "core/capture and core/record include no family's code (${CMAKE_CURRENT_LIST_FILE})")
