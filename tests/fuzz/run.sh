#!/usr/bin/env bash
# Runs every libFuzzer target for SECONDS each.
#
#   tests/fuzz/run.sh SECONDS [BUILD_DIR]
#
# BUILD_DIR defaults to <repo>/build-fuzz. When it holds no build yet it is
# configured with clang and IMUDESK_FUZZ=ON; the fuzz targets are then built
# (a no-op when up to date). Each target starts from its seed corpus in
# tests/fuzz/seeds/<target>/, copied into BUILD_DIR/fuzz/corpus/<target>/ (the
# scratch corpus keeps growing across runs; the seed directory is never written).
# Crash/leak reproducers land in BUILD_DIR/fuzz/artifacts/<target>/, full logs in
# BUILD_DIR/fuzz/logs/<target>.log.
#
# Environment:
#   FUZZ_TARGETS  space-separated subset (default: every tests/fuzz/fuzz_*.cpp)
#   FUZZ_JOBS     targets run at the same time, 1 or 2 (default 1)
#   BUILD_JOBS    ninja -j (default 2)
#   FUZZ_ARGS     extra libFuzzer flags
#
# Exit status: 0 when no target crashed, leaked, timed out or reported a
# sanitizer error; 1 otherwise; 2 on usage or build errors.
set -u

usage() {
    echo "usage: $0 SECONDS [BUILD_DIR]" >&2
    exit 2
}

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    usage
fi
SECONDS_PER_TARGET=$1
case "$SECONDS_PER_TARGET" in
'' | *[!0-9]*) usage ;;
esac
[ "$SECONDS_PER_TARGET" -ge 1 ] || usage

SCRIPT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
SRC_DIR=$(cd "$SCRIPT_DIR/../.." && pwd)
BUILD_DIR=${2:-$SRC_DIR/build-fuzz}
case "$BUILD_DIR" in
/*) ;;
*) BUILD_DIR=$PWD/$BUILD_DIR ;;
esac
# Every tests/fuzz/fuzz_<name>.cpp is a target.
ALL_TARGETS=$(cd "$SCRIPT_DIR" && ls fuzz_*.cpp | sed 's/\.cpp$//' | tr '\n' ' ')
TARGETS=${FUZZ_TARGETS:-$ALL_TARGETS}
JOBS=${FUZZ_JOBS:-1}
BUILD_JOBS=${BUILD_JOBS:-2}

# --- configure and build ----------------------------------------------------
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    echo "== configuring $BUILD_DIR (clang, IMUDESK_FUZZ=ON)"
    # -O1 (the level libFuzzer's authors use) with line tables for the reports instead of the
    # default -O2 -g, and the asserts on (no NDEBUG).
    CC=clang CXX=clang++ cmake -S "$SRC_DIR" -B "$BUILD_DIR" -G Ninja -DIMUDESK_FUZZ=ON \
        -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" \
        -DIMUDESK_BUILD_GUI=OFF -DIMUDESK_BUILD_TESTS=ON -DIMUDESK_BUILD_BENCH=OFF || exit 2
elif ! grep -q '^IMUDESK_FUZZ:BOOL=ON' "$BUILD_DIR/CMakeCache.txt"; then
    echo "error: $BUILD_DIR is not a fuzz build (IMUDESK_FUZZ is not ON); pick another BUILD_DIR" >&2
    exit 2
fi
echo "== building $TARGETS"
# shellcheck disable=SC2086
cmake --build "$BUILD_DIR" -j "$BUILD_JOBS" --target $TARGETS || exit 2
# FUZZ_BUILD_ONLY=1: build, do not fuzz (scripts/setup.sh builds ahead, beside its suites).
[ "${FUZZ_BUILD_ONLY:-0}" = 1 ] && exit 0

WORK=$BUILD_DIR/fuzz
mkdir -p "$WORK/logs"

# --- run ---------------------------------------------------------------------
run_target() {
    local t=$1 bin corpus artifacts log
    bin=$BUILD_DIR/tests/fuzz/$t
    [ -x "$bin" ] || bin=$(find "$BUILD_DIR" -type f -name "$t" -perm -u+x | head -n 1)
    corpus=$WORK/corpus/$t
    artifacts=$WORK/artifacts/$t
    log=$WORK/logs/$t.log
    if [ -z "$bin" ]; then
        echo "error: $t was not built" >"$log"
        echo 2 >"$WORK/logs/$t.rc"
        return
    fi
    mkdir -p "$corpus" "$artifacts"
    touch "$WORK/logs/$t.start"
    if [ -d "$SCRIPT_DIR/seeds/$t" ]; then
        cp -p "$SCRIPT_DIR/seeds/$t/"* "$corpus/" 2>/dev/null
    fi
    # shellcheck disable=SC2086
    ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0} \
    UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
        "$bin" "$corpus" -max_len=4096 -max_total_time="$SECONDS_PER_TARGET" -timeout=25 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$artifacts/" ${FUZZ_ARGS:-} >"$log" 2>&1
    echo $? >"$WORK/logs/$t.rc"
}

stat_of() { # stat_of LOG NAME -> value of "stat::NAME: value"
    sed -n "s/^stat::$2: *//p" "$1" | tail -n 1
}

