#!/bin/sh
# aero: builds libpd 0.16.1 (with its Pd 0.56-5) from ../shared/vendor into
# build/libpd/VARIANT, once: VARIANT is `single` (one Pd per process:
# `make STATIC=true`) or `multi` (several Pd instances, each in its own
# thread: `make STATIC=true MULTI=true`, i.e. -DPDINSTANCE -DPDTHREADS).
# Each variant gets its own source tree: libpd builds its objects in place.
# Exit 0 when built (or already built), 77 when the archives are absent,
# 1 when the build fails (its log is printed).
# Usage: build-libpd.sh VARIANT [VENDOR_DIR]
set -u
variant=$1
vendor=${2:-../shared/vendor}
dest=build/libpd/$variant
case "$variant" in
    single) flags="STATIC=true" ;;
    multi) flags="STATIC=true MULTI=true" ;;
    *) echo "build-libpd: unknown variant '$variant' (single, multi)" >&2; exit 2 ;;
esac
libpd_tgz=$(VENDOR=$vendor sh platforms/vendor.sh libpd-0.16.1.tar.gz 2>/dev/null || echo "$vendor/libpd-0.16.1.tar.gz")
pd_tgz=$(VENDOR=$vendor sh platforms/vendor.sh pure-data-0.56-5.tar.gz 2>/dev/null || echo "$vendor/pure-data-0.56-5.tar.gz")
if [ ! -f "$libpd_tgz" ] || [ ! -f "$pd_tgz" ]; then
    echo "libpd: $libpd_tgz or $pd_tgz absent: skipped"
    exit 77
fi
# built already with these flags: nothing to do
if [ -f "$dest/libs/libpd.a" ] && [ -f "$dest/libs/libpd.so" ] &&
    [ "$(cat "$dest/.aero-flags" 2>/dev/null)" = "$flags" ]; then
    exit 0
fi
rm -rf "$dest"
mkdir -p "$dest"
tar xzf "$libpd_tgz" -C "$dest" --strip-components=1 &&
    tar xzf "$pd_tgz" -C "$dest/pure-data" --strip-components=1 || exit 1
echo "libpd: building $variant ($flags) in $dest"
# a make of its own: not the flags of a calling make (pd-lib-builder turns
# the built-in rules off, which libpd's Makefile relies on)
# shellcheck disable=SC2086
if ! env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
    nice -n 10 make -C "$dest" -j2 $flags >"$dest/build.log" 2>&1; then
    tail -30 "$dest/build.log"
    echo "libpd: the $variant build failed (log: $dest/build.log)" >&2
    exit 1
fi
echo "$flags" >"$dest/.aero-flags"
