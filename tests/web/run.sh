#!/bin/sh
# aero: `make check-web`: the page of `make web` (libpd + aero compiled to
# WebAssembly) in Debian's Chromium, headless, driven by playwright-core
# (tests/web/package.json, its lock file; installed into tests/web/
# node_modules by npm ci). Checks that
#   - the page loads and plays live in an AudioWorklet with no console error;
#   - each scene (web/scenes/*.pd) rendered offline in the page for SECONDS
#     (default 3) equals the native render of the same patch (Pd 0.56-5 as
#     native libpd, the native aero linked statically: tests/libpd/render.c)
#     within float rounding, and build/aero-analyze finds the same spectral
#     peak and level in both;
#   - the wind-speed slider changes the sound as in Pd: the 25 mm rod
#     alone, no gusts, 12 -> 24 m/s: the Aeolian tone's frequency doubles
#     and its level rises 18 dB (below).
# Ends with `N passed, N failed`. Run from the repository root after
# `make web` and `make all` (the Makefile's check-web does both).
# BENCH=1 also prints the page's and the native cost per 128-frame block
# (bench/web.sh uses it).
ROOT=$(pwd)
OUT=build/web-check
SECONDS_RENDER=${WEB_SECONDS:-3}
VENDOR=${VENDOR:-../shared/vendor}
RATE=48000
passed=0
failed=0
pass() { passed=$((passed + 1)); echo "  ok    $*"; }
fail() { failed=$((failed + 1)); echo "  FAIL  $*"; }
judge() { # a command's exit status; its own output says what it measured
    if line=$("$@" 2>&1); then
        passed=$((passed + 1)); echo "  $line"
    else
        failed=$((failed + 1)); echo "  $line"
    fi
}
START=$(date +%s)
section() { echo; echo "== $* (at $(( $(date +%s) - START )) s)"; }
rm -rf "$OUT"
mkdir -p "$OUT"

