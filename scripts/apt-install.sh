#!/usr/bin/env bash
# Installs the Debian packages named on the command line that are missing, with
# --no-install-recommends (paraview recommends python3-paraview, which would remove
# libvtk9-dev), and refuses if apt would remove anything. Root, or sudo when available.
# All output goes to stderr. The one way every flowsurf script installs packages.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then SUDO="sudo"; fi
missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "flowsurf: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get -o DPkg::Lock::Timeout=900 update -qq >&2
sim="$($SUDO apt-get install -s --no-install-recommends "${missing[@]}")"
if grep -q '^Remv ' <<<"$sim"; then
  echo "flowsurf: installing ${missing[*]} would remove packages; refusing:" >&2
  grep '^Remv ' <<<"$sim" >&2
  exit 1
fi
$SUDO apt-get -o DPkg::Lock::Timeout=900 install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
