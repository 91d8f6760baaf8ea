#!/bin/sh
# make check-packages: every deken package, after the platform builds.
#  1. tests/objects/96-packaging.sh (through tests/run.sh, ONLY=packaging)
#     with DEKEN_PLATFORMS (default: every platform): make deken, then each
#     package's checksum, object list, contents, and each binary's platform,
#     float size, exports and glibc;
#  2. tests/packages/clean-debian.sh: the Linux packages loaded and played
#     in a minimal Debian 12 with only Pd.
# Ends with `N passed, N failed` over both. Run from the repository root
# after `make all lib double` (the negative control installs those).
DEKEN_PLATFORMS=${DEKEN_PLATFORMS:-linux-amd64 linux-arm64 linux-armv7 windows-amd64 darwin}
OUTDIR=build/tests/out-packages
start=$(date +%s)
mkdir -p build/tests
DEKEN_PLATFORMS=$DEKEN_PLATFORMS ONLY=96-packaging TEST_OUT=$OUTDIR \
    sh tests/run.sh | tee build/tests/packages.log
sh tests/packages/clean-debian.sh "$OUTDIR/deken" | tee build/tests/clean-debian.log
passed=0 failed=0
for log in build/tests/packages.log build/tests/clean-debian.log; do
    line=$(tail -n 1 "$log")
    case "$line" in
        *" passed, "*" failed") ;;
        *) line="0 passed, 1 failed" ; echo "$log: the run did not finish" ;;
    esac
    p=${line%% passed*} f=${line#*passed, } f=${f%% failed*}
    passed=$((passed + p)) failed=$((failed + f))
done
echo
echo "check-packages ($(($(date +%s) - start)) s)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
