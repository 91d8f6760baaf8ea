#!/bin/sh
# make bench: aero's tones against the closest open peer, the Sound Design
# Toolkit (SDT, SkAT-VG/SDT, GPL-3.0; a benchmark peer only, none of its
# files enters this repository): [aeolian~] against SDT's [windkarman~],
# [cavity~] against [windcavity~], and the texture modes of both aero
# objects beside them, in one run with the repetitions alternating.
#
# SDT's Pd library is built from the vendored archive into build/sdt/ (when
# the archive is there: ../shared/vendor/sdt-0509de41.tar.gz, or
# SDT_ARCHIVE; without it the SDT rows are left out and the aero rows run).
#
# Equivalent settings: the same tone frequency at the same speed. SDT's
# wind is a 0-1 value (clipped above 1), so each SDT object gets the aero
# speed U times a factor:
#   [windkarman~ diameter d]: a two-pole resonance at fc = 8 w / d (SDT's
#     SDTWindKarman_updateResonance), so w = f_a d / (8 U), f_a the tone
#     [aeolian~ -d d] sounds at U = 10 m/s (measured here);
#   [windcavity~ length L diameter D]: a comb tuned to c / (2 L + 1.6 D)
#     (c = 340.29 m/s) and a resonance at fc = c / (2 L + 1.6 D) (L / D) w
#     (SDTWindCavity_updateGeometry/updateResonance), so w = f_c (2 L +
#     1.6 D) D / (c L U), f_c the strongest tone of [cavity~ -L L -D D] at
#     10 m/s (its Rossiter mode 2, measured here).
# Before a pair is timed, one instance of each renders 2 s at 10 m/s and
# build/aero-analyze reports its level and spectral peak: a silent object
# (level below 20 dB SPL, or an SDT peak away from the tone: 10 % for
# [windkarman~], 50 % for [windcavity~]'s broad band) is not timed.
#
# Timing: N instances fed one gusting speed (10 m/s +- 3, a [line~] ramp
# every 10 ms), summed into a [catch~], Pd in batch mode at 48 kHz for S
# seconds of sound; the CPU time (user + sys, bash's time) of each
# Pd run minus that of the same patch with no instance, the fastest of R
# repetitions, the objects alternating within each repetition. Each run
# prints the logical time it rendered and the level of the sum, checked
# before its time is used.
#   BENCH_PEER_SOURCES (200), BENCH_PEER_SECONDS (20), BENCH_PEER_REPS (3)
# Not a test: figures go to BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench/peer
mkdir -p "$DIR"
N=${BENCH_PEER_SOURCES:-200}
S=${BENCH_PEER_SECONDS:-20}
REPS=${BENCH_PEER_REPS:-3}
RATE=48000
ANALYZE=$ROOT/build/aero-analyze
SDT_ARCHIVE=${SDT_ARCHIVE:-$ROOT/../shared/vendor/sdt-0509de41.tar.gz}
SDT_DIR=$ROOT/build/sdt
SDT_LIB=$SDT_DIR/SDT/.build.linux/SDT.pd_linux
PD_BIN=${PD:-$(command -v pd || command -v puredata)}
[ -x "$ANALYZE" ] || { echo "bench/peer.sh: build $ANALYZE first (make tools)" >&2; exit 1; }

# the geometry both sides share
D_CYL=0.01 L_CYL=0.5         # cylinder diameter and span
L_CAV=0.02 D_CAV=0.01 W_CAV=0.05
C_SDT=340.29                 # SDT_MACH1

# --- SDT's Pd library, from the vendored archive ---------------------------
have_sdt=0
if [ -f "$SDT_ARCHIVE" ]; then
    sums=$(dirname "$SDT_ARCHIVE")/SHA256SUMS
    if [ -f "$sums" ] && ! (cd "$(dirname "$SDT_ARCHIVE")" &&
        grep " $(basename "$SDT_ARCHIVE")\$" SHA256SUMS | sha256sum -c --quiet -); then
        echo "SDT: $SDT_ARCHIVE does not match its SHA256SUMS: peer rows left out"
    else
        if [ ! -f "$SDT_LIB" ] || [ "$SDT_ARCHIVE" -nt "$SDT_LIB" ]; then
            echo "SDT: building its Pd library from $SDT_ARCHIVE into build/sdt/ ..."
            rm -rf "$SDT_DIR" && mkdir -p "$SDT_DIR"
            tar -xzf "$SDT_ARCHIVE" -C "$SDT_DIR" &&
                nice -n 10 make -C "$SDT_DIR/SDT" -j2 pd CFLAGS="-include stdlib.h" \
                    >"$SDT_DIR/build.log" 2>&1 ||
                { echo "SDT: build failed (build/sdt/build.log)"; tail -5 "$SDT_DIR/build.log"; }
        fi
        [ -f "$SDT_LIB" ] && have_sdt=1
    fi