# --- native renders: libpd 0.16.1 (the same Pd 0.56-5 as the page) --------
section "native: libpd 0.16.1 with the native aero, the same scene patches"
sh tests/libpd/build-libpd.sh single "$VENDOR" || { echo "check-web: native libpd did not build"; exit 1; }
L=build/libpd/single
if cc -std=c99 -D_POSIX_C_SOURCE=200809L -O2 -Wall -Wextra -Werror \
    -I$L/libpd_wrapper -I$L/pure-data/src -Isrc/pd -Isrc/core/common \
    -Isrc/core/solve -Isrc/core/play tests/libpd/render.c src/pd/*.c \
    $L/libs/libpd.a build/libaero_core.a -lsndfile -lfftw3f_threads -lfftw3f \
    -lm -lpthread -ldl -fopenmp -o "$OUT/render-native" >"$OUT/render-native.log" 2>&1; then
    pass "native render host (tests/libpd/render.c) builds"
else
    cat "$OUT/render-native.log"; fail "native render host"
fi
scenes=$(ls web/scenes/*.pd | sed 's|web/scenes/||; s|\.pd$||')
for s in $scenes; do
    "$OUT/render-native" -data "$ROOT" -path "$ROOT/abstractions" \
        -seconds "$SECONDS_RENDER" -settle 0 "web/scenes/$s.pd" \
        "$OUT/native-$s.wav" 2>"$OUT/native-$s.log" || fail "native render of $s"
done

# --- levels: the master limiter, each scene's loudness ---------------------
section "levels: the master limiter (-1 dBTP) and each scene's default loudness"
judge_all() { # every "ok"/"FAIL" line of a command counted
    "$@" >"$OUT/judge.log" 2>&1
    while IFS= read -r line; do
        case "$line" in
            ok*) passed=$((passed + 1)); echo "  $line" ;;
            FAIL*) failed=$((failed + 1)); echo "  $line" ;;
            *) echo "  $line" ;;
        esac
    done <"$OUT/judge.log"
}
judge_all node tests/web/limiter.mjs
# the first 10 s of each scene at its defaults, natively (the same samples
# as the page's, checked below for the first SECONDS)
for s in $scenes; do
    "$OUT/render-native" -data "$ROOT" -path "$ROOT/abstractions" \
        -seconds 10 -settle 0 "web/scenes/$s.pd" "$OUT/loud-$s.wav" \
        2>"$OUT/loud-$s.log" || fail "native 10 s render of $s"
done
judge_all node tests/web/loudness.mjs $RATE "$OUT"/loud-*.wav

# examples/web-embed (checked below) compiles meanwhile: the page's checks
# mostly wait on the audio clock. At -O1: the same steps and code, built in
# about 9 s where -O3's whole-module optimisation took nearly 3 min on the
# loaded 2-core machine; this checks that the steps work, not its speed
rm -rf "$OUT/embed" && mkdir -p "$OUT/embed"
cp examples/web-embed/* "$OUT/embed/"
(cd "$OUT/embed" && AERO="$ROOT" OPT=-O1 nice sh build.sh) >"$OUT/embed.log" 2>&1 &
embed_build=$!

# --- the page in Chromium ---------------------------------------------------
section "the page in Chromium (headless, playwright-core)"
(cd tests/web && [ -d node_modules/playwright-core ] ||
    npm ci --no-audit --no-fund --loglevel=error) >/dev/null ||
    { echo "check-web: npm ci failed"; exit 1; }
# a free port for python's static server
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory build/web \
    >"$OUT/server.log" 2>&1 &
server=$!
trap 'kill $server $embed_build 2>/dev/null' EXIT INT TERM
sleep 1
judge_all node tests/web/check.mjs "http://127.0.0.1:$port/" "$OUT" "$SECONDS_RENDER" \
    ${BENCH:+bench}
cp "$OUT/judge.log" "$OUT/browser.log"
kill $server 2>/dev/null

# --- the same samples ----------------------------------------------------------
# Tolerance: the page and the native host run the same C (Pd 0.56-5, aero)
# in IEEE single precision, both without fused multiply-adds; they differ
# where the two C libraries round differently: emscripten's musl sin, cos,
# exp, pow, acos against glibc's (each within an ulp, not always the same
# one), and libpd's -ffast-math, which lets clang and gcc reassociate Pd's
# own sums differently. One such rounding is eps = 2^-24 of the value, a
# handful of them 16 eps. Where it enters a quantity that is integrated
# sample after sample (an oscillator's or a rotation's phase, a position),
# the error adds up: a phase that has turned 2 pi f t carries at most
# eps 2 pi f t, and a tone of amplitude A then differs by A eps 2 pi f t,
# largest for f at Nyquist. So at time t the bound is
#     |web - native| <= peak eps (16 + 2 pi (RATE/2) t)
# (1e-6 of the peak at the start, 2.7e-2 after 3 s at 48 kHz). A different
# seed, parameter, file or Pd version differs by the signal itself (order
# 1 x peak) and fails; tests/web/compare.mjs prints the measured largest
# difference against the peak and the bound.
# the number in aero-analyze's line ("ok peak of F: 123.4 Hz")
measure() { build/aero-analyze "$@" | sed -n 's/^[a-zA-Z]* [^:]*: \(-*[0-9.e+-]*\) .*/\1/p'; }
# aero-analyze on both renders: the same spectral peak (to 0.1 %) and level
# (to 0.01 dB)
analyze_same() {
    a=$(measure peak --ch "$2" "$OUT/native-$1.wav")
    b=$(measure peak --ch "$2" "$OUT/web-$1.wav")
    la=$(measure level --ch "$2" "$OUT/native-$1.wav")
    lb=$(measure level --ch "$2" "$OUT/web-$1.wav")
    awk -v s="$1" -v ch="$2" -v a="$a" -v b="$b" -v la="$la" -v lb="$lb" 'BEGIN {
        ok = a != "" && b != "" && la != "" && lb != "" && a > 0 &&
            (a - b) / a < 1e-3 && (b - a) / a < 1e-3 && la - lb < 0.01 && lb - la < 0.01
        printf "%s  %s ch %s: aero-analyze peak %s / %s Hz, level %s / %s dB SPL (native / web)\n",
            ok ? "ok   " : "FAIL ", s, ch, a, b, la, lb
        exit !ok }'
}
section "the same samples as native Pd (|web - native| <= peak eps (16 + 2 pi RATE/2 t))"
for s in $scenes; do
    judge node tests/web/compare.mjs "$OUT/native-$s.wav" "$OUT/web-$s.wav" $RATE
    for ch in 0 1; do
        judge analyze_same "$s" "$ch"
    done
done

# negative control: a render of the same patch with other controls (the
# wires scene, one rod, no gusts) must fail the comparison
if node tests/web/compare.mjs "$OUT/native-wires.wav" "$OUT/wires-u12.wav" $RATE >/dev/null; then
    fail "negative control: the wires scene with other controls passed as the same samples"
else
    pass "negative control: the wires scene with other controls differs beyond the bound"
fi

