#!/usr/bin/env python3
"""Windows compile check (issue 54): core, ui and the two applications compiled for Windows with
Debian's mingw-w64 cross compiler against Qt's headers, syntax only.

  scripts/check_windows.py BUILD_DIR            every translation unit of BUILD_DIR's core, ui
                                                and app targets (its compile_commands.json)
  scripts/check_windows.py BUILD_DIR --probe F  one source F, with the flags of core's engine floor

What is checked: that every line parses and type-checks as C++20 for x86_64 Windows (mingw-w64's
headers, Qt's public headers, Eigen), with <windows.h> included first in every unit, so that a name
Windows defines as a macro (ERROR, DELETE, min, max, near, ...) or a POSIX-only header or call
outside its platform file fails. The units are the build's own: its unity batches, the files
compiled alone and the moc outputs. What is not checked: nothing links or runs (Qt for Windows
cannot be installed here), so a missing Windows implementation of a function is not found, and
Qt's headers are Linux's build of them (the same API; Windows-only Qt classes are not there).
Left out by design: the POSIX platform files (<name>_posix.cpp; their <name>_windows.cpp is
compiled instead) and the simulators' pseudo-terminals (core/sim/pty_*.cpp, Unix-only).
Exit 0: every unit compiled; 1: a unit failed (its first errors are printed); 2: usage or set-up.

A unit that compiled is remembered, as ccache remembers an object, in
${XDG_CACHE_HOME:-~/.cache}/imudesk/windows-check (IMUDESK_WINDOWS_CHECK_CACHE names another folder;
"off" turns it off): a run compiles again only the units whose key changed. The key holds the
cross compiler's version, the Debian packages of the headers it reads (Qt, mingw-w64, Eigen), this
script, the unit's Windows command, the text of the unit and of every header the Linux build of the
same unit read (ninja's dependency log), all with the checkout's and the build's paths named instead
of spelt (a generated file may name them: a clone in another folder then finds what an earlier one
left), and the text of every
*_windows.* file of core, ui and app (a header only Windows includes is not in that log). A unit
without a valid entry in the log (the Windows twins of platform files) is always compiled; a unit
that failed is never remembered.
"""
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

COMPILER = "x86_64-w64-mingw32-g++-posix"
# <windows.h> as every unit sees it first; precompiled once per run (it is a third of a second
# of every unit otherwise).
WINDOWS_DEFINES = ["-DNOMINMAX", "-DWIN32_LEAN_AND_MEAN", "-DUNICODE", "-D_UNICODE"]
BASE_FLAGS = ["-std=c++20", "-w"]
UNIX_ONLY = re.compile(r"(_posix\.cpp|/core/sim/pty_[a-z_]+\.cpp)$")
# Headers the build finds in /usr/include, which cannot be on a cross compiler's path (glibc's
# headers are there too): copied into a folder of their own.
USR_INCLUDE_HEADERS = ["zstd.h", "zstd_errors.h", "zdict.h", "matio.h", "matio_pubconf.h"]


def fail_setup(message):
    print(f"check-windows: {message}", file=sys.stderr)
    sys.exit(2)


def output_of(args):
    return args[args.index("-o") + 1] if "-o" in args else ""


def windows_args(args, extra_include):
    """The Linux compile command made a Windows syntax check: its defines and include folders."""
    out = [COMPILER, "-fsyntax-only"] + BASE_FLAGS + WINDOWS_DEFINES + [
        "-include", os.path.join(extra_include, "imudesk_windows.h"), "-isystem", extra_include]
    i = 1
    while i < len(args):
        a = args[i]
        if a in ("-o", "-MT", "-MF", "-c"):
            i += 2 if a != "-c" else 1
            continue
        if a in ("-I", "-isystem", "-D", "-U", "-include"):
            value = args[i + 1]
            if a == "-isystem" and value.endswith("/mkspecs/linux-g++"):
                value = value[: -len("linux-g++")] + "win32-g++"
            if a == "-include" and value.endswith((".h", ".hxx")) and "cmake_pch" in value:
                i += 2
                continue
            out += [a, value]
            i += 2
            continue
        if a.startswith(("-I", "-D", "-U")):
            out.append(a)
        # -O, -g, -W, -f, -std and the rest: Linux's code generation, not needed for a syntax check
        i += 1
    return out