else
    echo "SDT: no archive at $SDT_ARCHIVE: the peer rows are left out"
fi
SDT_FLAGS=""
[ $have_sdt = 1 ] && SDT_FLAGS="-path $(dirname "$SDT_LIB") -lib SDT"

# --- sounding checks: one instance, 2 s at 10 m/s --------------------------
OUT=$DIR/check
export ROOT OUT
PD_RATE=$RATE
. "$ROOT/tests/pdtest.sh"
PD=$PD_BIN
PD_FLAGS="$PD_FLAGS $SDT_FLAGS"
mkdir -p "$OUT"
# check NAME CHAIN INIT [EVENT]: renders chk-NAME.wav (not NAME.wav: a
# texture of that name would be found beside the patch), prints its level
# and spectral peak (50-5000 Hz, the spectrum smoothed over $SMOOTH Hz),
# sets $peak; returns 1 when it does not sound (level below 20 dB SPL)
SMOOTH=5
check() {
    pd_render "chk-$1" "$2" 1 2000 "$3" 0 ${4:+"$4"}
    level=$($ANALYZE level "$OUT/chk-$1.wav" --skip 0.5 2>&1 | awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^-?[0-9.]+$/) { print $i; exit } }')
    peak=$($ANALYZE peak "$OUT/chk-$1.wav" --skip 0.5 --fmin 50 --fmax 5000 --smooth $SMOOTH 2>&1 | awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^[0-9.]+$/) { print $i; exit } }')
    printf '  sounding check %-12s level %s dB, peak %s Hz (smoothed over %s Hz)\n' \
        "$1" "${level:-?}" "${peak:-?}" "$SMOOTH"
    if grep -q -i -e "couldn't create" -e "error" "$OUT/chk-$1.log"; then
        echo "    errors in $OUT/chk-$1.log:"; grep -i -e "couldn't create" -e "error" "$OUT/chk-$1.log"
        return 1
    fi
    awk -v l="$level" 'BEGIN { exit !(l != "" && l > 20) }'
}
near() { # A B TOL: |A/B - 1| <= TOL
    awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { exit !(a != "" && b > 0 && a / b >= 1 - t && a / b <= 1 + t) }'
}

echo "== aero against SDT (the peer), $N sources, $S s at $RATE Hz, $(nproc) cores, $(date -u '+%Y-%m-%d %H:%M') UTC"
ok_aeolian=0 ok_karman=0 ok_cavity=0 ok_windcavity=0 ok_cavtex=0 ok_aeotex=0
check aeolian "aeolian~ -d $D_CYL -l $L_CYL" "; aero-speed 10" && ok_aeolian=1
f_a=$peak
check cavity "cavity~ -L $L_CAV -D $D_CAV -W $W_CAV" "; aero-speed 10" && ok_cavity=1
f_c=$peak
check cavity-tex "cavity~ -texture cavity -L $L_CAV -D $D_CAV -W $W_CAV" "; aero-speed 10" && ok_cavtex=1
check aeolian-tex "aeolian~ -texture cylinder -n 10 -l 0.3" "; aero-speed 10" && ok_aeotex=1
# wind per m/s, from SDT's formulas (above) and the aero tones at 10 m/s
k_karman=$(awk -v f="$f_a" -v d=$D_CYL 'BEGIN { printf "%.6g", f * d / (8 * 10) }')
k_cavity=$(awk -v f="$f_c" -v l=$L_CAV -v d=$D_CAV -v c=$C_SDT 'BEGIN {
    printf "%.6g", f * (2 * l + 1.6 * d) * d / (c * l * 10) }')
