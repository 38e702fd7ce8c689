#!/usr/bin/env bash
# Proves that scripts/debian-packages.txt is complete: in a fresh Debian 12 minbase root, with only
# what `scripts/setup.sh install` installs there (the same function as the README's two commands),
# the project configures with tests and benchmarks on and the sanitizer and fuzzer toolchains link;
# and that the Debian package (cmake/Packaging.cmake) installs: `apt-get install ./imudesk_*.deb` in
# the bare root, before the list, brings every library it needs, and from /usr/bin the application
# (imudesk --demo --screenshot) and the CLI (simulate --pty + probe, --help) run offscreen and
# `man imudesk-cli` shows its manual page.
#
#   scripts/check-fresh-debian.sh [--build DIR]   DIR: a built tree whose package DIR/package/imudesk_*.deb
#                                                 is installed in the root (default build/test; made with
#                                                 cpack here when DIR has binaries but no package; without
#                                                 binaries, imudesk and imudesk-cli are built and packaged
#                                                 inside the root after the list, which is slower)
#   scripts/check-fresh-debian.sh --clean         only remove roots left behind by killed runs
#   scripts/check-fresh-debian.sh --readme demo|test
#                                                 instead of the steps, run the README's command
#                                                 (scripts/setup.sh demo|test) as root in the fresh
#                                                 root, as a new user would (test: about an hour)
#
# Needs root (mmdebstrap's root mode, mount namespaces) and Debian's package mirror.
# Environment: IMUDESK_FRESH_CACHE (base tarball and .deb cache, default ~/.cache/imudesk/fresh-debian),
# IMUDESK_FRESH_WORKDIR (where roots are made, default /var/tmp), IMUDESK_DEBIAN_MIRROR,
# IMUDESK_DEBIAN_SECURITY, IMUDESK_FRESH_PACKAGE_LIST (another package list, for testing this check).
#
# Safety: every mount is made inside a private mount and PID namespace (unshare); the root gets its
# own proc, a read-only sysfs and a tmpfs /dev holding only null, zero, full, random, urandom, tty,
# a new devpts instance and a tmpfs /dev/shm. Nothing of the host's /dev or /sys is ever bound into it. The root is
# removed with `rm -rf --one-file-system` only after the namespace is gone, and only when the host
# sees no mount below it.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
src="$(cd "$here/.." && pwd)"
cache="${IMUDESK_FRESH_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/imudesk/fresh-debian}"
workbase="${IMUDESK_FRESH_WORKDIR:-/var/tmp}"
mirror="${IMUDESK_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
security="${IMUDESK_DEBIAN_SECURITY:-http://deb.debian.org/debian-security}"
suite=bookworm
prefix=imudesk-fresh-root.
tarball="$cache/debian12-minbase.tar"

say() { printf '%s\n' "$*"; }
now() { date +%s; }

