# ctest ui_folders: the include rules of ui/ (docs/ARCHITECTURE.md, "The window side"):
#   cmake -DUI=<source>/ui -P check_ui_folders.cmake
# - the shell (ui/workspace) names no family: it includes nothing of ui/families, whose plug-ins
#   app/gui/main.cpp registers and hands to the window;
# - a feature folder (any other but ui/families, the shell's plug-ins, and ui/common) includes
#   nothing of the shell;
# - ui/station and ui/results do not include each other (what both need is in ui/common or core).
# Every broken rule is printed as FILE: include; then it fails.
cmake_minimum_required(VERSION 3.16)
if(NOT UI)
  message(FATAL_ERROR "usage: cmake -DUI=<source>/ui -P check_ui_folders.cmake")
endif()

set(failures 0)
function(forbid folder pattern why)
  file(GLOB_RECURSE sources ${UI}/${folder}/*.h ${UI}/${folder}/*.cpp)
  foreach(source ${sources})
    file(STRINGS ${source} hits REGEX "^[ \t]*#[ \t]*include[ \t]*\"(ui/)?(${pattern})/")
    foreach(hit ${hits})
      file(RELATIVE_PATH name ${UI} ${source})
      message(SEND_ERROR "ui/${name}: ${hit}: ${why}")
      math(EXPR failures "${failures} + 1")
    endforeach()
  endforeach()
  set(failures ${failures} PARENT_SCOPE)
endfunction()

forbid(workspace "families" "the shell names no family (its plug-ins are handed to it)")
file(GLOB folders RELATIVE ${UI} ${UI}/*)
foreach(folder ${folders})
  if(IS_DIRECTORY ${UI}/${folder} AND NOT folder MATCHES "^(workspace|families|common)$")
    forbid(${folder} "workspace" "a feature folder includes nothing of the shell")
  endif()
endforeach()
forbid(station "results" "ui/station and ui/results do not include each other")
forbid(results "station" "ui/station and ui/results do not include each other")

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} include(s) break ui's folder rules (above)")
endif()
message(STATUS "ui's folder rules hold")