# --- a control moved in the page changes the sound as in Pd ----------------
# The 25 mm rod alone at 12 and 24 m/s (Re 2.0e4 and 4.1e4): f = St U / d
# with St = 0.198 (1 - 19.7/Re) (Roshko), so the tone's frequency doubles
# (x 2.002); the level follows Curle, p ~ U^3 St C_L' with Norberg's (2003)
# C_L'(Re), nearly flat here: +18.06 dB from U^3 and +0.4 dB from C_L'. The
# frequency within 2 % (a 1.5 Hz bin at 95 Hz), the level within 1 dB (as
# tests/libpd's Curle level).
section "the wind-speed slider, the 25 mm rod alone, 12 -> 24 m/s (as in Pd)"
law() { awk -v u1=12 -v u2=24 -v d=0.025 -v what="$1" 'BEGIN {
    for (k = 1; k <= 2; k++) { u = k == 1 ? u1 : u2; re = 1.225 * u * d / 1.81e-5
        st[k] = 0.198 * (1 - 19.7 / re); x = log(re / 1600) / log(10)
        cl[k] = re < 5400 ? 0.045 + 3 * x^4.6 : 0.52 - 0.06 * x^-2.6 }
    if (what == "ratio") printf "%.4f", st[2] * u2 / (st[1] * u1)
    else printf "%.2f", 20 * log(u2^3 * st[2] * cl[2] / (u1^3 * st[1] * cl[1])) / log(10) }'; }
judge build/aero-analyze peakratio --fmin 50 --fmax 1000 --nfft 32768 \
    "$OUT/wires-u12.wav" "$OUT/wires-u24.wav" --expect "$(law ratio)" --tol 0.02
judge build/aero-analyze leveldiff "$OUT/wires-u12.wav" "$OUT/wires-u24.wav" \
    --expect "$(law level)" --tol 1

# --- examples/web-embed: docs/web.md's embedding, from its steps alone ----
section "examples/web-embed built in an empty folder from its README's steps"
if wait $embed_build; then
    pass "examples/web-embed: AERO=... sh build.sh after make web builds embed.js and embed.wasm"
    python3 -m http.server "$port" --bind 127.0.0.1 --directory "$OUT/embed" \
        >"$OUT/server-embed.log" 2>&1 &
    server=$!
    sleep 1
    judge_all node tests/web/embed.mjs "http://127.0.0.1:$port/"
    kill $server 2>/dev/null
else
    tail -20 "$OUT/embed.log"
    fail "examples/web-embed: its build.sh failed ($OUT/embed.log)"
fi

# --- the small things outside the page ------------------------------------
section "make web-serve and docs/web.md"
serve=$(make -n --no-print-directory web-serve PORT=8123 2>/dev/null | grep http.server)
case "$serve" in
    *"--bind 127.0.0.1"*8123*|*8123*"--bind 127.0.0.1"*) pass "make web-serve PORT=8123: $serve" ;;
    *) fail "make web-serve does not bind 127.0.0.1 on PORT= ($serve)" ;;
esac
# each texture's size as docs/web.md states it (gzip -9, kB) within 3 %
for t in sword fire; do
    kb=$(gzip -9c "textures/$t.wav" | wc -c | awk '{printf "%.0f", $1 / 1000}')
    said=$(sed -n "s/.*the $t's texture \([0-9]*\) kB.*/\1/p" docs/web.md | tr -d '\n')
    awk -v a="$kb" -v b="$said" -v t="$t" 'BEGIN { ok = b != "" && (a - b) / a < 0.03 && (b - a) / a < 0.03
        printf "%s  docs/web.md: the %s texture %s kB, measured %s kB (gzip -9)\n", ok ? "ok   " : "FAIL ", t, b, a
        exit !ok }' && passed=$((passed + 1)) || failed=$((failed + 1))
done

# platforms/vendor.sh (make web's archives): a verified archive in VENDOR
# is used as it is, a damaged copy is refused before anything is fetched
section "platforms/vendor.sh: the source archives checked against their pinned SHA-256"
got=$(VENDOR="$VENDOR" sh platforms/vendor.sh libpd-0.16.1.tar.gz 2>&1)
[ "$got" = "$VENDOR/libpd-0.16.1.tar.gz" ] && pass "vendor.sh: libpd-0.16.1.tar.gz found in VENDOR ($got)" ||
    fail "vendor.sh: libpd-0.16.1.tar.gz in VENDOR not used ($got)"
mkdir -p "$OUT/bad-vendor"
head -c 100000 "$VENDOR/libpd-0.16.1.tar.gz" >"$OUT/bad-vendor/libpd-0.16.1.tar.gz"
if got=$(VENDOR="$OUT/bad-vendor" sh platforms/vendor.sh libpd-0.16.1.tar.gz 2>&1); then
    fail "vendor.sh: a truncated libpd-0.16.1.tar.gz was accepted"
else
    case "$got" in *refused*) pass "vendor.sh: a truncated copy is refused: ${got%%(*}" ;;
        *) fail "vendor.sh: a truncated copy failed without saying why ($got)" ;; esac
fi

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