# ---------------------------------------------------------------------------------------------
# Inside the namespace: this script again, as `--inside ROOTFS WORK`. Runs every step in the root
# and prints one line per step; the first failing step ends it with status 1.
# ---------------------------------------------------------------------------------------------
if [ "${1:-}" = --inside ]; then
  rootfs="$2" work="$3" readme="${4:-}"
  set +e
  step_start=0
  begin() { step_name="$1"; step_start=$(now); say "   .. $step_name"; }
  pass() { say "   ok $step_name ($(( $(now) - step_start )) s)"; }
  failstep() {
    say "   FAIL $step_name: $1"
    [ -n "${2:-}" ] && [ -f "$2" ] && { say "   --- last lines of $(basename "$2"):"; tail -n 25 "$2" | sed 's/^/   | /'; }
    exit 1
  }
  inroot() { # runs a command in the root with a clean environment (and the host's CAs, if it has its own)
    local ca=()
    [ -f "$rootfs/etc/imudesk-host-ca.pem" ] && ca=(NODE_EXTRA_CA_CERTS=/etc/imudesk-host-ca.pem)
    chroot "$rootfs" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      LANG=C.UTF-8 TERM=dumb DEBIAN_FRONTEND=noninteractive "${ca[@]}" "$@"
  }

  begin "mount a private /dev (tmpfs), proc and read-only sysfs in the root"
  mount -t tmpfs -o mode=0755,size=16m,nosuid,noexec tmpfs "$rootfs/dev" || failstep "tmpfs /dev"
  for node in "null c 1 3" "zero c 1 5" "full c 1 7" "random c 1 8" "urandom c 1 9" "tty c 5 0"; do
    set -- $node
    mknod -m 0666 "$rootfs/dev/$1" "$2" "$3" "$4" || failstep "mknod $1"
  done
  mkdir -m 0755 "$rootfs/dev/pts" && mkdir -m 1777 "$rootfs/dev/shm"
  mount -t devpts -o newinstance,ptmxmode=0666,mode=0620 devpts "$rootfs/dev/pts" || failstep "devpts"
  # /dev/shm as on a real machine: its own tmpfs (half the memory), not the 16 MiB of /dev (the
  # export benchmark writes its CSVs there).
  mount -t tmpfs -o mode=1777,size=50%,nosuid,nodev tmpfs "$rootfs/dev/shm" || failstep "tmpfs /dev/shm"
  ln -s pts/ptmx "$rootfs/dev/ptmx"
  ln -s /proc/self/fd "$rootfs/dev/fd"
  ln -s /proc/self/fd/0 "$rootfs/dev/stdin"; ln -s /proc/self/fd/1 "$rootfs/dev/stdout"
  ln -s /proc/self/fd/2 "$rootfs/dev/stderr"
  mount -t proc -o nosuid,nodev,noexec proc "$rootfs/proc" || failstep "proc"
  mount -t sysfs -o ro,nosuid,nodev,noexec sysfs "$rootfs/sys" || failstep "sysfs"
  # Packages do not start services in the root (postgresql's cluster, as in a container image):
  # the tests start the servers they need themselves.
  printf '#!/bin/sh\nexit 101\n' > "$rootfs/usr/sbin/policy-rc.d" && chmod 0755 "$rootfs/usr/sbin/policy-rc.d"
  mkdir -p "$cache/archives/partial"
  mount --bind "$cache/archives" "$rootfs/var/cache/apt/archives" || failstep "package cache"
  cp /etc/resolv.conf "$rootfs/etc/resolv.conf" 2>/dev/null
  # The host's own certificate authorities, as its name servers above: where a proxy inspects TLS,
  # the npm registry's certificate is signed by one of them (Node.js takes them from
  # NODE_EXTRA_CA_CERTS beside its own; Debian's packages come over plain HTTP, signed by Debian).
  if compgen -G "/usr/local/share/ca-certificates/*.crt" > /dev/null; then
    cat /usr/local/share/ca-certificates/*.crt > "$rootfs/etc/imudesk-host-ca.pem"
  fi
  pass

  # The Debian package in /tmp/imudesk-deb of the root: installed with apt-get as a user would (its
  # Depends only: recommends are not part of the check), then imudesk and imudesk-cli run from /usr/bin.
  package_steps() { # when: "into the bare root" or "after the list"
    local deb
    deb="$(cd "$rootfs" && ls tmp/imudesk-deb/imudesk_*.deb 2>/dev/null | head -n 1)"
    begin "install the Debian package $when: apt-get install ./$(basename "$deb")"
    [ -n "$deb" ] || failstep "no package in the root's /tmp/imudesk-deb"
    { inroot apt-get update -q && inroot bash -c "cd /tmp/imudesk-deb && apt-get install -y -q --no-install-recommends ./$(basename "$deb")"; } \
      > "$work/deb-install.log" 2>&1 || failstep "apt-get could not install the package" "$work/deb-install.log"
    [ -x "$rootfs/usr/bin/imudesk" ] && [ -x "$rootfs/usr/bin/imudesk-cli" ] \
      || failstep "the package installed no /usr/bin/imudesk or /usr/bin/imudesk-cli" "$work/deb-install.log"
    say "      $(grep -oE '[0-9]+ newly installed' "$work/deb-install.log" | tail -n 1); Depends: $(inroot dpkg-query -W -f='${Depends}' imudesk | cut -c1-110)..."
    pass

    begin "every shared library of /usr/bin/imudesk and /usr/bin/imudesk-cli is there"
    inroot ldd /usr/bin/imudesk /usr/bin/imudesk-cli > "$work/ldd.log" 2>&1
    if grep -q 'not found' "$work/ldd.log"; then
      grep 'not found' "$work/ldd.log" | sort -u | sed 's/^/   | /'
      failstep "shared libraries missing (the package's Depends lack their Debian packages)"
    fi
    pass

    begin "imudesk --demo --screenshot offscreen"
    inroot env QT_QPA_PLATFORM=offscreen XDG_CONFIG_HOME=/tmp/config timeout 120 \
      imudesk --demo --screenshot /tmp/demo.png --after 2 > "$work/demo.log" 2>&1 \
      || failstep "imudesk did not run (a Qt plugin or runtime package missing from the package's Depends?)" "$work/demo.log"
    magic="$(head -c 8 "$rootfs/tmp/demo.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')"
    [ "$magic" = 89504e470d0a1a0a ] || failstep "no PNG written" "$work/demo.log"
    say "      $(stat -c %s "$rootfs/tmp/demo.png") bytes of PNG"
    pass

    begin "imudesk-cli simulate --pty, then imudesk-cli probe on that pty"
    inroot bash -c '
      imudesk-cli simulate --pty > /tmp/sim.out 2>&1 &
      sim=$!
      pty=""
      for _ in $(seq 100); do
        pty="$(sed -n "s/^pty: *//p" /tmp/sim.out | head -n 1)"
        [ -n "$pty" ] && break
        sleep 0.1
      done
      [ -n "$pty" ] || { echo "the simulator printed no pty"; cat /tmp/sim.out; kill $sim; exit 1; }
      timeout 60 imudesk-cli probe "$pty" --json
      rc=$?
      kill $sim 2>/dev/null; wait $sim 2>/dev/null
      exit $rc' > "$work/probe.log" 2>&1 \
      || failstep "simulate + probe failed" "$work/probe.log"
    grep -q '"identified": *true' "$work/probe.log" || failstep "probe did not identify the simulated module" "$work/probe.log"
    say "      $(grep -oE '"product": *"[^"]*"' "$work/probe.log" | head -n 1), $(grep -oE '"firmware": *"[^"]*"' "$work/probe.log" | head -n 1)"
    pass

    # man-db is the check's own tool (a reader of the page), not a dependency of the package.
    begin "imudesk-cli --help, and man imudesk-cli (man-db installed for the check)"
    inroot imudesk-cli --help > "$work/help.log" 2>&1 || failstep "imudesk-cli --help failed" "$work/help.log"
    grep -q '^usage: imudesk-cli' "$work/help.log" || failstep "imudesk-cli --help printed no usage" "$work/help.log"
    inroot apt-get install -y -q --no-install-recommends man-db > "$work/man-db.log" 2>&1 \
      || failstep "apt-get could not install man-db" "$work/man-db.log"
    inroot env MANWIDTH=80 man imudesk-cli > "$work/man.log" 2>&1 || failstep "man imudesk-cli failed" "$work/man.log"
    grep -q 'talk to IMU and AHRS modules from scripts' "$work/man.log" || failstep "man imudesk-cli showed no NAME section" "$work/man.log"
    inroot env MANWIDTH=80 man imudesk > "$work/man-gui.log" 2>&1 || failstep "man imudesk failed" "$work/man-gui.log"
    say "      --help: $(wc -l < "$work/help.log") lines; man imudesk-cli: $(wc -l < "$work/man.log") lines, man imudesk: $(wc -l < "$work/man-gui.log") lines"
    pass
  }

  if [ -n "$readme" ]; then
    begin "the README's command as root: scripts/setup.sh $readme (log: $work/readme-$readme.log)"
    inroot env IMUDESK_IN_FRESH_ROOT=1 bash -c "cd /src && ./scripts/setup.sh $readme" < /dev/null \
      > "$work/readme-$readme.log" 2>&1
    rc=$?
    cp "$work/readme-$readme.log" "$cache/readme-$readme.log"
    say "      exit status $rc; the whole output is kept in $cache/readme-$readme.log"
    tail -n 15 "$work/readme-$readme.log" | sed 's/^/   | /'
    if [ "$readme" = demo ] && [ "$rc" -eq 1 ] && grep -q '^No display found' "$work/readme-$readme.log"; then
      say "      the demo command built the app and reached the window step; the root has no display, and it says so"
      pass
      exit 0
    fi
    [ "$rc" -eq 0 ] && pass || failstep "scripts/setup.sh $readme ended with $rc"
    exit 0
  fi

  if [ -f "$work/host-package" ]; then
    when="into the bare root" package_steps
  fi

  begin "install the packages: scripts/setup.sh install (as the README's commands do)"
  say "      (marker: package install running)"
  inroot /src/scripts/setup.sh install > "$work/install.log" 2>&1 \
    || failstep "setup.sh install failed (apt could not install the list: see its output)" "$work/install.log"
  inroot apt-get autoclean -q > /dev/null 2>&1 # keep only current .debs in the cache
  pass

  # The results tests (tests/common/pg_server.h) start a PostgreSQL server of their own as the
  # unprivileged user nobody: the same here, with the list's packages only, and psql reaches it.
  begin "a PostgreSQL server from the list starts as nobody (initdb, pg_ctl) and answers psql"
  inroot bash -c '
    set -e
    bin="$(ls -d /usr/lib/postgresql/*/bin | sort -V | tail -n 1)"
    dir="$(mktemp -d /tmp/pg-XXXXXX)"; mkdir "$dir/sock"; chown -R 65534:65534 "$dir"
    cd "$dir"
    as_nobody() { setpriv --reuid=65534 --regid=65534 --clear-groups -- "$@"; }
    as_nobody "$bin/initdb" -D "$dir/data" -U imudesk_admin --auth=trust -E UTF8 --no-locale --no-sync > /dev/null
    as_nobody "$bin/pg_ctl" -D "$dir/data" -o "-k $dir/sock -p 25438 -c listen_addresses=" -l "$dir/log" -w start > /dev/null
    psql -X -A -t -h "$dir/sock" -p 25438 -U imudesk_admin -d postgres -c "SELECT version()"
    rc=0
    ls /usr/lib/x86_64-linux-gnu/qt6/plugins/sqldrivers/libqsqlpsql.so > /dev/null || rc=1
    as_nobody "$bin/pg_ctl" -D "$dir/data" -m fast -w stop > /dev/null
    cd /; rm -rf "$dir"
    exit $rc' > "$work/postgresql.log" 2>&1 \
    || failstep "the PostgreSQL server or the QPSQL driver of Qt is missing or does not start" "$work/postgresql.log"
  say "      $(head -n 1 "$work/postgresql.log" | cut -c1-60)"
  pass

  begin "the tests' tools from npm: the official MCAP reader loads on Debian's Node.js"
  # setup.sh install ran `npm ci --prefix tests/mcap`; the reader answers a missing file with its
  # JSON error, which it can only do once every module it imports has loaded.
  inroot node /src/tests/mcap/read_mcap.mjs /nonexistent.mcap > "$work/mcap-reader.log" 2>&1
  grep -q '"error"' "$work/mcap-reader.log" || failstep "node could not run tests/mcap/read_mcap.mjs" "$work/mcap-reader.log"
  pass

  begin "configure the project with tests and benchmarks (cmake -G Ninja, Release)"
  if ! inroot cmake -S /src -B /build -G Ninja -DCMAKE_BUILD_TYPE=Release \
       -DIMUDESK_BUILD_TESTS=ON -DIMUDESK_BUILD_BENCH=ON > "$work/configure.log" 2>&1; then
    say "   FAIL $step_name"
    # The fatal lines (CMake's "-- Could NOT find" status lines are optional packages).
    grep -vE '^-- ' "$work/configure.log" \
      | grep -E 'CMake Error|could not be found|Could not find|Could NOT find|Failed to find' \
      | sed 's/^ */   | /' | head -n 12
    # Name the Debian package behind each CMake package it could not find.
    mapfile -t names < <(grep -vE '^-- ' "$work/configure.log" \
                         | grep -oE 'because dependency [A-Za-z0-9_]+|provided by "[A-Za-z0-9_]+"|Failed to find required Qt component "[A-Za-z0-9_]+"' \
                         | sed -E 's/^because dependency //; s/.*"([A-Za-z0-9_]+)"$/\1/' \
                         | sed -E '/^(Qt6|Eigen)/!s/^/Qt6/' | sort -u)
    list="$rootfs/src/scripts/debian-packages.txt"
    for name in "${names[@]}"; do
      candidates=()
      case "$name" in
        Qt6*) low="$(tr '[:upper:]' '[:lower:]' <<< "${name#Qt6}")"; candidates=("qt6-${low}-dev" "libqt6${low}6-dev") ;;
        Eigen3) candidates=(libeigen3-dev) ;;
      esac
      pkg="" listed=""
      for c in "${candidates[@]}"; do
        if grep -Ev '^\s*(#|$)' "$list" | tr -d ' \t' | grep -qx "$c"; then listed="$c"; break; fi
      done
      if [ -n "$listed" ]; then
        say "   missing: CMake package $name; its Debian package $listed is in the list, so one of its own dependencies named here is not"
        continue
      fi
      for c in "${candidates[@]}"; do
        if inroot apt-cache show "$c" > /dev/null 2>&1; then pkg="$c"; break; fi
      done
      if [ -n "$pkg" ]; then
        say "   missing: CMake package $name -> add the Debian package $pkg to scripts/debian-packages.txt"
      else
        say "   missing: CMake package $name (no Debian package of that name; apt-file search ${name}Config.cmake tells)"
      fi
    done
    exit 1
  fi
  pass

  begin "toolchains of the test command: g++ with ASan+UBSan and with TSan, clang++ with libFuzzer"
  cat > "$rootfs/tmp/probe.cpp" <<'EOF'
