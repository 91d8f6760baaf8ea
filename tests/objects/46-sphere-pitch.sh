# --- [body~]: the sphere texture at its published pitch (issue 39) ----------------
section "[body~]: a whirled ball sounds at the subcritical sphere's St"

# textures/sphere.wav keeps its 3D flow's force history and has its time
# axis scaled to the subcritical sphere's St 0.2 (`--calibrate sphere`;
# Sakamoto and Haniu 1990, Kim and Durbin 1988: the large-scale wake sheds
# at St ~0.2 for 800 < Re < 2e5; textures/README.md). A calibrated number
# is checked where it is heard: through [body~] in Pd. What the
# calibration does not set (the mean drag, the Doppler shift) is checked
# in 45-body.sh and below.
sphere_meta() { build/aerotex info textures/sphere.wav | sed -n "s/^$1=//p"; }
st_ref=$(sphere_meta calibration_st)
# the shipped texture was made calibrated, to the published value
in_range "sphere texture's reference St (calibration_st)" "$st_ref" 0.18 0.20 \
    "Sakamoto and Haniu 1990: ~0.2"
in_range "sphere texture's St as held (st)" "$(sphere_meta st)" \
    "$(awk -v s="$st_ref" 'BEGIN { print 0.99 * s }')" \
    "$(awk -v s="$st_ref" 'BEGIN { print 1.01 * s }')" \
    "calibration_st +-1 % (the rate is a whole number of Hz)"

# A 5 cm ball (the 10 cm texture at -scale 0.5) whirled on a 1.2 m cord at
# 2 and 3 turns/s (15.1 and 22.6 m/s), heard 40 m away in the plane of
# the circle, so that every turn it comes at the listener and goes away
# (Doppler): over 8 s its spectral peak (smoothed over a tenth of the
# tone) lies at St v / d of the calibrated St within 5 %
sp_window() { # PHASE TURN_S: start of the 1/8-turn window centred on that
    # phase of the second turn, in the recording, s (as 45-body.sh)
    awk -v p="$1" -v T="$2" 'BEGIN { print (p + 1 - 1/16) * T - 0.2 + 40 / 343 }'
}
for turns in 2 3; do
    v=$(awk -v n="$turns" 'BEGIN { print 2 * 3.14159265 * 1.2 * n }')
    f=$(awk -v s="$st_ref" -v v="$v" 'BEGIN { printf "%.2f", s * v / 0.05 }')
    PD_EXTRA="tests/pd/aero-whirl 1.2 $turns 5" \
        pd_render "sp-whirl-$turns" "body~ -texture sphere -scale 0.5 -seed 1" \
        1 9000 "; aero-obj listener 0 -40 0"
    judge $ANALYZE finite "$OUT/sp-whirl-$turns.wav" --max 10
    judge $ANALYZE peak "$OUT/sp-whirl-$turns.wav" --expect "$f" --tol 0.05 \
        --skip 1 --fmin "$(awk -v f="$f" 'BEGIN { print f / 3 }')" \
        --fmax "$(awk -v f="$f" 'BEGIN { print f * 3 }')" --nfft 32768 \
        --smooth "$(awk -v f="$f" 'BEGIN { print 0.3 * f }')"
done
# and with Doppler: at 3 turns/s the 1/8-turn windows coming at the
# listener hold the spectrum of those going away stretched by
# (c0 + v k) / (c0 - v k), k = sin(pi/8) / (pi/8) (+-2 %, as 45-body.sh)
v3=$(awk 'BEGIN { print 2 * 3.14159265 * 1.2 * 3 }')
sp_doppler=$(awk -v v="$v3" 'BEGIN { k = sin(3.14159265 / 8) / (3.14159265 / 8)
    printf "%.5f", (343 + v * k) / (343 - v * k) }')
judge $ANALYZE scaleratio "$OUT/sp-whirl-3.wav" "$OUT/sp-whirl-3.wav" \
    --skip "$(sp_window 1 0.333333)" --skip2 "$(sp_window 0.5 0.333333)" \
    --dur 0.0417 --every 0.333333 --count 20 --nfft 2048 --fmin 100 \
    --fmax 3000 --expect "$sp_doppler" --tol 0.02
