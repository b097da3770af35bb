#!/usr/bin/env bash
# Link launcher of the `getme` CLI (client/CMakeLists.txt, RULE_LAUNCH_LINK): runs the link command
# it is given with every Abseil shared library replaced by Debian's static archive of it.
#
# Why: a `getme smooth` run is a whole process, and the issue-14 comparison with Mesquite times it
# end to end. Loading and relocating Abseil's 33 shared libraries was 1.7 ms of every start, and
# calls through their PLT cost more on top: on tire.vtk the whole run fell from 44.5 to 38.8 ms
# (docs/design.md, "Why the CLI links Abseil statically"). Abseil's CMake package only describes
# the shared libraries, and the CLI's libraries (getme_core …) are shared with
# getme-server, which must keep the shared ones: gRPC's own libraries link them, and two copies of
# Abseil in one process would each keep their own global state. So the swap is made here, for this
# one executable, and refused for anything that links gRPC.
set -euo pipefail
command=()
archives=()
for argument in "$@"; do
  if [[ $argument == *libgrpc* ]]; then
    echo "link_abseil_statically.sh: $argument: a target that links gRPC must use the shared" \
      "Abseil gRPC itself links" >&2
    exit 1
  fi
  if [[ $argument =~ ^(.*/libabsl_[A-Za-z0-9_]+)\.so(\.[0-9.]+)?$ && -f ${BASH_REMATCH[1]}.a ]]; then
    archives+=("${BASH_REMATCH[1]}.a")
  else
    command+=("$argument")
  fi
done
# The archives depend on each other in no single order: a group resolves them all. Last on the
# line, after every library that uses them.
if ((${#archives[@]} > 0)); then
  command+=(-Wl,--start-group "${archives[@]}" -Wl,--end-group)
fi
exec "${command[@]}"