echo "== fuzzing: ${SECONDS_PER_TARGET}s per target, $JOBS at a time, logs in $WORK/logs"
running=0
for t in $TARGETS; do
    rm -f "$WORK/logs/$t.rc"
    echo "   $(date +%H:%M:%S) start $t"
    if [ "$JOBS" -ge 2 ]; then
        run_target "$t" &
        running=$((running + 1))
        if [ "$running" -ge "$JOBS" ]; then
            wait -n
            running=$((running - 1))
        fi
    else
        run_target "$t"
    fi
done
wait

# --- report ------------------------------------------------------------------
status=0
printf '\n%-20s %-10s %12s %8s %14s %6s %12s %7s\n' target result executions exec/s "corpus units" cov "corpus dir" "rss MB"
for t in $TARGETS; do
    log=$WORK/logs/$t.log
    rc=$(cat "$WORK/logs/$t.rc" 2>/dev/null || echo 2)
    result=ok
    if grep -q 'ERROR: LeakSanitizer' "$log"; then
        result=LEAK
    elif grep -qE 'ERROR: AddressSanitizer|runtime error:|ERROR: UndefinedBehaviorSanitizer' "$log"; then
        result=SANITIZER
    elif grep -q 'ERROR: libFuzzer: timeout' "$log"; then
        result=TIMEOUT
    elif grep -qE 'ERROR: libFuzzer: out-of-memory|ERROR: libFuzzer: .*malloc' "$log"; then
        result=OOM
    elif grep -qE 'ERROR: libFuzzer: deadly signal|ERROR: libFuzzer' "$log"; then
        result=CRASH
    elif [ "$rc" != 0 ]; then
        result="EXIT $rc"
    fi
    [ "$result" = ok ] || status=1
    # libFuzzer's own view (the last status line): corpus units/bytes and coverage.
    last=$(grep -E '^#[0-9]+[[:space:]].*cov: [0-9]+.*corp: ' "$log" | tail -n 1)
    units=$(echo "$last" | sed -n 's/.*corp: \([^ ]*\).*/\1/p')
    cov=$(echo "$last" | sed -n 's/.*cov: \([0-9]*\).*/\1/p')
    files=$(find "$WORK/corpus/$t" -type f 2>/dev/null | wc -l)
    printf '%-20s %-10s %12s %8s %14s %6s %12s %7s\n' "$t" "$result" "$(stat_of "$log" number_of_executed_units)" \
        "$(stat_of "$log" average_exec_per_sec)" "${units:--}" "${cov:--}" "$files files" "$(stat_of "$log" peak_rss_mb)"
    if [ "$result" != ok ]; then
        grep -m 3 -E 'invariant failed|ERROR:|runtime error:|SUMMARY:' "$log" | sed 's/^/    /'
        find "$WORK/artifacts/$t" -type f -newer "$WORK/logs/$t.start" 2>/dev/null | head -n 5 |
            sed 's/^/    reproducer: /'
    fi
done
exit $status