#include <cstddef>
#include <cstdint>
#include <vector>
#ifdef FUZZ
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* d, size_t n) { std::vector<uint8_t> v(d, d + n); return v.empty() ? 0 : 0; }
#else
int main() { std::vector<int> v(4, 1); return v[3] - 1; }
#endif
EOF
  inroot g++ -std=c++20 -fsanitize=address,undefined /tmp/probe.cpp -o /tmp/probe-asan > "$work/tools.log" 2>&1 \
    && inroot /tmp/probe-asan >> "$work/tools.log" 2>&1 \
    || failstep "g++ -fsanitize=address,undefined does not build or run (libasan, libubsan)" "$work/tools.log"
  inroot g++ -std=c++20 -fsanitize=thread /tmp/probe.cpp -o /tmp/probe-tsan >> "$work/tools.log" 2>&1 \
    && inroot /tmp/probe-tsan >> "$work/tools.log" 2>&1 \
    || failstep "g++ -fsanitize=thread does not build or run (libtsan2, with gcc)" "$work/tools.log"
  inroot clang++ -DFUZZ -fsanitize=fuzzer,address,undefined /tmp/probe.cpp -o /tmp/probe-fuzz >> "$work/tools.log" 2>&1 \
    && inroot /tmp/probe-fuzz -runs=50 >> "$work/tools.log" 2>&1 \
    || failstep "clang++ -fsanitize=fuzzer does not build or run (clang, libclang-rt-14-dev)" "$work/tools.log"
  pass

  if [ ! -f "$work/host-package" ]; then
    begin "build imudesk and imudesk-cli in the root and package them (no host build was given)"
    { inroot cmake --build /build -j "$(nproc)" --target imudesk imudesk-cli \
        && inroot cpack -G DEB --config /build/CPackConfig.cmake -B /build/package \
        && mkdir -p "$rootfs/tmp/imudesk-deb" && cp "$rootfs"/build/package/imudesk_*.deb "$rootfs/tmp/imudesk-deb/"; } \
      > "$work/build.log" 2>&1 || failstep "build or cpack in the root failed" "$work/build.log"
    pass
    when="after the list" package_steps
  fi
  exit 0
