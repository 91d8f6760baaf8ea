# --- [cavity~] in real Pd ----------------------------------------------------
section "[cavity~]: Rossiter modes, depth resonance and lock-in in Pd"

# Rossiter (1964): f_m = (U/L)(m - 0.25)/(M + 1/0.57), M = U/343;
# quarter-wave depth mode f = c0 / (4 (D + 0.82 sqrt(L W / pi)))
rossiter_hz() {
    awk -v u="$1" -v l="$2" -v m="$3" 'BEGIN {
        printf "%.6g\n", u / l * (m - 0.25) / (u / 343 + 1 / 0.57) }'
}
band_around() { # F REL: "F*(1-REL) F*(1+REL)"
    awk -v f="$1" -v r="$2" 'BEGIN { printf "%g %g\n", f * (1 - r), f * (1 + r) }'
}

# 1. peaks at the Rossiter frequencies, two cavities and speeds (deep
# modes far away, so nothing locks)
for case in "10 0.02 0.01 0.05" "15 0.05 0.02 0.1"; do
    set -- $case
    name="cav-u$1-l$2"
    pd_render "$name" "cavity~ -L $2 -D $3 -W $4" 1 4000 "; aero-speed $1"
    for mode in 1 2 3; do
        f=$(rossiter_hz "$1" "$2" "$mode")
        set -- $(band_around "$f" 0.15) "$@"
        judge $ANALYZE peak "$OUT/$name.wav" --expect "$f" --tol 0.02 \
            --fmin "$1" --fmax "$2" \
            --smooth "$(awk -v f="$f" 'BEGIN{print f*0.04}')"
        shift 2
    done
done

# 2. lock-in: depth resonance tuned onto mode 2 (D + 0.82 a = c0 / (4 f_2))
f1=$(rossiter_hz 10 0.02 1)
f2=$(rossiter_hz 10 0.02 2)
depth=$(awk -v f="$f2" 'BEGIN { a = sqrt(0.02 * 0.05 / 3.14159265)
    printf "%.5f", 343 / (4 * f) - 0.82 * a }')
pd_render cav-locked "cavity~ -L 0.02 -D $depth -W 0.05" 1 4000 "; aero-speed 10"
judge $ANALYZE banddiff "$OUT/cav-locked.wav" $(band_around "$f1" 0.1) \
    $(band_around "$f2" 0.1) --min 15
judge $ANALYZE banddiff "$OUT/cav-u10-l0.02.wav" $(band_around "$f1" 0.1) \
    $(band_around "$f2" 0.1) --max 10
judge $ANALYZE leveldiff "$OUT/cav-u10-l0.02.wav" "$OUT/cav-locked.wav" --min 10

# 3. level: +12 dB per doubling of speed (amplitude ~ U^2);
# the paper's exponent 4 on request gives +24 dB
pd_render cav-u20 "cavity~ -L 0.02 -D 0.01 -W 0.05" 1 3000 "; aero-speed 20"
judge $ANALYZE leveldiff "$OUT/cav-u10-l0.02.wav" "$OUT/cav-u20.wav" --expect 12 --tol 1.5
pd_render cav-e4-u10 "cavity~ -exponent 4" 1 3000 "; aero-speed 10"
pd_render cav-e4-u20 "cavity~ -exponent 4" 1 3000 "; aero-speed 20"
judge $ANALYZE leveldiff "$OUT/cav-e4-u10.wav" "$OUT/cav-e4-u20.wav" --expect 24 --tol 1.5
# and -6 dB per doubling of distance
pd_render cav-r2 "cavity~ -L 0.02 -D 0.01 -W 0.05 -listener 0 2 0" 1 3000 "; aero-speed 10"
pd_render cav-r4 "cavity~ -L 0.02 -D 0.01 -W 0.05 -listener 0 4 0" 1 3000 "; aero-speed 10"
judge $ANALYZE leveldiff "$OUT/cav-r2.wav" "$OUT/cav-r4.wav" --expect -6 --tol 1

# and -stereo: each ear hears the field at its own distance (1/r, a
# compact source's far field, Curle 1955): ears 1 m and 2 m out of the
# opening, the far one 6 dB lower
pd_render cav-stereo "cavity~ -L 0.02 -D 0.01 -W 0.05 -stereo -ears 0 1 0 0 2 0" 2 3000 "; aero-speed 10"
L=$($ANALYZE level "$OUT/cav-stereo.wav" --ch 0 | sed 's/.*: \([-0-9.e]*\) dB.*/\1/')
judge $ANALYZE level "$OUT/cav-stereo.wav" --ch 1 --expect "$(awk -v l="$L" 'BEGIN{print l-6}')" --tol 1

# 4. texture mode: the shipped cavity texture plays, finite, and follows the
# same speed law (+12 dB per doubling, the texture read at v/v0)
pd_render cav-tex-u10 "cavity~ -texture cavity" 1 3000 "; aero-speed 10"
pd_render cav-tex-u20 "cavity~ -texture cavity" 1 3000 "; aero-speed 20"
log_clean "$OUT/cav-tex-u10.log" "[cavity~ -texture cavity] loads the shipped texture"
judge $ANALYZE finite "$OUT/cav-tex-u10.wav"
judge $ANALYZE leveldiff "$OUT/cav-tex-u10.wav" "$OUT/cav-tex-u20.wav" --expect 12 --tol 1.5
# texture mode honours -L: the shear-layer tone sits at St_L = f L / v
# (Rossiter 1964), so a cavity twice as long (the texture's L0 = 2 cm)
# sounds an octave lower at the same speed
pd_render cav-tex-L2 "cavity~ -L 0.02 -texture cavity -seed 3" 1 3000 "; aero-speed 10"
pd_render cav-tex-L4 "cavity~ -L 0.04 -texture cavity -seed 3" 1 3000 "; aero-speed 10"
judge $ANALYZE peakratio "$OUT/cav-tex-L2.wav" "$OUT/cav-tex-L4.wav" \
    --expect 0.5 --tol 0.05 --fmin 100 --fmax 1500 --smooth 15

# 5. a missing texture: a clear error, and the model still sounds
pd_render cav-missing "cavity~ -texture no-such-texture" 1 3000 "; aero-speed 10"
if grep -q "can't find texture 'no-such-texture'" "$OUT/cav-missing.log"; then
    pass "missing texture reported: $(grep -o "can't find.*" "$OUT/cav-missing.log" | head -1)"
else
    fail "no error for a missing texture"; cat "$OUT/cav-missing.log"
fi
judge $ANALYZE peak "$OUT/cav-missing.wav" --expect "$f2" --tol 0.02 \
    $(band_around "$f2" 0.15 | awk '{print "--fmin", $1, "--fmax", $2}') --smooth 20

# 6. bad input: hostile speeds and messages, finite output, errors reported
pd_render cav-bad "cavity~ -L -1 -D 0 -W nan -bogus" 1 2000 "; aero-speed 0" 0 \
    "300 ; aero-speed -10" "600 ; aero-speed 1e30" \
    "900 ; aero-obj length 0; aero-obj listener 1; aero-obj exponent 99; aero-obj texture cylinder" \
    "1200 ; aero-speed 10"
judge $ANALYZE finite "$OUT/cav-bad.wav" --max 1000
reports_at_least "$OUT/cav-bad.log" "[cavity~]" 7
pd_render cav-nan "$nan_expr|cavity~" 1 500 "; aero-speed 1"
judge $ANALYZE finite "$OUT/cav-nan.wav"