if [ $have_sdt = 1 ]; then
    echo "  SDT wind = U x $k_karman for [windkarman~] (fc = 8 w / d = $f_a Hz at 10 m/s)," \
         "U x $k_cavity for [windcavity~] (fc = c/(2L+1.6D) (L/D) w = $f_c Hz at 10 m/s)"
    check windkarman "*~ $k_karman|windkarman~" "; aero-speed 10" \
        "0 ; aero-obj diameter $D_CYL" && near "$peak" "$f_a" 0.1 && ok_karman=1
    # at this wind the resonance's Q is 10 w L / D = 0.8: a broad band, not
    # a tone, whose peak lies below fc (its poles are far from the unit
    # circle): the peak of the spectrum smoothed over 100 Hz, within 50 %
    SMOOTH=100
    check windcavity "*~ $k_cavity|windcavity~" "; aero-speed 10" \
        "0 ; aero-obj length $L_CAV; aero-obj diameter $D_CAV" && near "$peak" "$f_c" 0.5 && ok_windcavity=1
    SMOOTH=5
fi

# --- timed patches ----------------------------------------------------------
# gen NAME COUNT SCALE INIT OBJECT: COUNT copies of OBJECT fed by the gusting
# speed times SCALE, INIT (a message-box body, may be empty) sent to each
# after DSP starts; prints the logical time rendered and the sum's level
gen() {
    {
        echo "#N canvas 0 50 800 600 10;"
        echo "#X obj 10 10 loadbang;"                               # 0
        echo "#X obj 10 30 t b b b b;"                              # 1
        echo "#X msg 100 50 \\; pd dsp 1;"                          # 2
        echo "#X obj 10 70 delay $((S * 1000));"                    # 3
        echo "#X obj 10 90 t b b b;"                                # 4
        echo "#X msg 10 110 \\; pd quit;"                           # 5
        echo "#X obj 200 10 metro 10;"                              # 6
        echo "#X obj 200 30 expr 10 + 2*sin(\\\$f1*0.013) + 1*sin(\\\$f1*0.031);" # 7
        echo "#X obj 200 50 f;"                                     # 8
        echo "#X obj 230 50 + 1;"                                   # 9
        echo "#X msg 200 70 \\\$1 10;"                             # 10
        echo "#X obj 200 90 line~;"                                 # 11
        echo "#X obj 200 110 *~ $3;"                                # 12
        echo "#X obj 10 500 catch~ sum;"                            # 13
        echo "#X obj 10 520 env~ 16384;"                            # 14
        echo "#X obj 10 540 f;"                                     # 15
        echo "#X obj 10 560 print bench-level-dB;"                  # 16
        echo "#X obj 100 540 timer;"                                # 17
        echo "#X obj 100 560 print bench-logical-ms;"               # 18
        echo "#X msg 300 50 ${4:-bang};"                            # 19
        i=0
        while [ $i -lt "$2" ]; do
            echo "#X obj $((10 + (i % 20) * 30)) $((150 + (i / 20) % 300)) $5;"
            echo "#X obj 10 480 throw~ sum;"
            i=$((i + 1))
        done
        for c in "0 0 1 0" "1 3 17 0" "1 2 2 0" "1 1 19 0" "1 0 3 0" \
            "1 0 6 0" "3 0 4 0" "4 2 17 1" "4 1 15 0" "4 0 5 0" "17 0 18 0" \
            "15 0 16 0" "14 0 15 1" "13 0 14 0" "6 0 8 0" "8 0 9 0" \
            "9 0 8 1" "8 0 7 0" "7 0 10 0" "10 0 11 0" "11 0 12 0"; do
            echo "#X connect $c;"
        done
        i=0
        while [ $i -lt "$2" ]; do
            obj=$((20 + 2 * i))
            echo "#X connect 12 0 $obj 0;"
            [ -n "$4" ] && echo "#X connect 19 0 $obj 0;"
            echo "#X connect $obj 0 $((obj + 1)) 0;"
            i=$((i + 1))
        done
    } >"$DIR/$1.pd"
}

