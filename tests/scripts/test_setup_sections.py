#!/usr/bin/python3
"""scripts/setup.sh and the two sections of scripts/packages.txt: --build-only checks only [build]
(so scripts/build.sh never installs what only the tests run), the counts it reports match the
list parsed here, and a malformed list or argument stops with the line or argument named.

Each case runs a copy of setup.sh and common.sh in a scratch repository whose packages.txt the
case writes, so no case installs anything: every package it lists is installed (bash, coreutils)
or sits in a section the case does not ask for."""

import pathlib
import shutil
import subprocess
import sys
import tempfile

scripts = pathlib.Path(sys.argv[1])


def run(package_list, *args):
    with tempfile.TemporaryDirectory() as root:
        (pathlib.Path(root) / "scripts").mkdir()
        for name in ("setup.sh", "common.sh"):
            shutil.copy(scripts / name, pathlib.Path(root) / "scripts" / name)
        (pathlib.Path(root) / "scripts" / "packages.txt").write_text(package_list)
        return subprocess.run(["bash", f"{root}/scripts/setup.sh", *args], capture_output=True,
                              text=True)


def sections(text):
    """The packages of each section, parsed independently of setup.sh."""
    found, current = {}, None
    for line in text.splitlines():
        entry = line.split("#", 1)[0].strip()
        if entry in ("[build]", "[run]"):
            current = entry[1:-1]
        elif entry:
            found.setdefault(current, []).append(entry)
    return found


# The repository's own list on this machine, where the suite runs after setup.sh installed it.
real = sections((scripts / "packages.txt").read_text())
assert None not in real, f"packages before any section: {real.get(None)}"
assert set(real) == {"build", "run"}, set(real)
for package in ("build-essential", "cmake", "clang-14", "libgrpc++-dev", "protobuf-compiler"):
    assert package in real["build"], f"{package} must be in [build]: the builds use it"
for package in ("python3", "openfoam", "chromium", "nodejs", "redis-server", "gnuplot-nox"):
    assert package in real["run"], f"{package} belongs in [run]: only tests and tools run it"
build_only = subprocess.run(["bash", str(scripts / "setup.sh"), "--build-only"],
                            capture_output=True, text=True)
assert build_only.returncode == 0, build_only.stderr
assert f"all {len(real['build'])} packages of scripts/packages.txt (build) are installed" in \
    build_only.stdout, build_only.stdout
everything = subprocess.run(["bash", str(scripts / "setup.sh")], capture_output=True, text=True)
assert everything.returncode == 0, everything.stderr
total = len(real["build"]) + len(real["run"])
assert f"all {total} packages of scripts/packages.txt (build run) are installed" in \
    everything.stdout, everything.stdout

# --build-only leaves [run] alone: its package does not exist, and nothing tries to install it.
skipped = run("[build]\nbash  # a comment\ncoreutils\n\n[run]\ngetme-no-such-package\n",
              "--build-only")
assert skipped.returncode == 0, skipped.stderr
assert "all 2 packages of scripts/packages.txt (build) are installed" in skipped.stdout, \
    skipped.stdout

# Malformed lists and arguments stop before apt, naming the line or the argument.
before = run("bash\n[build]\ncoreutils\n", "--build-only")
assert before.returncode == 1
assert "packages.txt:1: 'bash' comes before any [build] or [run] section" in before.stderr, \
    before.stderr
unknown = run("[build]\nbash\n\n[docs]\ncoreutils\n", "--build-only")
assert unknown.returncode == 1
assert "packages.txt:4: unknown section '[docs]' (expected [build] or [run])" in unknown.stderr, \
    unknown.stderr
empty = run("[run]\nbash\n", "--build-only")
assert empty.returncode == 1
assert "lists no packages for: build" in empty.stderr, empty.stderr
argument = run("[build]\nbash\n", "--tests-only")
assert argument.returncode == 1
assert "unknown argument '--tests-only'" in argument.stderr, argument.stderr
print("setup.sh sections: all cases passed")
