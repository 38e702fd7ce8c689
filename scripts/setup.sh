#!/usr/bin/env bash
# ImuDesk set-up on Debian 12; safe to run again. Run it as root (a container, a new VM: no sudo
# needed) or as a user with sudo rights: then only apt-get runs through sudo, and the build is yours.
#   scripts/setup.sh demo     install packages, build a release build, open imudesk on a simulated HI14 (--demo)
#   scripts/setup.sh package  install packages, build a release build, make the Debian package
#                             build/release/package/imudesk_<version>_amd64.deb (cpack) and lint it (lintian)
#   scripts/setup.sh test     install packages, build, make and lint the Debian package, prove the package
#                             list and the package in a fresh Debian 12 root (scripts/check-fresh-debian.sh:
#                             it installs the .deb there with apt-get), run the whole test suite headless (the
#                             widget tests in the release build, every other test in an AddressSanitizer + UBSan
#                             build) and the benchmarks, then every fuzz target (clang, libFuzzer) for
#                             FUZZ_SECONDS (default 20) and the threads' tests with ThreadSanitizer
#   scripts/setup.sh install  only install the Debian packages (the fresh-root check runs this inside its root)
#   (scripts/setup.sh later-builds: the ThreadSanitizer and fuzz builds alone; `test` runs it in the background)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
mode="${1:-}"
case "$mode" in
  demo|package|test|install|later-builds) ;;
  *) echo "usage: $0 demo|package|test|install" >&2; exit 2 ;;
esac

jobs="$(nproc 2>/dev/null || echo 2)"
# ccache (when installed; CMakeLists.txt uses it): paths below the tree are hashed relative to
# it, so a fresh clone in another folder reuses what an earlier build of the same sources made.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1

