#!/bin/sh
# aero: the outside source archives the builds unpack (FFTW, libsndfile,
# Pd, libpd), found or fetched, and always checked:
#   sh platforms/vendor.sh ARCHIVE      prints the path of a verified ARCHIVE
# It looks in $VENDOR (default ../shared/vendor beside the clone), then in
# the download folder ${AERO_CACHE:-~/.cache/aero}/vendor, and else fetches
# it from its release URL (curl or wget) into that folder. Whatever the
# source, the file must have the SHA-256 pinned below, or it is refused (a
# damaged or altered archive is never built). Offline, it says which files
# to get and from where. docs/building.md lists the same URLs and sums.
set -eu

A=${1:?usage: sh platforms/vendor.sh ARCHIVE}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
VENDOR=${VENDOR:-$ROOT/../shared/vendor}
FETCHED=${AERO_CACHE:-$HOME/.cache/aero}/vendor

# ARCHIVE SHA-256 URL...: FFTW and libsndfile are the release sources as
# Debian keeps them (byte for byte FFTW's own fftw-3.3.10.tar.gz); Pd and
# libpd are `git archive`s of their release commits, whose sums GitHub's
# generated tag archives need not reproduce (see docs/building.md)
pin() {
    case $1 in
    fftw-3.3.10.tar.gz) echo 56c932549852cddcfafdab3820b0200c7742675be92179e59e6215b340e26467 \
        https://www.fftw.org/fftw-3.3.10.tar.gz \
        https://deb.debian.org/debian/pool/main/f/fftw3/fftw3_3.3.10.orig.tar.gz ;;
    libsndfile-1.2.0.tar.gz) echo 62dc4e2bcd45f6f0e89cbc3522cc90eb174dca0eef0a0d19ead289833b390cd7 \
        https://deb.debian.org/debian/pool/main/libs/libsndfile/libsndfile_1.2.0.orig.tar.gz \
        https://snapshot.debian.org/archive/debian/20230101T000000Z/pool/main/libs/libsndfile/libsndfile_1.2.0.orig.tar.gz ;;
    pure-data-0.56-5.tar.gz) echo d12f651431480c3d2bce1b1614a056fbe8d80be6328e66f3a6eab335f587cecf \
        https://github.com/pure-data/pure-data/archive/refs/tags/0.56-5.tar.gz ;;
    libpd-0.16.1.tar.gz) echo 4826aacfe4c03dbb74d77a0a3089eef38d12586717c53be729a5489d54d6a9fe \
        https://github.com/libpd/libpd/archive/refs/tags/0.16.1.tar.gz ;;
    *) echo "vendor.sh: no pinned archive '$1' (fftw-3.3.10.tar.gz," \
        "libsndfile-1.2.0.tar.gz, pure-data-0.56-5.tar.gz, libpd-0.16.1.tar.gz)" >&2
       exit 2 ;;
    esac
}
set -- $(pin "$A")
SUM=$1
shift

# ok FILE: its sum is the pinned one
ok() { [ "$(sha256sum "$1" | cut -d' ' -f1)" = "$SUM" ]; }

for f in "$VENDOR/$A" "$FETCHED/$A"; do
    [ -f "$f" ] || continue
    if ok "$f"; then echo "$f"; exit 0; fi
    echo "vendor.sh: $f: SHA-256 $(sha256sum "$f" | cut -d' ' -f1)," \
        "not the pinned $SUM: refused (a damaged or different archive;" \
        "delete it or replace it with the release archive)" >&2
    exit 1
done

mkdir -p "$FETCHED"
tmp="$FETCHED/.$A.$$"
trap 'rm -f "$tmp"' EXIT
for url in "$@"; do
    if command -v curl >/dev/null; then
        curl -fsSL --retry 2 --connect-timeout 20 -o "$tmp" "$url" 2>/dev/null || continue
    elif command -v wget >/dev/null; then
        wget -q -T 20 -O "$tmp" "$url" || continue
    else
        break
    fi
    if ok "$tmp"; then
        mv "$tmp" "$FETCHED/$A"
        echo "vendor.sh: fetched $A from $url (SHA-256 checked)" >&2
        echo "$FETCHED/$A"
        exit 0
    fi
    echo "vendor.sh: $url: SHA-256 $(sha256sum "$tmp" | cut -d' ' -f1), not the" \
        "pinned $SUM: refused" >&2
done
{
    echo "vendor.sh: $A is not in $VENDOR nor in $FETCHED, and could not be"
    echo "  fetched (offline, or no curl/wget). Get it from"
    for url in "$@"; do echo "    $url"; done
    echo "  check that its SHA-256 is $SUM"
    echo "  and put it in a folder given as VENDOR=/that/folder (make VENDOR=...)."
    echo "  docs/building.md lists every archive the builds use."
} >&2
exit 1
