#!/usr/bin/env bash
# Makes the user guide's screenshots with the real application under the offscreen
# platform: scripts/screenshots.sh [BUILD_DIR] (default build/test). Writes docs/screenshots/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build/test}"
app="$build/app/gui/imudesk"
out="$root/docs/screenshots"
mkdir -p "$out"
export QT_QPA_PLATFORM=offscreen
# A scratch settings file, so that the pictures do not depend on this user's preferences.
export XDG_CONFIG_HOME="$(mktemp -d)"
trap 'rm -rf "$XDG_CONFIG_HOME"' EXIT
shot() { # name, language, arguments...
  local name="$1" lang="$2"; shift 2
  "$app" --lang "$lang" --screenshot "$out/$name-$lang.png" --after 4 "$@"
  echo "  $out/$name-$lang.png"
}
for lang in en zh_CN zh_TW; do
  shot main "$lang" --demo
  shot configuration "$lang" --demo --dock configuration
  shot hec495 "$lang" --link hec495 --motion spin
  shot modbus "$lang" --link modbus --motion tumble
  shot can "$lang" --link can --motion tumble
done
