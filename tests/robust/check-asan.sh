#!/bin/sh
# aero: the whole test suite (tests/run.sh) against the
# ASan/UBSan build of `make asan`: instrumented unit tests, analyser and
# aerotex, and instrumented externals loaded into the stock Pd with the
# sanitizer runtime preloaded. Any sanitizer report fails the run, even one
# that did not change a test's verdict (e.g. a leak found at Pd's exit).
# Run from the repository root after `make all asan`. ONLY=pattern is
# passed to tests/run.sh (e.g. ONLY=aeolian: the unit tests, object scripts
# and help patches whose path contains it; ONLY=objects/9 for the
# robustness scripts), and `make check-asan` passes it on to
# check-valgrind; the negative control below always runs. Every unit test
# runs here, those declared slow for memcheck (tests/robust/slow-tests.sh)
# included, shortened: AERO_TEST_SANITIZED=1 makes test_flow2d and
# test_urans run their flows a few time units, for the memory checks only
# (make check judges their physics). The hostile-input test runs its Pd
# runs two at a time (HOSTILE_JOBS).
set -u
ROOT=$(pwd)
ASAN_ROOT=$ROOT/build-asan/root
REPORTS=$ROOT/build-asan/reports
LIBASAN=$(gcc -print-file-name=libasan.so)
rm -rf "$REPORTS"
mkdir -p "$REPORTS" "$ROOT/build-asan/bin"

# the suite runs in a mirror of the tree whose build/ and externals are the
# instrumented ones
# (platforms/ and .git for `make deken`: the package build and the git
# archive of the sources)
for d in tests help textures trees src abstractions fuzz demo examples docs \
    platforms .git LICENSE README.md Makefile pd-lib-builder; do
    [ -e "$ROOT/$d" ] && ln -sfn "$ROOT/$d" "$ASAN_ROOT/$d"
done
# the writable-globals check reads the normal build's objects (the
# sanitizers add their own globals to the instrumented ones)
mkdir -p "$ASAN_ROOT/build"
ln -sfn "$ROOT/build/core" "$ASAN_ROOT/build/core"

# `pd` on the PATH: the stock Pd with libasan preloaded (Pd itself is not
# instrumented; the runtime must be loaded before any instrumented
# external). Leak detection stays on: Pd keeps every patch, class and
# symbol reachable from its globals until exit, so LSan (which reports only
# unreachable blocks) has nothing of Pd's to report; a suppressions file
# (tests/robust/lsan.supp) names any block Pd itself loses, with the reason.
cat >"$ROOT/build-asan/bin/pd" <<WRAP
#!/bin/sh
LD_PRELOAD="$LIBASAN\${LD_PRELOAD:+:\$LD_PRELOAD}" exec /usr/bin/pd "\$@"
WRAP
chmod +x "$ROOT/build-asan/bin/pd"
PATH=$ROOT/build-asan/bin:$PATH
# reports go to files (one per process), so nothing hides in a Pd log
ASAN_OPTIONS="log_path=$REPORTS/asan:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
LSAN_OPTIONS="suppressions=$ROOT/tests/robust/lsan.supp:print_suppressions=0"
UBSAN_OPTIONS="log_path=$REPORTS/ubsan:print_stacktrace=1:halt_on_error=1"
# libgomp's thread pool: one thread, so the instrumented tools stay within
# the machine's budget
OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
# the fuzz regressions (tests/objects/95-fuzz-replay.sh) under ASan too
FUZZ_REPLAY_FLAGS="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all"
# Pd runs 3-10x slower instrumented ([fieldsound~]'s hostile run
# preprocesses its 32^3 fallback burst ~60 times)
HOSTILE_TIMEOUT=${HOSTILE_TIMEOUT:-900}
HOSTILE_JOBS=${HOSTILE_JOBS:-2}
AERO_TEST_SANITIZED=1
# the vendor archives the package build reads, from the real tree's place
AERO_VENDOR=${AERO_VENDOR:-$ROOT/../shared/vendor}
export HOSTILE_TIMEOUT HOSTILE_JOBS AERO_TEST_SANITIZED AERO_VENDOR PATH ASAN_OPTIONS LSAN_OPTIONS UBSAN_OPTIONS OMP_NUM_THREADS FUZZ_REPLAY_FLAGS

echo "== check-asan: tests/run.sh with ASan+UBSan ($LIBASAN preloaded into Pd)"
slow=$(sh tests/robust/slow-tests.sh | while read -r n; do
    case "build/tests/$n" in *"${ONLY:-}"*) printf ' %s' "$n" ;; esac; done)
[ -n "$slow" ] && echo "   (declared slow for memcheck, covered by this run alone:$slow)"
(cd "$ASAN_ROOT" && sh tests/run.sh)
suite=$?
(cd "$ASAN_ROOT" && sh tests/robust/asan-control.sh "$REPORTS")
control=$?

# UBSan (gcc) may print into the Pd log instead of log_path: look there too
grep -a -l -r -e "runtime error:" -e "ERROR: AddressSanitizer" \
    -e "ERROR: LeakSanitizer" "$ASAN_ROOT/build/tests/out" 2>/dev/null |
    grep -v asan-control | while read -r log; do
        cp "$log" "$REPORTS/in-log.$(basename "$log")"
    done
reports=$(ls "$REPORTS" 2>/dev/null | grep -v '^control' | wc -l)
echo
if [ "$reports" -ne 0 ]; then
    echo "FAIL  $reports sanitizer report(s) in $REPORTS:"
    for r in "$REPORTS"/*; do
        case "$r" in */control*) continue ;; esac
        echo "--- $r"; head -40 "$r"
    done
fi
[ "$suite" -eq 0 ] && [ "$control" -eq 0 ] && [ "$reports" -eq 0 ] && {
    echo "check-asan: suite passed, no sanitizer report"; exit 0; }
echo "check-asan: FAILED (suite $suite, control $control, $reports reports)"
exit 1