install_packages() {
  mapfile -t pkgs < <(grep -Ev '^\s*(#|$)' "$here/debian-packages.txt")
  local missing=()
  for p in "${pkgs[@]}"; do
    # Node.js from another source (NodeSource's nodejs carries npm and conflicts with Debian's
    # npm package): the commands are what the tests need.
    case "$p" in
      nodejs) command -v node >/dev/null && continue ;;
      npm) command -v npm >/dev/null && continue ;;
    esac
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  if ((${#missing[@]})); then
    local sudo=()
    if [ "$(id -u)" -ne 0 ]; then
      if ! command -v sudo >/dev/null; then
        echo "!! missing packages: ${missing[*]}" >&2
        echo "!! run this as root (there is no sudo here), or install sudo and give this user sudo rights" >&2
        exit 1
      fi
      sudo=(sudo)
    fi
    echo "== installing ${missing[*]}"
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
  else
    echo "== Debian packages: all present"
  fi
}

configure_and_build_targets() { # dir, build type, targets (one word, ;-separated), extra cmake args...
  local dir="$1" type="$2" targets="$3"; shift 3
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$type" "$@"
  cmake --build "$dir" -j "$jobs" --target ${targets//;/ }
}
configure_and_build() { # dir, build type, extra cmake args...: everything the configuration has
  local dir="$1" type="$2"; shift 2
  configure_and_build_targets "$dir" "$type" all "$@"
}

# The Debian package of a built tree: DIR/package/imudesk_<version>_<arch>.deb (cmake/Packaging.cmake
# says what goes in it). cpack installs what the tree has built; it builds nothing itself.
make_package() { # dir
  local dir="$1" deb
  rm -f "$dir/package/"imudesk_*.deb
  cpack -G DEB --config "$dir/CPackConfig.cmake" -B "$dir/package" > "$dir/package.log" 2>&1 \
    || { tail -n 25 "$dir/package.log" >&2; echo "!! cpack could not make the package (log: $dir/package.log)" >&2; exit 1; }
  deb="$(ls "$dir/package/"imudesk_*.deb)"
  echo "   package: $deb"
  echo "   depends: $(dpkg-deb -f "$deb" Depends)"
}
# lintian on a package: every tag it reports is printed; an error fails the run, warnings do not.
lint_package() { # dir
  local deb rc=0
  deb="$(ls "$1/package/"imudesk_*.deb)"
  lintian --fail-on error --display-info "$deb" > "$1/lintian.log" 2>&1 || rc=$?
  sed 's/^/   | /' "$1/lintian.log"
  if [ "$rc" -ne 0 ]; then
    echo "!! lintian reports errors in $deb (above)" >&2
    exit 1
  fi
  echo "   lintian: no error ($(grep -c '^W: ' "$1/lintian.log" || true) warnings)"
}

# The builds that `test` needs last, for its fuzzing and ThreadSanitizer phases (what they are is
# said where those phases run).
if [ "$mode" = later-builds ]; then
  configure_and_build_targets "$root/build/tsan" Release tsan_tests -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
    -DIMUDESK_TSAN=ON -DIMUDESK_BUILD_GUI=OFF -DIMUDESK_BUILD_TESTS=ON -DIMUDESK_BUILD_BENCH=OFF
  FUZZ_BUILD_ONLY=1 BUILD_JOBS="$jobs" "$root/tests/fuzz/run.sh" "${FUZZ_SECONDS:-20}" "$root/build/fuzz"
  exit 0
fi

install_packages
# The test-only tools from npm, at the versions tests/mcap/package-lock.json pins: the official
# MCAP reader (@mcap/core) and the ROS 2 message decoder the MCAP tests read files back with.
install_test_tools() {
  echo "== npm ci --prefix tests/mcap (the official MCAP reader, for the tests)"
  npm ci --prefix "$root/tests/mcap" --no-audit --no-fund --loglevel=error
}
if [ "$mode" = install ] || [ "$mode" = test ]; then
  install_test_tools
fi
[ "$mode" = install ] && exit 0

if [ "$mode" = package ]; then
  configure_and_build "$root/build/release" Release -DIMUDESK_BUILD_TESTS=OFF -DIMUDESK_BUILD_BENCH=OFF
  make_package "$root/build/release"
  lint_package "$root/build/release"
  echo "Install it with: sudo apt-get install $(ls "$root/build/release/package/"imudesk_*.deb)"
  exit 0
fi

if [ "$mode" = demo ]; then
  configure_and_build "$root/build/release" Release -DIMUDESK_BUILD_TESTS=OFF
  if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ] && [ -z "${QT_QPA_PLATFORM:-}" ]; then
    echo "No display found: run this from a desktop session (or set QT_QPA_PLATFORM)." >&2
    exit 1
  fi
  exec "$root/build/release/app/gui/imudesk" --demo
fi

# test: each phase says how long it took, and the end lists them all (for CI's log).
phase_names=() phase_secs=()
phase_name="" phase_start=$SECONDS run_start=$SECONDS
phase() { # name: ends the running phase, starts this one
  if [ -n "$phase_name" ]; then
    phase_names+=("$phase_name"); phase_secs+=($((SECONDS - phase_start)))
    echo "   ($((SECONDS - phase_start)) s)"
  fi
  phase_name="$1" phase_start=$SECONDS
  [ -n "$1" ] && echo "== $1"
  return 0
}
phase_summary() {
  phase ""
  echo "== time per phase"
  for i in "${!phase_names[@]}"; do printf '   %6d s  %s\n' "${phase_secs[$i]}" "${phase_names[$i]}"; done
  printf '   %6d s  in all\n' $((SECONDS - run_start))
}
trap 'phase_summary' EXIT
export QT_QPA_PLATFORM=offscreen

# The fresh-root check and its safety test need root (mmdebstrap's root mode, mount namespaces):
# a user with sudo rights runs them through sudo, as apt-get above (the build they read stays
# the user's). Known before the first build, so that a user without sudo is told at once.
as_root=()
if [ -z "${IMUDESK_IN_FRESH_ROOT:-}" ] && [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null; then
    echo "!! the fresh-root check needs root: run this as root, or give this user sudo rights" >&2
    exit 1
  fi
  as_root=(sudo --preserve-env=IMUDESK_FRESH_CACHE,IMUDESK_FRESH_WORKDIR,IMUDESK_DEBIAN_MIRROR)
fi
# The fresh-root check: fails when a build, test or runtime dependency is missing from
# scripts/debian-packages.txt (the host may have it installed by hand), naming it, or when the
# Debian package lacks a dependency: it is installed with apt-get into the bare root before the
# list, and imudesk and imudesk-cli run from /usr/bin. Before it, the check's own safety test: a run
# killed during its package install leaves the host's /dev untouched and its root removable.
# Both mostly wait on tar, apt, dpkg and the mirror (together about one core for two minutes),
# so they run in the background, one after the other (they share the cache and the roots'
# folder), each into its own log, printed when they are waited for. They run beside fuzzing,
# whose length is set in seconds per parser whatever else runs, so they cost the run no time
# there (beside a build they cost the build their CPU; beside a benchmark they would disturb what
# it measures; beside the suite, even at nice 19, their package installs made four of its pty
# tests miss a reply once, in the run's first minutes). A run that stops early stops them too
# (SIGTERM: the check removes its root).
background_checks() { # the safety test, then the check of the package made from build/test
  if [ -n "${IMUDESK_IN_FRESH_ROOT:-}" ]; then
    for name in fresh-root-safety fresh-root-check; do
      echo "skipped: this run is itself inside the fresh root check's root" > "$root/build/$name.log"
    done
    return 0
  fi
  (
    child=""
    trap '[ -z "$child" ] || kill -TERM "$child" 2>/dev/null; wait; exit 143' TERM
    "${as_root[@]}" "$here/test-check-fresh-debian.sh" > "$root/build/fresh-root-safety.log" 2>&1 &
    child=$!
    wait "$child" || exit 1
    "${as_root[@]}" "$here/check-fresh-debian.sh" --build "$root/build/test" > "$root/build/fresh-root-check.log" 2>&1 &
    child=$!
    wait "$child" || exit 2
  ) &
  background_pid=$!
}
background_pid=""
wait_background_checks() { # prints their logs; fails the run when one failed
  local rc=0 name
  if [ -n "$background_pid" ]; then
    wait "$background_pid" || rc=$?
  fi
  background_pid=""
  for name in fresh-root-safety fresh-root-check; do
    echo "   -- $name (log: build/$name.log)"
    [ ! -f "$root/build/$name.log" ] || sed 's/^/   /' "$root/build/$name.log"
  done
  case "$rc" in
    0) ;;
    1) echo "!! the fresh-root check's safety test failed (above; log: build/fresh-root-safety.log)" >&2; exit 1 ;;
    *) echo "!! the fresh-root check failed (above; log: build/fresh-root-check.log)" >&2; exit 1 ;;
  esac
}
# The ThreadSanitizer and fuzz builds (`later-builds` above) run in the background from the
# suite on, at nice 19: the suite mostly waits on simulated devices' clocks (it leaves the two
# cores about a fifth idle), and the scheduler gives a nice-19 build only the CPU it leaves
# idle, so the builds advance without taking time from the tests. Stopped (SIGSTOP to their
# process group) while the benchmarks measure speed, continued and waited for after them,
# before fuzzing. In their own session (setsid), so the group can be signalled.
later_pid=""
start_later_builds() {
  setsid nice -n 19 "$here/setup.sh" later-builds > "$root/build/later-builds.log" 2>&1 &
  later_pid=$!
}
signal_later_builds() { # signal
  [ -z "$later_pid" ] || kill "-$1" -- "-$later_pid" 2>/dev/null || true
}
wait_later_builds() {
  local rc=0
  [ -z "$later_pid" ] || wait "$later_pid" || rc=$?
  later_pid=""
  tail -n 5 "$root/build/later-builds.log" | sed 's/^/   /'
  if [ "$rc" -ne 0 ]; then
    tail -n 40 "$root/build/later-builds.log" >&2
    echo "!! the ThreadSanitizer or fuzz build failed (above; log: build/later-builds.log)" >&2
    exit 1
  fi
}
trap '[ -z "$background_pid" ] || kill -TERM "$background_pid" 2>/dev/null; signal_later_builds CONT; signal_later_builds TERM; phase_summary' EXIT
# The suites run up to eight tests a core: most of them wait on a simulated device's clock, and
# ctest's resource allocation (tests/CMakeLists.txt gives each test its measured CPU share, the
# build writes ctest-cpu-slots.json) keeps the CPU they need within the cores.
# A test that fails is run once more: only a test that fails twice stops the run (the pty and
# timing tests share two cores with everything else on a CI machine).
run_suite() { # build dir, extra ctest args...
  local dir="$1"; shift
  (cd "$dir" && ctest --output-on-failure -j "$((jobs * 8))" --resource-spec-file "$dir/ctest-cpu-slots.json" \
    --repeat until-pass:2 "$@")
}