def units(build):
    path = os.path.join(build, "compile_commands.json")
    if not os.path.exists(path):
        fail_setup(f"{path} not found: configure BUILD_DIR with CMake first (it exports compile commands)")
    entries = json.load(open(path))
    chosen, by_file = [], {}
    for e in entries:
        args = shlex.split(e["command"])
        out = output_of(args)
        if not out.startswith(("core/", "ui/", "app/")) or "/.rcc/" in e["file"]:
            continue  # tests, benchmarks, the floors' probes; the resources' data
        by_file[os.path.realpath(e["file"])] = args
        if UNIX_ONLY.search(e["file"]):
            continue
        chosen.append((e["file"], args))
    # The Windows side of each platform file, with the flags of its POSIX twin.
    for posix, args in list(by_file.items()):
        if posix.endswith("_posix.cpp"):
            win = posix[: -len("_posix.cpp")] + "_windows.cpp"
            if not os.path.exists(win):
                fail_setup(f"{posix} has no Windows twin {win}")
            chosen.append((win, args))
    return chosen


def engine_flags(build):
    for f, args in units(build):
        if "imudesk_core_engine" in output_of(args) or "imudesk_core_engine" in f:
            return args
    fail_setup("no unit of core's engine floor in the build")


def windows_command(item, extra_include):
    source, args = item
    cmd = windows_args(args, extra_include)
    if source not in cmd:
        cmd.append(source)
    return cmd


def compile_one(item, extra_include, keys=None):
    """(source, exit code, stderr, seconds, remembered): remembered when the cache (keys) had it."""
    source, args = item
    cmd = windows_command(item, extra_include)
    marker = keys.marker(source, args, cmd) if keys else None
    if marker and os.path.exists(marker):
        return source, 0, "", 0.0, True
    t = time.monotonic()
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode == 0 and marker:
        os.makedirs(os.path.dirname(marker), exist_ok=True)
        with open(marker, "w") as f:
            f.write(os.path.relpath(source, keys.root) + "\n")
    return source, r.returncode, r.stderr, time.monotonic() - t, False


def cache_folder():
    chosen = os.environ.get("IMUDESK_WINDOWS_CHECK_CACHE", "")
    if chosen == "off":
        return None
    if chosen:
        return chosen
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "imudesk", "windows-check")


def source_folder(build):
    """The checkout a build folder was configured from (its CMakeCache.txt), or None."""
    try:
        for line in open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8", errors="replace"):
            if line.startswith("CMAKE_HOME_DIRECTORY:"):
                return os.path.realpath(line.split("=", 1)[1].strip())
    except OSError:
        pass
    return None


def ninja_deps(build):
    """Object (as the build names it) -> the files its Linux compile read; only entries ninja marks VALID."""
    r = subprocess.run(["ninja", "-C", build, "-t", "deps"], capture_output=True, text=True)
    deps, current = {}, None
    if r.returncode != 0:
        return deps
    for line in r.stdout.splitlines():
        if not line.strip():
            current = None
        elif not line[0].isspace():
            obj, _, status = line.partition(": ")
            current = [] if status.rstrip().endswith("(VALID)") else None
            if current is not None:
                deps[obj] = current
        elif current is not None:
            current.append(line.strip())
    return deps