fi

# ---------------------------------------------------------------------------------------------
# Outside: cache the base, make the root, run the steps in a private namespace, remove the root.
# ---------------------------------------------------------------------------------------------
mounts_below() { # prints the host's mount points below $1 (none expected: the mounts are private)
  awk -v p="$1/" 'substr($5, 1, length(p)) == p { print $5 }' /proc/self/mountinfo
}

remove_root() { # removes a root once nothing is mounted below it
  local dir="$1"
  if [ -n "$(mounts_below "$dir")" ]; then
    say "!! not removing $dir: the host sees mounts below it:" >&2
    mounts_below "$dir" >&2
    return 1
  fi
  rm -rf --one-file-system "$dir"
}

clean_stale() { # roots of runs that were killed: their owner process is gone
  local dir pid
  for dir in "$workbase/$prefix"*; do
    [ -d "$dir" ] || continue
    pid="$(cat "$dir/owner.pid" 2>/dev/null || true)"
    if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then continue; fi
    say "   removing the root of a run that did not finish: $dir"
    remove_root "$dir" || true
  done
}

if [ "$(id -u)" -ne 0 ]; then
  say "check-fresh-debian: needs root (mmdebstrap --mode=root, mount namespaces); run it as root or with sudo" >&2
  exit 1
fi

