#!/usr/bin/env bash
# Makes the user guide's screenshots with the real application under the offscreen platform, on
# a screen of 1366x768 and one of 1920x1080, in English and Simplified Chinese:
#   scripts/screenshots.sh [BUILD_DIR]      (default build/test; writes docs/screenshots/)
# Every workspace kind (HiPNUC serial, its configuration, HEC495, Modbus, J1939, CANopen, a
# replay) is the GUI itself (--screenshot); every wizard page and the firmware-update dialog
# come from tst_layout (wizardPages, in tests/tests_ui), which checks them as it saves them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build/test}"
app="$build/app/gui/imudesk"
cli="$build/app/cli/imudesk-cli"
out="$root/docs/screenshots"
mkdir -p "$out"
rm -f "$out"/*.png
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
# A scratch settings folder, so that the pictures do not depend on this user's preferences.
export XDG_CONFIG_HOME="$scratch/config"
screen() { # width height -> an offscreen screen of that size
  local f="$scratch/screen-$1x$2.json"
  printf '{"screens": [{"name": "s", "x": 0, "y": 0, "width": %d, "height": %d, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]}\n' "$1" "$2" > "$f"
  echo "$f"
}
# A four-second capture of the tumbling simulator, for the replay workspace.
"$cli" simulate --pty --motion tumble > "$scratch/sim.txt" 2>&1 &
sim=$!
for _ in $(seq 50); do grep -q '^pty: ' "$scratch/sim.txt" && break; sleep 0.1; done
"$cli" record "$(sed -n 's/^pty: //p' "$scratch/sim.txt")" -o "$scratch/demo.imucap" --duration 4 > /dev/null 2>&1 || true
kill "$sim" 2> /dev/null || true
wait "$sim" 2> /dev/null || true
shot() { # name, width, height, language, arguments...
  local name="$1" w="$2" h="$3" lang="$4"; shift 4
  local file="$out/$name-${w}x$h-$lang.png"
  QT_QPA_PLATFORM="offscreen:configfile=$(screen "$w" "$h")" \
    "$app" -qwindowgeometry "${w}x$h+0+0" --lang "$lang" --screenshot "$file" --after "${after:-4}" "$@" > /dev/null 2>&1
  echo "  $file"
}
for lang in en zh_CN; do
  for size in "1366 768" "1920 1080"; do
    set -- $size
    shot main "$1" "$2" "$lang" --demo --motion tumble
    shot configuration "$1" "$2" "$lang" --demo --dock configuration
    shot hec495 "$1" "$2" "$lang" --link hec495 --motion spin
    shot modbus "$1" "$2" "$lang" --link modbus --motion tumble
    shot j1939 "$1" "$2" "$lang" --link can --motion tumble
    shot canopen "$1" "$2" "$lang" --link canopen --motion tumble
    [ -s "$scratch/demo.imucap" ] && shot replay "$1" "$2" "$lang" --link "$scratch/demo.imucap"
    # The production station on a simulated tray of eight (three faulty), once the quick plan has ended.
    after=25 shot station "$1" "$2" "$lang" --station-demo "$root/docs/examples/station-hi14-quick.json"
  done
done
# The wizards and the firmware-update dialog, every page, both sizes, both languages.
IMUDESK_LAYOUT_SHOTS="$out" QT_QPA_PLATFORM=offscreen "$build/tests/tests_ui" tst_layout wizardPages > "$scratch/wizards.log" 2>&1 \
  || { cat "$scratch/wizards.log"; echo "the wizard pages have layout problems (above)"; exit 1; }
ls "$out"/wizard-*.png "$out"/firmware-*.png | sed 's/^/  /'