phase "build (release, tests and benchmarks)"
mkdir -p "$root/build"
configure_and_build "$root/build/test" Release -DIMUDESK_BUILD_TESTS=ON -DIMUDESK_BUILD_BENCH=ON
phase "Debian package: build it and lint it (cpack from build/test, lintian)"
# The binaries of the build above, no second build: build/test/package/imudesk_<version>_amd64.deb.
make_package "$root/build/test"
lint_package "$root/build/test"

phase "Windows compile check: core, ui and app for Windows with mingw-w64, syntax only (scripts/check_windows.py)"
python3 "$root/scripts/check_windows.py" "$root/build/test"

phase "build with AddressSanitizer and UndefinedBehaviorSanitizer"
# The core, imudesk-cli and every test that needs no widgets (unit, integration, threads), without
# debug information. The widget tests and the window run from the release build only: on a
# fresh 2-core machine their instrumented build and run (the UI library, the GUI, tests_ui; the
# slowest tests of the suite) cost about 500 s of a cold run that issue 53 bounds at 1,800 s, and
# the code they exercise beyond the core is the widgets'. The tests and the application compile
# at -O0 (IMUDESK_TEST_OPTIMIZE), in about 0.7 of -O1's time; the core stays at -O1
# (IMUDESK_CORE_OPTIMIZE), as its Eigen maths needs inlining to run in time. AddressSanitizer
# finds the same errors at either level. Leak checking stays with the fuzzers (Qt's caches live
# until exit).
configure_and_build "$root/build/asan" Release -DCMAKE_CXX_FLAGS_RELEASE="-O0 -DNDEBUG" \
  -DIMUDESK_TEST_OPTIMIZE=-O0 -DIMUDESK_CORE_OPTIMIZE=-O1 -DIMUDESK_SANITIZE=ON \
  -DIMUDESK_BUILD_GUI=OFF -DIMUDESK_BUILD_TESTS=ON -DIMUDESK_BUILD_BENCH=OFF