build="$src/build/test"
readme=""
case "${1:-}" in
  --clean) clean_stale; exit 0 ;;
  --build) build="$2" ;;
  --readme) readme="$2"; build=/nonexistent
            case "$readme" in demo|test) ;; *) say "usage: $0 --readme demo|test" >&2; exit 2 ;; esac ;;
  "") ;;
  *) say "usage: $0 [--build DIR] | --clean" >&2; exit 2 ;;
esac

t0=$(now)
say "== fresh Debian 12 root check"
clean_stale
if ! command -v mmdebstrap > /dev/null; then
  say "   installing mmdebstrap (Debian package) for this check"
  apt-get update -q > /dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends mmdebstrap > /dev/null
fi

mkdir -p "$cache/archives/partial"
if [ ! -s "$tarball" ] || [ -n "$(find "$tarball" -mtime +7 2>/dev/null)" ]; then
  s=$(now)
  say "   .. base: mmdebstrap --variant=minbase $suite (cached in $cache, renewed weekly)"
  mmdebstrap --quiet --variant=minbase --mode=root --format=tar "$suite" "$tarball.part" \
    "deb $mirror $suite main" "deb $mirror $suite-updates main" "deb $security $suite-security main" \
    > "$cache/mmdebstrap.log" 2>&1 </dev/null \
    || { tail -n 20 "$cache/mmdebstrap.log"; say "VERDICT: FAIL (mmdebstrap could not make the base root; is the mirror reachable?)"; exit 1; }
  mv "$tarball.part" "$tarball"
  say "   ok base ($(( $(now) - s )) s)"
