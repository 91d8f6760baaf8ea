#!/bin/sh
# Installs the Debian packages named on the command line that are missing.
# Quiet and quick when everything is present; uses sudo when not root.
missing=""
for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" ||
        missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "aero: installing Debian packages:$missing"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null &&
    $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null ||
    { echo "aero: apt-get could not install:$missing" >&2; exit 1; }