# run NAME: CPU seconds (user + sys, bash's time keyword: bash is
# Essential in Debian, /usr/bin/time is not) of one render; checks that it
# rendered S s of logical time and that the sum sounded (or, for the empty
# patch, did not)
run() {
    log=$DIR/$1.log
    # shellcheck disable=SC2086
    bash -c 'TIMEFORMAT="bench-cpu %3U %3S %3R"; time "$@"' run \
        timeout 3600 "$PD_BIN" -batch -nogui -noaudio -noprefs -stderr -nostdpath \
        -r $RATE -path "$ROOT" $SDT_FLAGS -open "$DIR/$1.pd" >"$log" 2>&1
    ms=$(sed -n 's/^bench-logical-ms: //p' "$log")
    db=$(sed -n 's/^bench-level-dB: //p' "$log")
    cpu=$(awk '/^bench-cpu/ { printf "%.3f", $2 + $3 }' "$log")
    bad=""
    awk -v m="$ms" -v s="$S" 'BEGIN { exit !(m != "" && m >= 1000 * s - 20 && m <= 1000 * s + 20) }' ||
        bad="rendered ${ms:-no} ms of $S s"
    grep -q -i -e "couldn't create" -e "error" "$log" && bad="$bad; errors in $log"
    case $1 in
        empty) ;;
        *) awk -v d="$db" 'BEGIN { exit !(d != "" && d > 1) }' || bad="$bad; silent sum (env~ ${db:-?} dB)" ;;
    esac
    if [ -n "$bad" ]; then
        echo "  $1: not used: $bad" >&2
        echo ""
    else
        echo "$cpu"
    fi
}

gen empty 0 1 "" "aeolian~"
# only what sounded is timed
names=""
[ $ok_aeolian = 1 ] && names="$names aeolian"
[ $ok_karman = 1 ] && names="$names windkarman"
[ $ok_cavity = 1 ] && names="$names cavity"
[ $ok_windcavity = 1 ] && names="$names windcavity"
[ $ok_cavtex = 1 ] && names="$names cavity-tex"
[ $ok_aeotex = 1 ] && names="$names aeolian-tex"
gen aeolian "$N" 1 "" "aeolian~ -d $D_CYL -l $L_CYL"
gen cavity "$N" 1 "" "cavity~ -L $L_CAV -D $D_CAV -W $W_CAV"
gen cavity-tex "$N" 1 "" "cavity~ -texture cavity -L $L_CAV -D $D_CAV -W $W_CAV"
gen aeolian-tex "$((N / 10))" 1 "" "aeolian~ -texture cylinder -n 10 -l 0.3"
if [ $have_sdt = 1 ]; then
    gen windkarman "$N" "$k_karman" "diameter $D_CYL" "windkarman~"
    gen windcavity "$N" "$k_cavity" "length $L_CAV \\, diameter $D_CAV" "windcavity~"
fi

# the repetitions, alternating; every time is kept in $DIR/times.txt
: >"$DIR/times.txt"
r=1
while [ $r -le "$REPS" ]; do
    for name in empty $names; do
        t=$(run "$name")
        echo "$r $name ${t:-nan}" >>"$DIR/times.txt"
    done
    r=$((r + 1))
done

# per source-sample cost: (fastest render - fastest empty) / (sources x
# samples); the ratio of each pair also per repetition, for its spread
awk -v n="$N" -v s="$S" -v rate="$RATE" -v reps="$REPS" \
    -v okA="$ok_aeolian" -v okK="$ok_karman" -v okC="$ok_cavity" \
    -v okW="$ok_windcavity" -v okT="$ok_cavtex" -v okS="$ok_aeotex" \
    -v kk="$k_karman" -v kc="$k_cavity" '
{ if ($3 != "nan") { t[$2, $1] = $3; if (!(($2) in best) || $3 < best[$2]) best[$2] = $3 } }
function ns(name, per) {
    if (!((name in best) && ("empty" in best))) return -1
    return 1e9 * (best[name] - best["empty"]) / (per * s * rate)
}
function row(label, name, per, peer, peerper,   a, b, r, lo, hi, k, x) {
    a = ns(name, per)
    if (a < 0) { printf "  %-44s not measured\n", label; return }
    if (best[name] - best["empty"] < 0.2 || (peer != "" && (peer in best) && best[peer] - best["empty"] < 0.2))
        label = label " [under 0.2 s CPU: too short to time]"
    if (peer == "") { printf "  %-44s %7.2f ns per source-sample\n", label, a; return }
    b = ns(peer, peerper)
    if (b <= 0) { printf "  %-44s %7.2f ns per source-sample (peer not measured)\n", label, a; return }
    lo = 1e9; hi = 0
    for (k = 1; k <= reps; k++)
        if (((name, k) in t) && ((peer, k) in t) && (("empty", k) in t)) {
            x = (t[name, k] - t["empty", k]) / per / ((t[peer, k] - t["empty", k]) / peerper)
            if (x < lo) lo = x; if (x > hi) hi = x
        }
    printf "  %-44s %7.2f ns per source-sample, %.3f of %s (%.2f; per repetition %.3f-%.3f)\n",
        label, a, a / b, peer, b, lo, hi
}
END {
    printf "  empty patch: %.3f s CPU (fastest of %d)\n", best["empty"], reps
    row("[aeolian~ -d 0.01 -l 0.5] (model)", "aeolian", n, okK ? "windkarman" : "", n)
    if (okK) row("[windkarman~] (SDT, wind = U x " kk ")", "windkarman", n, "", n)
    row("[cavity~ -L 0.02 -D 0.01 -W 0.05] (model)", "cavity", n, okW ? "windcavity" : "", n)
    if (okW) row("[windcavity~] (SDT, wind = U x " kc ")", "windcavity", n, "", n)
    row("[cavity~] model / [aeolian~] model", "cavity", n, "aeolian", n)
    row("[cavity~ -texture cavity] (1 point source)", "cavity-tex", n, "", n)
    row("[aeolian~ -texture cylinder -n 10], per point", "aeolian-tex", 10 * int(n / 10), "", n)
    row("[cavity~] texture / [aeolian~] texture per point", "cavity-tex", n, "aeolian-tex", 10 * int(n / 10))
    if (!okA || !okC || !okT || !okS) print "  (an aero object failed its sounding check: see above)"
}' "$DIR/times.txt" | tee "$DIR/peer.txt"