else
  say "   ok base: cached $tarball"
fi

mkdir -p "$workbase"
work="$(mktemp -d "$workbase/${prefix}XXXXXX")"
echo $$ > "$work/owner.pid"
rootfs="$work/root"
mkdir "$rootfs"
say "   root: $rootfs"
ns_pid=""
finish() {
  local rc=$?
  set +e
  if [ -n "$ns_pid" ] && kill -0 "$ns_pid" 2>/dev/null; then kill -KILL "$ns_pid" 2>/dev/null; fi
  [ -n "$ns_pid" ] && wait "$ns_pid" 2>/dev/null
  # The namespace's processes die with it; wait until none has its root inside ours any more.
  local p r
  for _ in $(seq 40); do
    r=""
    for p in /proc/[0-9]*; do
      case "$(readlink "$p/root" 2>/dev/null)" in "$rootfs"|"$rootfs"/*) r=1; break ;; esac
    done
    [ -z "$r" ] && break
    sleep 0.25
  done
  mkdir -p "$cache/last-run" && rm -f "$cache/last-run/"*.log && cp "$work"/*.log "$cache/last-run/" 2>/dev/null
  remove_root "$work" || say "!! left $work in place (see above)" >&2
  exit "$rc"
}
trap finish EXIT
trap 'exit 130' INT HUP
trap 'exit 143' TERM

s=$(now)
tar -xpf "$tarball" --numeric-owner -C "$rootfs"
# The sources as the repository has them (tracked and new files, no build trees).
if git -C "$src" rev-parse --git-dir > /dev/null 2>&1; then
  mkdir "$rootfs/src"
  git -C "$src" ls-files -z --cached --others --exclude-standard \
    | tar -C "$src" --null --no-recursion --ignore-failed-read -T - -cf - 2>/dev/null | tar -xf - -C "$rootfs/src"
else
  mkdir "$rootfs/src"
  tar -C "$src" --exclude='./build*' --exclude=./.git -cf - . | tar -xf - -C "$rootfs/src"
fi
# dpkg in the root without its fsync after every file it unpacks (force-unsafe-io): the root is
# thrown away at the end, so what a power cut would do to it does not matter, and its package
# installs wait on the disk for most of their time otherwise. What gets installed is the same.
mkdir -p "$rootfs/etc/dpkg/dpkg.cfg.d"
echo force-unsafe-io > "$rootfs/etc/dpkg/dpkg.cfg.d/imudesk-check-unsafe-io"
if [ -n "${IMUDESK_FRESH_PACKAGE_LIST:-}" ]; then
  cp "$IMUDESK_FRESH_PACKAGE_LIST" "$rootfs/src/scripts/debian-packages.txt"
  say "   (package list replaced by $IMUDESK_FRESH_PACKAGE_LIST)"
fi
if [ -n "$readme" ]; then
  say "   ok root unpacked with the sources ($(( $(now) - s )) s)"
elif deb="$(ls "$build/package/"imudesk_*.deb 2>/dev/null | head -n 1)" && [ -n "$deb" ]; then
  mkdir "$rootfs/tmp/imudesk-deb" && cp "$deb" "$rootfs/tmp/imudesk-deb/" && touch "$work/host-package"
  say "   ok root unpacked with the sources and the package $deb ($(( $(now) - s )) s)"
elif [ -x "$build/app/gui/imudesk" ] && [ -x "$build/app/cli/imudesk-cli" ]; then
  # A built tree without its package (scripts/setup.sh makes it; cpack here otherwise, into the
  # root's work folder, so the build tree gets no files of root's).
  cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/package" > "$work/cpack.log" 2>&1 \
    || { tail -n 20 "$work/cpack.log"; say "VERDICT: FAIL (cpack could not package $build)"; exit 1; }
  mkdir "$rootfs/tmp/imudesk-deb" && cp "$work/package/"imudesk_*.deb "$rootfs/tmp/imudesk-deb/" && touch "$work/host-package"
  say "   ok root unpacked with the sources; $build packaged with cpack ($(( $(now) - s )) s)"
else
  say "   ok root unpacked with the sources ($(( $(now) - s )) s); no built binaries in $build: building them in the root"
fi

export cache
unshare --mount --pid --fork --kill-child --propagation private -- \
  bash "$here/check-fresh-debian.sh" --inside "$rootfs" "$work" "$readme" &
ns_pid=$!
rc=0
wait "$ns_pid" || rc=$?
ns_pid=""
if [ "$rc" -eq 0 ]; then
  say "VERDICT: PASS: a fresh Debian 12 root with scripts/debian-packages.txt alone configures; the .deb installs there and imudesk and imudesk-cli run from /usr/bin ($(( $(now) - t0 )) s)"
else
  say "VERDICT: FAIL: the fresh Debian 12 root check failed at the step above ($(( $(now) - t0 )) s; logs in $cache/last-run)"
  say "         a package the host has by hand is missing from scripts/debian-packages.txt or from the .deb's Depends, or a step broke"
fi
exit "$rc"
