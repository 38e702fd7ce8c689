#!/usr/bin/env bash
# The README's set-up commands work as a user with sudo rights: `scripts/setup.sh test` run as
# such a user (nobody, through setpriv) runs what needs root, the fresh-root check and its
# safety test, through sudo, as it does apt-get; a user without sudo is told what to do.
# The build, packaging and test tools are stand-ins that only note their call: what is proven
# is the script's own path up to and through the fresh-root phase (the stand-in of the last
# suite, ThreadSanitizer's, ends the run there). Usage: check_setup_as_user.sh SOURCE_DIR
set -euo pipefail
src="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v setpriv >/dev/null || { echo "setup as a user: skipped (no setpriv)"; exit 0; }
[ "$(id -u)" -eq 0 ] || { echo "setup as a user: skipped (needs root to become another user)"; exit 0; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"
# A copy of the scripts that nobody can read, in a tree of its own.
mkdir -p "$work/tree/scripts" "$work/bin" "$work/home"
cp "$src/scripts/setup.sh" "$src/scripts/debian-packages.txt" "$work/tree/scripts/"
mkdir -p "$work/tree/tests/fuzz"
printf '#!/bin/sh\necho "fuzzing ran" >> %s/calls\n' "$work" > "$work/tree/tests/fuzz/run.sh"
for s in check-fresh-debian.sh test-check-fresh-debian.sh; do
  printf '#!/bin/sh\necho "$0 ran as uid $(id -u)" >> %s/calls\n' "$work" > "$work/tree/scripts/$s"
done
printf 'import os\nopen("%s/calls", "a").write("check_windows.py ran as uid %%d\\n" %% os.getuid())\n' "$work" \
  > "$work/tree/scripts/check_windows.py"
printf 'import os\nimport sys\nos.makedirs(sys.argv[1], exist_ok=True)\nopen("%s/calls", "a").write("combine_suites.py ran\\n")\n' "$work" > "$work/tree/scripts/combine_suites.py"
stub() { # name, body
  printf '#!/bin/sh\n%s\n' "$2" > "$work/bin/$1"
}
stub dpkg-query 'echo "install ok installed"'
# A build makes stand-ins of the benchmarks that the run starts from it.
stub cmake 'echo "cmake $*" >> '"$work"'/calls; for a in "$@"; do [ "$prev" = -B ] && mkdir -p "$a"
  if [ "$prev" = --build ]; then mkdir -p "$a/tests/bench"
    for b in bench_decode bench_alloc_live bench_gui_live bench_export bench_allan bench_magcal bench_update bench_station soak; do
      printf "#!/bin/sh\necho \"\$0 ran\" >> '"$work"'/calls\n" > "$a/tests/bench/$b"; chmod a+x "$a/tests/bench/$b"; done
  fi; prev="$a"; done; exit 0'
stub dpkg-deb 'echo "libc6"'
stub cpack 'for a in "$@"; do case "$prev" in -B) mkdir -p "$a" && touch "$a/imudesk_0_amd64.deb";; esac; prev="$a"; done'
stub lintian 'exit 0'
stub npm 'echo "npm $*" >> '"$work"'/calls'
# The suites pass, up to the last one (ThreadSanitizer's), which ends the run after the
# fresh-root phase, which waits for the check and its safety test (they run beside fuzzing).
stub ctest 'case "$*" in *"-L tsan"*) echo "ctest reached" >> '"$work"'/calls; exit 3;; esac; exit 0'
stub sudo 'echo "sudo $*" >> '"$work"'/calls; while [ "${1#-}" != "$1" ]; do shift; done; exec "$@"'
chmod -R a+rX "$work" && chmod 777 "$work" "$work/home" && chmod a+x "$work"/bin/* "$work"/tree/scripts/*.sh "$work/tree/tests/fuzz/run.sh"
touch "$work/calls" && chmod 666 "$work/calls"
chown -R 65534:65534 "$work/tree" # the user's own checkout
as_nobody() {
  setpriv --reuid=65534 --regid=65534 --clear-groups env -i HOME="$work/home" PATH="$1:/usr/bin:/bin" \
    bash "$work/tree/scripts/setup.sh" test > "$work/out" 2>&1
}
# With sudo: the fresh-root check and its safety test run through it, and the run goes on.
rc=0
as_nobody "$work/bin" || rc=$?
[ "$rc" -eq 3 ] || { cat "$work/out" >&2; fail "setup.sh test as a user with sudo stopped with $rc before the last test suite"; }
grep -q "^sudo .*check-fresh-debian.sh --build $work/tree/build/test" "$work/calls" \
  || { cat "$work/calls" >&2; fail "the fresh-root check did not run through sudo"; }
grep -q "^sudo .*test-check-fresh-debian.sh" "$work/calls" || fail "the fresh-root safety test did not run through sudo"
# Without sudo: a clear word on what to do, before anything needs root.
rm "$work/bin/sudo"
: > "$work/calls"
rc=0
as_nobody "$work/bin" || rc=$?
[ "$rc" -eq 1 ] || { cat "$work/out" >&2; fail "without sudo: exit $rc, expected 1"; }
grep -q "needs root: run this as root, or give this user sudo rights" "$work/out" \
  || { cat "$work/out" >&2; fail "without sudo: no word on what to do"; }
echo "setup as a user: ok"