# Instruction counts (valgrind's callgrind), which do not move with the
# machine's load: the aero objects only (SDT's would take minutes under
# valgrind), BENCH_PEER_IR_SOURCES (20) for 1 s, minus the empty patch.
# BENCH_PEER_CALLGRIND=0 leaves them out.
if [ "${BENCH_PEER_CALLGRIND:-1}" != 0 ] && command -v valgrind >/dev/null 2>&1; then
    S_SAVED=$S
    S=1
    NI=${BENCH_PEER_IR_SOURCES:-20}
    ir() { # NAME COUNT OBJECT: instructions of a 1 s render
        gen "$1-ir" "$2" 1 "" "$3"
        valgrind --tool=callgrind --callgrind-out-file="$DIR/$1.callgrind" \
            "$PD_BIN" -batch -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
            -path "$ROOT" -open "$DIR/$1-ir.pd" >"$DIR/$1-ir.log" 2>&1
        sed -n 's/^summary: //p' "$DIR/$1.callgrind"
    }
    e=$(ir empty 0 "aeolian~")
    a=$(ir aeolian "$NI" "aeolian~ -d $D_CYL -l $L_CYL")
    c=$(ir cavity "$NI" "cavity~ -L $L_CAV -D $D_CAV -W $W_CAV")
    ct=$(ir cavity-tex "$NI" "cavity~ -texture cavity -L $L_CAV -D $D_CAV -W $W_CAV")
    at=$(ir aeolian-tex "$((NI / 10))" "aeolian~ -texture cylinder -n 10 -l 0.3")
    # the sword: its texture and the airfoil self-noise band above it
    # (blade_noise.h), edge-on in the gusting wind
    as=$(ir aeolian-sword "$((NI / 10))" "aeolian~ -texture sword -n 10 -l 0.3")
    awk -v e="$e" -v a="$a" -v c="$c" -v ct="$ct" -v at="$at" -v as="$as" -v n="$NI" -v r="$RATE" 'BEGIN {
        ia = (a - e) / n / r; ic = (c - e) / n / r
        ict = (ct - e) / n / r; iat = (at - e) / (10 * int(n / 10)) / r
        ias = (as - e) / (10 * int(n / 10)) / r
        printf "  instructions per source-sample (callgrind, %d sources, 1 s): [aeolian~] %.1f, [cavity~] %.1f (%.2f x), [cavity~ -texture cavity] %.1f, [aeolian~ -texture] per point %.1f (%.2f x), [aeolian~ -texture sword] with its noise band per point %.1f (%.2f x the cylinder)\n",
            n, ia, ic, ic / ia, ict, iat, ict / iat, ias, ias / iat }' | tee -a "$DIR/peer.txt"
    S=$S_SAVED
fi
exit 0
