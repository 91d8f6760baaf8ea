#!/bin/sh
# make deken: the deken packages of aero, one per platform and float size,
# zipped from the staged library folders build/PLATFORM/aero/ (made by
# `make platform P=PLATFORM`), and the (Sources) package from git.
#   sh platforms/deken.sh DEKEN_DIR VERSION PLATFORM...
# PLATFORM is Pd's name (linux-amd64, linux-arm64, linux-armv7,
# windows-amd64) or darwin (macOS, universal binaries); each package is
# named as deken names it, aero[vVERSION](OS-CPU-FLOATSIZE).dek, with one
# (OS-CPU-FLOATSIZE) per CPU its binaries hold (darwin:
# (Darwin-arm64-32)(Darwin-amd64-32)), and holds the folder aero/ with
# that platform's binaries of that float size and everything that is not
# a binary (help, abstractions, textures, trees, aero-meta.pd, LICENSE,
# README.md). Beside each: NAME.dek.txt, the object list (one
# "NAME<TAB>DESCRIPTION" line per object, tests/deken-objects.sh) and
# NAME.dek.sha256 (sha256sum -c checks it).
set -e
dir=$1 version=$2
shift 2
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
name="aero[v$version]"

# the binaries of one package: PLATFORM FLOATSIZE -> the extension kept;
# every other binary in the staged folder is left out
binary_ext() {
    case "$1:$2" in
        linux-amd64:32 | linux-arm64:32 | linux-armv7:32) echo pd_linux ;;
        linux-amd64:64) echo linux-amd64-64.so ;;
        windows-amd64:32) echo windows-amd64-32.dll ;;
        windows-amd64:64) echo windows-amd64-64.dll ;;
        darwin:32) echo d_fat ;;
        darwin:64) echo darwin-fat-64.so ;;
    esac
}
deken_archs() { # PLATFORM FLOATSIZE: linux-amd64 32 -> (Linux-amd64-32)
    case "$1" in
        linux-*) echo "(Linux-${1#*-}-$2)" ;;
        windows-*) echo "(Windows-${1#*-}-$2)" ;;
        darwin) echo "(Darwin-arm64-$2)(Darwin-amd64-$2)" ;;
        *) echo "deken.sh: unknown platform $1" >&2; return 1 ;;
    esac
}
# the float sizes shipped per platform: arm Pd (Debian's, Raspberry Pi
# OS's) is single precision only
float_sizes() {
    case "$1" in
        linux-amd64 | windows-amd64 | darwin) echo "32 64" ;;
        *) echo 32 ;;
    esac
}

for p in "$@"; do
    stage=build/$p/aero
    if [ ! -f "$stage/aero-meta.pd" ]; then
        echo "deken.sh: no staged folder $stage (make platform P=$p)" >&2
        exit 1
    fi
    for fs in $(float_sizes "$p"); do
        ext=$(binary_ext "$p" "$fs")
        dek="$name$(deken_archs "$p" "$fs").dek"
        rm -f "$dir/$dek"
        # the list of files, binaries only of this package's kind; zip
        # reads it from stdin (-@), names relative to build/PLATFORM
        (cd "build/$p" && find aero \( -type d -o -type f \) | LC_ALL=C sort | awk -v ext=".$ext" '
            /\.(pd_linux|so|dll|exe|dylib|pd_darwin|l_[a-z0-9]+|m_[a-z0-9]+|d_[a-z0-9]+)$/ {
                if (substr($0, length($0) - length(ext) + 1) != ext) next }
            { print }' | zip -q -X -@ "$dir/$dek")
    done
done
# the sources: the committed tree (what a user builds from)
git archive --format=zip --prefix=aero/ -o "$dir/$name(Sources).dek" HEAD

sh tests/deken-objects.sh $(for c in src/pd/*~.c; do basename "$c" .c; done) \
    $(cd abstractions && ls *.pd | sed 's/\.pd$//') >"$dir/objects.txt"
(cd "$dir" && for f in *.dek; do
    cp objects.txt "$f.txt"
    sha256sum "$f" >"$f.sha256"
done && rm objects.txt)
ls -1 "$dir"/*.dek
