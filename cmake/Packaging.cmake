# The Debian package: `cpack -G DEB --config BUILD/CPackConfig.cmake` (or `scripts/setup.sh package`)
# turns what `cmake --install` installs into imudesk_<version>_amd64.deb, installed below /usr.
#
# What the package holds, besides the two executables and the desktop entry, icon and AppStream
# metadata that app/gui installs:
#   - a manual page for each executable (resources/man, compressed here with gzip -n as Debian wants);
#   - /usr/share/doc/imudesk/copyright and changelog.gz (resources/debian; the version has no Debian
#     revision, so it is a native package and its changelog is changelog.gz, not changelog.Debian.gz);
#   - the udev rule as an example (/usr/share/doc/imudesk/examples): it widens access to every
#     USB-serial adapter of the listed chips, which the administrator decides, not the package.
# The translations are not separate files: the .qm files are compiled into imudesk as Qt resources
# (:/i18n, see app/gui/CMakeLists.txt), so the executable carries them.
#
# Dependencies: dpkg-shlibdeps reads the libraries the executables link (CPACK_DEBIAN_PACKAGE_SHLIBDEPS);
# what Qt loads at run time as plugins is named by hand below.
include(GNUInstallDirs)

set(IMUDESK_DEB_MAINTAINER "ImuDesk maintainers <maintainers@users.noreply.h-seed-2088a983.example>"
    CACHE STRING "Maintainer field of the Debian package")

# --- manual pages -------------------------------------------------------------------------------
find_program(IMUDESK_GZIP gzip REQUIRED)
set(IMUDESK_MAN_PAGES imudesk-cli)
if(IMUDESK_BUILD_GUI)
  list(APPEND IMUDESK_MAN_PAGES imudesk)
endif()
set(IMUDESK_MAN_OUTPUTS)
foreach(page IN LISTS IMUDESK_MAN_PAGES)
  set(in ${CMAKE_BINARY_DIR}/man/${page}.1)
  set(out ${CMAKE_BINARY_DIR}/man/${page}.1.gz)
  configure_file(${CMAKE_SOURCE_DIR}/resources/man/${page}.1 ${in} @ONLY) # the version in its header
  # -n: no name or time stamp in the gzip header, so the same page gives the same bytes.
  add_custom_command(OUTPUT ${out}
    COMMAND ${IMUDESK_GZIP} -9 -n -c ${in} > ${out}
    DEPENDS ${in} VERBATIM)
  list(APPEND IMUDESK_MAN_OUTPUTS ${out})
  install(FILES ${out} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endforeach()
add_custom_target(imudesk_man DEPENDS ${IMUDESK_MAN_OUTPUTS})
# Built with the executables, so that building just them (as scripts and the fresh-root check do)
# leaves a tree that `cmake --install` and cpack can install.
add_dependencies(imudesk-cli imudesk_man)
if(TARGET imudesk)
  add_dependencies(imudesk imudesk_man)
endif()

# --- documentation files Debian policy asks for -------------------------------------------------
set(IMUDESK_DOC_DIR ${CMAKE_INSTALL_DATADIR}/doc/imudesk)
file(STRINGS ${CMAKE_SOURCE_DIR}/resources/debian/changelog IMUDESK_CHANGELOG_HEAD LIMIT_COUNT 1)
if(NOT IMUDESK_CHANGELOG_HEAD MATCHES "^imudesk \\(${PROJECT_VERSION}\\) ")
  message(WARNING "resources/debian/changelog does not start with an entry for ${PROJECT_VERSION} "
                  "(its first line: ${IMUDESK_CHANGELOG_HEAD}); add one before packaging")
endif()
set(IMUDESK_CHANGELOG_GZ ${CMAKE_BINARY_DIR}/man/changelog.gz)
add_custom_command(OUTPUT ${IMUDESK_CHANGELOG_GZ}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
  COMMAND ${IMUDESK_GZIP} -9 -n -c ${CMAKE_SOURCE_DIR}/resources/debian/changelog > ${IMUDESK_CHANGELOG_GZ}
  DEPENDS ${CMAKE_SOURCE_DIR}/resources/debian/changelog VERBATIM)
add_custom_target(imudesk_changelog DEPENDS ${IMUDESK_CHANGELOG_GZ})
add_dependencies(imudesk_man imudesk_changelog)
install(FILES ${IMUDESK_CHANGELOG_GZ} ${CMAKE_SOURCE_DIR}/resources/debian/copyright DESTINATION ${IMUDESK_DOC_DIR})
install(FILES ${CMAKE_SOURCE_DIR}/resources/udev/60-imudesk-serial.rules DESTINATION ${IMUDESK_DOC_DIR}/examples)

# --- CPack --------------------------------------------------------------------------------------
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME imudesk)
set(CPACK_PACKAGE_VENDOR "ImuDesk")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${IMUDESK_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "bench tool for IMU and AHRS modules")
# The extended description (CPack puts the summary above it): lines under 80 characters, an empty
# line between paragraphs.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "ImuDesk finds and connects HiPNUC inertial modules and the Witlink HEC495
compass over serial, RS-485 Modbus RTU and CAN. It shows live charts, a 3D
attitude view and status flags, edits every documented setting, runs
calibration wizards, updates firmware, and records, replays and exports logs.

imudesk is the desktop application (English, Simplified and Traditional
Chinese); imudesk-cli does the same work from scripts. A simulator of each
device is built in, so everything can be tried without hardware.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # imudesk_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# Loaded by Qt at run time, so dpkg-shlibdeps cannot see them: the SVG icon engine draws the
# window icon (libqt6svg6), Qt SQL's SQLite driver keeps the station's results (libqt6sql6-sqlite) and its PostgreSQL driver
# sends them to the line's database (libqt6sql6-psql).
# The platform plugins (xcb, offscreen) come with libqt6gui6, which the
# executables link.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6, libqt6sql6-sqlite, libqt6sql6-psql")
# Chinese text needs a CJK font; Qt's own dialog strings are translated by qt6-translations-l10n;
# qt6-wayland runs the window natively on a Wayland desktop (XWayland otherwise).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fonts-noto-cjk, qt6-translations-l10n, qt6-wayland")
set(CPACK_SOURCE_GENERATOR "") # source packages are the git tree
include(CPack)
