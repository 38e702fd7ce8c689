# ctest windows_probe: the Windows compile check (scripts/check_windows.py) catches a POSIX header
# outside its platform file.
#   cmake -DBUILD=<build folder> -DSOURCE=<source folder> -P check_windows_probe.cmake
# Two throw-away sources of core's engine floor, made in the build tree: one that includes a core
# header and <cmath> must compile for Windows; one that also includes <termios.h> (a header
# Windows does not have, which only the simulators' pseudo-terminal files may use) must not, and
# the compiler must say that termios.h is what it lacks.
cmake_minimum_required(VERSION 3.16)
if(NOT BUILD OR NOT SOURCE)
  message(FATAL_ERROR "usage: cmake -DBUILD=<build> -DSOURCE=<source> -P check_windows_probe.cmake")
endif()
find_program(MINGW x86_64-w64-mingw32-g++-posix)
if(NOT MINGW)
  message(FATAL_ERROR "x86_64-w64-mingw32-g++-posix is not installed (scripts/debian-packages.txt lists it: run scripts/setup.sh install)")
endif()
set(dir ${BUILD}/windows-probe)
file(MAKE_DIRECTORY ${dir})
file(WRITE ${dir}/portable.cpp "// Throw-away source of the windows_probe test: portable code.\n#include \"device/session_types.h\"\n#include <cmath>\nint portable_anchor = 0;\n")
file(WRITE ${dir}/posix_outside.cpp "// Throw-away source of the windows_probe test: a POSIX header outside its platform file.\n#include \"device/session_types.h\"\n#include <termios.h>\nint posix_anchor = 0;\n")

execute_process(COMMAND python3 ${SOURCE}/scripts/check_windows.py ${BUILD} --probe ${dir}/portable.cpp
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "portable code did not compile for Windows (the check itself is broken):\n${out}${err}")
endif()
message(STATUS "ok: portable code compiles for Windows")

execute_process(COMMAND python3 ${SOURCE}/scripts/check_windows.py ${BUILD} --probe ${dir}/posix_outside.cpp
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${err}" "termios.h: No such file or directory" found)
if(rc EQUAL 0)
  message(FATAL_ERROR "a file that includes <termios.h> outside its platform file compiled for Windows")
elseif(found EQUAL -1)
  message(FATAL_ERROR "the file with <termios.h> failed, but not for want of termios.h:\n${out}${err}")
endif()
message(STATUS "ok: a file that includes <termios.h> outside its platform file fails the Windows check")
