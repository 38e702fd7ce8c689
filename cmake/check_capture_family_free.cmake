# ctest capture_family_free: core/capture holds no family code (issue 54, point 1). A capture is
# decoded by the decoder of the family its header names (core/decode), so capture/ includes no
# family's protocol folder and no family's decoder, only decode/stream_decoder.h:
#   cmake -DCORE=<source>/core -P check_capture_family_free.cmake
# Every broken rule is printed as FILE: include; then it fails.
cmake_minimum_required(VERSION 3.16)
if(NOT CORE)
  message(FATAL_ERROR "usage: cmake -DCORE=<source>/core -P check_capture_family_free.cmake")
endif()
set(failures 0)
file(GLOB_RECURSE sources ${CORE}/capture/*.h ${CORE}/capture/*.cpp)
foreach(source ${sources})
  file(STRINGS ${source} hits REGEX "^[ \t]*#[ \t]*include[ \t]*\"(core/)?(protocol/(hipnuc|witlink|can|modbus|nmea)|decode/[a-z0-9_]+_(stream_decoder|vendor_csv))")
  foreach(hit ${hits})
    file(RELATIVE_PATH name ${CORE} ${source})
    message(SEND_ERROR "core/${name}: ${hit}: capture/ decodes through decode::decoderFor, never a family's own code")
    math(EXPR failures "${failures} + 1")
  endforeach()
endforeach()
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} include(s) of a family's code in core/capture")
endif()
message(STATUS "core/capture includes no family's code (${CMAKE_CURRENT_LIST_FILE})")
