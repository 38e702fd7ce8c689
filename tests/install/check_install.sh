#!/usr/bin/env bash
# `cmake --install` into a scratch prefix must give a launchable desktop entry: the binaries,
# the .desktop file (valid, Exec naming the installed binary), the icon it names, the
# AppStream metadata and the manual pages. Usage: check_install.sh BUILD_DIR
set -euo pipefail
build="$1"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
id=io.github.imudesk.ImuDesk
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -x "$prefix/bin/imudesk" ] || fail "bin/imudesk not installed"
[ -x "$prefix/bin/imudesk-cli" ] || fail "bin/imudesk-cli not installed"
desktop="$prefix/share/applications/$id.desktop"
[ -f "$desktop" ] || fail "$desktop missing"
exec_bin="$(sed -n 's/^Exec=\([^ ]*\).*/\1/p' "$desktop")"
[ -x "$prefix/bin/$exec_bin" ] || fail "Exec=$exec_bin is not an installed binary"
icon="$(sed -n 's/^Icon=//p' "$desktop")"
[ -f "$prefix/share/icons/hicolor/scalable/apps/$icon.svg" ] || fail "icon $icon.svg missing"
grep -q '<svg' "$prefix/share/icons/hicolor/scalable/apps/$icon.svg" || fail "icon is not SVG"
[ -f "$prefix/share/metainfo/$id.metainfo.xml" ] || fail "metainfo missing"
# A manual page per executable, compressed (cmake/Packaging.cmake), and the Debian copyright file.
for page in imudesk imudesk-cli; do
  gzip -t "$prefix/share/man/man1/$page.1.gz" 2>/dev/null || fail "man page share/man/man1/$page.1.gz missing or damaged"
  [ "$(gzip -dc "$prefix/share/man/man1/$page.1.gz" | grep -c '^\.TH ')" -eq 1 ] || fail "$page.1.gz is not a manual page"
done
[ -f "$prefix/share/doc/imudesk/copyright" ] || fail "share/doc/imudesk/copyright missing"
if command -v desktop-file-validate >/dev/null; then desktop-file-validate "$desktop"; fi
if command -v appstreamcli >/dev/null; then appstreamcli validate --no-net "$prefix/share/metainfo/$id.metainfo.xml" >/dev/null; fi
# The installed binary runs (offscreen) and reports its version.
QT_QPA_PLATFORM=offscreen "$prefix/bin/imudesk-cli" --version | grep -q '^imudesk-cli '
echo "install check: ok ($prefix)"