# Each test of the suite runs once, all in one ctest run (one pool of the cores for both builds'
# tests): the widget tests (label gui) from the release build, every other test from the
# sanitizer build, which builds all of them and finds what the release build would not (the
# release build's speed is the benchmarks' to measure, after this phase).
phase "test suite: the widget tests of the release build and every other test in the sanitizer build, one run (scripts/combine_suites.py; beside it, at nice 19: the ThreadSanitizer and fuzz builds)"
start_later_builds
python3 "$here/combine_suites.py" "$root/build/suites" "$root/build/test/ctest-cpu-slots.json" \
  "$root/build/test=^gui$" "$root/build/asan=^sanitized$"
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
run_suite "$root/build/suites" --timeout 900
unset ASAN_OPTIONS UBSAN_OPTIONS
signal_later_builds STOP
phase "benchmark (decode throughput against the manual's byte-at-a-time decoder)"
"$root/build/test/tests/bench/bench_decode" --mb 50
phase "benchmark (heap allocations per frame on the live session path)"
"$root/build/test/tests/bench/bench_alloc_live" || echo "!! bench_alloc_live missed a target (see above)"
# bench_gui_live and soak: exit 2 = a frame that reached ImuDesk was lost or the capture is
# damaged (fails the run); exit 1 = a target missed, e.g. frames the pty dropped because a loaded
# machine did not schedule the reader in time (reported, like the other benchmarks' targets).
# Like the test suite, a run that fails is run once more: only a failure twice stops CI.
live_bench() {
  local rc=0
  "$@" || rc=$?
  if [ "$rc" -ge 2 ]; then
    echo "!! $(basename "$1") lost data that reached ImuDesk (see above); running it once more"
    rc=0
    "$@" || rc=$?
    if [ "$rc" -ge 2 ]; then
      echo "!! $(basename "$1") lost data that reached ImuDesk twice (see above)" >&2
      exit 1
    fi
  fi
  [ "$rc" -eq 0 ] || echo "!! $(basename "$1") missed a target (see above)"
}
# Benchmark runs are shorter in CI than by hand (issue 33: CI's time): each still compares with
# its baseline in the same run; the full lengths are in each phase's name or docs/BENCHMARKS.md
# (the live bridge's: docs/LIVE_BRIDGE.md).
phase "benchmark (the whole window offscreen, simulator at 921600 baud, HI91 at 1000 Hz, 20 s in CI)"
live_bench "$root/build/test/tests/bench/bench_gui_live" --seconds 20
phase "benchmark (issue 36's four devices in one window: two modules at 1000 Hz, an HEC495 polled, a CANopen module on virtualcan; recorded as one session and exported aligned; 15 s in CI, 10 min in docs/BENCHMARKS.md)"
session_dir=$(mktemp -d)
live_bench "$root/build/test/tests/bench/bench_gui_live" --seconds 15 --devices 2 --mix --record "$session_dir"
rm -rf "$session_dir"
phase "benchmark (the live bridge: four modules at 1000 Hz in the window, two official Foxglove clients, every sample received; 15 s in CI, 60 s in docs/LIVE_BRIDGE.md)"
live_bench "$root/build/test/tests/bench/bench_gui_live" --seconds 15 --devices 4 --bridge
bench="$root/build/test/tests/bench"
phase "benchmark (export of a 1 kHz HI91 capture, 10 min of it in CI; --frames 3600000 for the full hour)"
"$bench/bench_export" --frames 600000 || echo "!! bench_export missed a target (see above)"
phase "benchmark (Allan deviation of 3.6 million samples per axis)"
"$bench/bench_allan" || echo "!! bench_allan missed a target (see above)"
phase "benchmark (magnetometer fit accuracy and speed against known truth, 100 trials in CI, 200 by default)"
"$bench/bench_magcal" --trials 100 --sweep-trials 400 || echo "!! bench_magcal missed a target (see above)"
phase "benchmark (firmware update throughput over a pty at 115200 and 921600 baud)"
"$bench/bench_update" --quick || echo "!! bench_update missed a target (see above)"
phase "benchmark (production station: a plan on eight simulated modules against one; 10 s in CI, 60 s by default)"
"$bench/bench_station" --plan-seconds 10 || echo "!! bench_station missed a target (see above)"
phase "benchmark (one time base: 4 simulated devices, 10 min of device time accelerated, against the truth)"
"$bench/bench_sync" || echo "!! bench_sync missed a target (see above)"
phase "benchmark (the module check: 200 simulated modules of known errors turned through 12 poses, bounds calibrated, 15 min at 400 Hz analysed)"
"$bench/bench_verify" || echo "!! bench_verify missed a target (see above)"
phase "benchmark (one sweep finds every device of a simulated bench: 4 ports and a CAN bus, against the same checks one after the other)"
"$bench/bench_discover" || echo "!! bench_discover missed a target (see above)"
phase "benchmark (results database: 1,000 module records uploaded to PostgreSQL, queries over 100,000 measurements)"
"$bench/bench_results" || echo "!! bench_results missed a target (see above)"
phase "soak (1 kHz HI91 with recording and the GUI offscreen; 20 s in CI, one hour by default)"
live_bench "$bench/soak" --seconds 20

