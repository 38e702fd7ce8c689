#!/usr/bin/env bash
# Safety test of scripts/check-fresh-debian.sh: a run that is killed midway (SIGKILL to its whole
# process group during the package install, so that no trap of its own runs) leaves the host's /dev
# as it was and no mount behind, and the root it left is removed by the next run (--clean) without
# touching /dev; a run stopped with SIGTERM removes its own root. Needs root and the mirror.
#   scripts/test-check-fresh-debian.sh
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
check="$here/check-fresh-debian.sh"
work="$(mktemp -d)"
passed=0 failed=0
ok() { echo "   ok $*"; passed=$((passed + 1)); }
bad() { echo "   FAIL $*"; failed=$((failed + 1)); }

dev_state() { # every directory and device node of the host's /dev (not the pts instance) with its type and numbers
  find /dev -xdev \( -type c -o -type b -o -type d \) -printf '%p %y %m\n' 2>/dev/null | sort
  stat -c '%n %t:%T' /dev/null /dev/zero /dev/urandom /dev/tty 2>/dev/null
}

killed_root=""
run_and_kill() { # signal: start a check in its own session, signal it once the package install runs
  local sig="$1" log="$work/run-$1.log" pid waited=0
  killed_root=""
  setsid "$check" --build "${IMUDESK_BUILD:-/nonexistent}" > "$log" 2>&1 &
  pid=$!
  while ! grep -q 'marker: package install running' "$log" 2>/dev/null; do
    sleep 0.5; waited=$((waited + 1))
    if ! kill -0 "$pid" 2>/dev/null || [ "$waited" -gt 1200 ]; then
      bad "SIG$sig run: the check never reached its package install"; cat "$log"; return 1
    fi
  done
  sleep 8 # dpkg/apt at work inside the root, its /dev, proc and sysfs mounted
  killed_root="$(sed -n 's/^ *root: //p' "$log" | head -n 1)"
  if [ "$sig" = KILL ]; then kill -KILL -- "-$pid"; else kill -"$sig" "$pid"; fi
  for _ in $(seq 120); do pgrep -s "$pid" > /dev/null || break; sleep 0.5; done
  if pgrep -s "$pid" > /dev/null; then bad "SIG$sig run: processes of the killed run still alive"; pgrep -a -s "$pid"; fi
}

before="$(dev_state)"
echo "== safety test of check-fresh-debian.sh ($(echo "$before" | wc -l) entries in the host's /dev)"

run_and_kill KILL
root="$killed_root"
case "$root" in /*) ;; *) echo "fresh-root safety: $passed passed, $((failed + 1)) failed"; exit 1 ;; esac
[ "$(dev_state)" = "$before" ] && ok "after SIGKILL during the package install: host /dev unchanged" \
  || { bad "after SIGKILL: host /dev changed"; diff <(echo "$before") <(dev_state) | head; }
echo probe > /dev/null 2>&1 && [ -c /dev/null ] && ok "/dev/null is still a character device" || bad "/dev/null damaged"
if awk -v p="$(dirname "$root")/" 'substr($5, 1, length(p)) == p' /proc/self/mountinfo | grep -q .; then
  bad "the host sees mounts below $(dirname "$root")"
else
  ok "the host sees no mount below the killed run's root"
fi
[ -d "$root/usr" ] && ok "the killed run left its root ($root)" || bad "no root left by the killed run (expected one)"
"$check" --clean > "$work/clean.log" 2>&1
[ ! -e "$(dirname "$root")" ] && ok "--clean removed it" || { bad "--clean did not remove $(dirname "$root")"; cat "$work/clean.log"; }
[ "$(dev_state)" = "$before" ] && ok "after removing the root: host /dev unchanged" \
  || { bad "after removing the root: host /dev changed"; diff <(echo "$before") <(dev_state) | head; }

# SIGTERM, as a CI runner or `timeout` stops a job: the run's own trap removes its root.
run_and_kill TERM
root="$killed_root"
if [ -n "$root" ] && [ ! -e "$(dirname "$root")" ]; then ok "after SIGTERM the run removed its own root"; else bad "SIGTERM left $root"; fi
[ "$(dev_state)" = "$before" ] && ok "after SIGTERM: host /dev unchanged" || bad "after SIGTERM: host /dev changed"

rm -rf "$work"
echo "fresh-root safety: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