class UnitKeys:
    """The cache key of a unit (the module docstring says what it holds)."""

    def __init__(self, build, extra_include, folder):
        self.folder = folder
        self.build = os.path.realpath(build)
        self.root = source_folder(self.build) or os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
        self.extra = extra_include
        # The checkout's and the build's paths, longest first, as they stand in commands and in
        # generated files (a unity batch of a build outside the checkout names the checkout).
        self.prefixes = sorted(((self.build, "@BUILD@"), (self.root, "@ROOT@"), (self.extra, "@EXTRA@")),
                               key=lambda p: -len(p[0]))
        self.deps = ninja_deps(build)
        self.texts = {}
        common = hashlib.sha256()
        for args in ([COMPILER, "--version"],
                     ["dpkg-query", "-W", "qt6-base-dev", "mingw-w64-x86-64-dev", "libeigen3-dev",
                      "g++-mingw-w64-x86-64-posix"]):
            try:
                common.update(subprocess.run(args, capture_output=True).stdout)
            except OSError:
                pass
        common.update(open(os.path.realpath(__file__), "rb").read())
        for folder in ("core", "ui", "app"):
            for base, _, files in sorted(os.walk(os.path.join(self.root, folder))):
                for name in sorted(files):
                    if "_windows." in name:
                        path = os.path.join(base, name)
                        common.update(self.relative(path).encode() + b"\0" + self.text_hash(path))
        self.common = common.digest()

    def relative(self, text):
        """The text with the checkout's, the build's and the temporary folder's paths named, not spelt."""
        for prefix, name in self.prefixes:
            text = text.replace(prefix, name)
        return text

    def text_hash(self, path):
        path = os.path.normpath(path if os.path.isabs(path) else os.path.join(self.build, path))
        if path not in self.texts:
            try:
                data = open(path, "rb").read()
                for prefix, name in self.prefixes:
                    data = data.replace(prefix.encode(), name.encode())
                self.texts[path] = hashlib.sha256(data).digest()
            except OSError:
                self.texts[path] = b"missing"
        return self.texts[path]

    def marker(self, source, linux_args, cmd):
        """The file that says the unit compiled, or None for a unit that is always compiled."""
        key = self.key(source, linux_args, cmd)
        return os.path.join(self.folder, key[:2], key) if key else None

    def key(self, source, linux_args, cmd):
        read = self.deps.get(output_of(linux_args))
        if read is None or source.endswith("_windows.cpp"):
            return None  # nothing says what it reads: compile it
        h = hashlib.sha256(self.common)
        for a in cmd:
            h.update(self.relative(a).encode() + b"\0")
        for path in [source] + read:
            full = os.path.normpath(path if os.path.isabs(path) else os.path.join(self.build, path))
            h.update(self.relative(full).encode() + b"\0" + self.text_hash(full))
        return h.hexdigest()


def main():
    if len(sys.argv) not in (2, 4) or (len(sys.argv) == 4 and sys.argv[2] != "--probe"):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    if not shutil.which(COMPILER):
        fail_setup(f"{COMPILER} not found: install Debian's g++-mingw-w64-x86-64-posix (scripts/debian-packages.txt)")
    build = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="imudesk-windows-") as extra:
        for h in USR_INCLUDE_HEADERS:
            if os.path.exists(f"/usr/include/{h}"):
                shutil.copy(f"/usr/include/{h}", extra)
        header = os.path.join(extra, "imudesk_windows.h")
        with open(header, "w") as f:
            f.write("#pragma once\n#include <windows.h>\n")
        pch = subprocess.run([COMPILER, "-x", "c++-header"] + BASE_FLAGS + WINDOWS_DEFINES + [header, "-o", header + ".gch"],
                             capture_output=True, text=True)
        if pch.returncode != 0:
            fail_setup(f"cannot precompile <windows.h>:\n{pch.stderr}")
        if len(sys.argv) == 4:
            probe = os.path.abspath(sys.argv[3])
            args = engine_flags(build)
            source, rc, err, _, _ = compile_one((probe, args), extra)
            sys.stderr.write(err)
            print(f"check-windows: {os.path.basename(probe)} {'compiles' if rc == 0 else 'does not compile'} for Windows")
            sys.exit(0 if rc == 0 else 1)
        todo = units(build)
        jobs = int(os.environ.get("CHECK_JOBS", os.cpu_count() or 2))
        start = time.monotonic()
        cache = cache_folder()
        keys = UnitKeys(build, extra, cache) if cache else None
        failed, remembered = [], 0
        with ThreadPoolExecutor(max_workers=jobs) as pool:
            for source, rc, err, secs, hit in pool.map(lambda u: compile_one(u, extra, keys), todo):
                remembered += hit
                if rc != 0:
                    failed.append((source, err))
        where = f"; {remembered} of them unchanged since a run that compiled them ({cache})" if cache else ""
        print(f"check-windows: {len(todo) - len(failed)} of {len(todo)} units of core, ui and app compile for "
              f"Windows (mingw-w64, syntax only) in {time.monotonic() - start:.0f} s{where}")
        for source, err in failed:
            lines = [l for l in err.splitlines() if "error" in l][:8]
            print(f"!! {source}:\n   " + "\n   ".join(lines), file=sys.stderr)
        sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