phase "the ThreadSanitizer and fuzz builds: what was left of them after the suite and the benchmarks (log: build/later-builds.log)"
signal_later_builds CONT
wait_later_builds

phase "fuzzing every parser, ${FUZZ_SECONDS:-20} s each (beside it: the fresh-root check's safety test, then the check)"
mkdir -p "$root/build"
background_checks
FUZZ_JOBS="$jobs" "$root/tests/fuzz/run.sh" "${FUZZ_SECONDS:-20}" "$root/build/fuzz"
phase "fresh Debian 12 root (waited for after fuzzing): the package list alone configures the project, the .deb installs and runs; a check killed midway leaves the host's /dev as it was"
wait_background_checks

phase "the threads' tests in the ThreadSanitizer build (any report fails; later-builds built core and these tests, ctest label tsan)"
# The session engine, recording, replay, station and firmware tests (tests/CMakeLists.txt lists
# them); no GUI. tests/tsan.supp says what is suppressed and why.
# halt_on_error: the first report ends its test with exitcode 66, so ctest names it; a test that
# fails is run once more, as above (a report is a failure both times: it is the code, not load).
# die_after_fork=0: tests start imudesk-cli (QProcess forks a process that may start threads
# before it runs the program; TSan would otherwise stop it there).
export TSAN_OPTIONS="suppressions=$root/tests/tsan.supp:halt_on_error=1:exitcode=66:second_deadlock_stack=1:die_after_fork=0"
run_suite "$root/build/tsan" -L tsan --timeout 900
unset TSAN_OPTIONS
