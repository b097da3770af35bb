#!/usr/bin/env bash
# Installs every Debian bookworm package the build, the tests and the demo use (scripts/packages.txt).
# Idempotent: when all of them are installed already it only checks, so re-runs take a second.
# Needs root (or sudo) only when something is missing. Works on a minimal debootstrap of bookworm.
#   scripts/setup.sh                every package
#   scripts/setup.sh --build-only   the [build] section only: what configuring and compiling need
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

sections="build run"
case "${1:-}" in
  "") ;;
  --build-only) sections="build" ;;
  *) die "unknown argument '$1' (usage: scripts/setup.sh [--build-only])" ;;
esac

package_list="$GETME_ROOT/scripts/packages.txt"
packages=()
section=""
line_number=0
while IFS= read -r line || [ -n "$line" ]; do
  line_number=$((line_number + 1))
  entry="${line%%#*}"
  entry="${entry//[[:space:]]/}"
  case "$entry" in
    "") ;;
    "[build]" | "[run]") section="${entry:1:-1}" ;;
    "["*) die "$package_list:$line_number: unknown section '$entry' (expected [build] or [run])" ;;
    *)
      [ -n "$section" ] || die "$package_list:$line_number: '$entry' comes before any [build] or [run] section"
      [[ " $sections " != *" $section "* ]] || packages+=("$entry")
      ;;
  esac
done < "$package_list"
[ "${#packages[@]}" -gt 0 ] || die "$package_list lists no packages for: $sections"

command -v dpkg-query > /dev/null || die "dpkg-query not found: this script supports Debian bookworm only"

missing=()
for package in "${packages[@]}"; do
  status="$(dpkg-query -W -f='${db:Status-Status}' "$package" 2> /dev/null || true)"
  [ "$status" = installed ] || missing+=("$package")
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages of scripts/packages.txt ($sections) are installed"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo > /dev/null ||
    die "not root and no sudo; run as root to install: ${missing[*]}"
  as_root=(sudo)
fi

if [ -r /etc/os-release ]; then
  codename="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"
  [ "$codename" = bookworm ] ||
    echo "setup: warning: this is '${codename:-unknown}', the package list is for Debian bookworm" >&2
fi

log "Installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
echo "setup: installed ${missing[*]}"
