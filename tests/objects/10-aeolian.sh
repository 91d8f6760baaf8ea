# --- [aeolian~] in real Pd ---------------------------------------------------
section "[aeolian~]: Strouhal/Reynolds model in Pd"

# 1. the peak sits at St(Re) U / d (laminar and subcritical wakes)
for case in "10 0.01" "20 0.005" "30 0.003" "2 0.0005" "6 0.0004"; do
    set -- $case
    f=$(tone_hz "$1" "$2")
    name="peak-u$1-d$2"
    pd_render "$name" "aeolian~ -d $2" 1 4000 "; aero-speed $1"
    judge $ANALYZE peak "$OUT/$name.wav" --expect "$f" --tol 0.02 \
        --fmin "$(awk -v f="$f" 'BEGIN{print f/2}')" \
        --fmax "$(awk -v f="$f" 'BEGIN{print f*1.5}')" \
        --smooth "$(awk -v f="$f" 'BEGIN{print f*0.04}')"
done

# the wake noise widens with Re: a nearly pure tone in the laminar wake
# (Re 68), a band of several percent once turbulent (Re 6800, 6100)
judge $ANALYZE width "$OUT/peak-u2-d0.0005.wav" --fmin 300 --fmax 900 --max 0.015
judge $ANALYZE width "$OUT/peak-u10-d0.01.wav" --fmin 100 --fmax 300 --min 0.03
judge $ANALYZE width "$OUT/peak-u30-d0.003.wav" --fmin 1000 --fmax 3000 --min 0.03

# 2. level: p ~ U^3 C_L'(Re) St(Re) (tests/laws.sh), twice
pd_render lvl-u5 "aeolian~ -d 0.01" 1 3000 "; aero-speed 5"
pd_render lvl-u10 "aeolian~ -d 0.01" 1 3000 "; aero-speed 10"
pd_render lvl-u20 "aeolian~ -d 0.01" 1 3000 "; aero-speed 20"
for pair in "5 10" "10 20"; do
    set -- $pair
    judge $ANALYZE leveldiff "$OUT/lvl-u$1.wav" "$OUT/lvl-u$2.wav" \
        --expect "$(level_step_db "$1" "$2" 0.01)" --tol 1.5
done

# 3. level: -6 dB per doubling of distance (p ~ 1/r)
pd_render dist-1 "aeolian~ -d 0.01 -l 0.2" 1 3000 "; aero-speed 10; aero-obj listener 0 1 0"
pd_render dist-2 "aeolian~ -d 0.01 -l 0.2" 1 3000 "; aero-speed 10; aero-obj listener 0 2 0"
pd_render dist-4 "aeolian~ -d 0.01 -l 0.2" 1 3000 "; aero-speed 10; aero-obj listener 0 4 0"
judge $ANALYZE leveldiff "$OUT/dist-1.wav" "$OUT/dist-2.wav" --expect -6 --tol 1
judge $ANALYZE leveldiff "$OUT/dist-2.wav" "$OUT/dist-4.wav" --expect -6 --tol 1

# 4. absolute level (Curle): p_rms = rho U^3 St C_L' L_c sqrt(N) / (4 c0 r)
# with C_L'(Re) of Norberg's (2003) fit, L_c = 3 d, N = l / L_c segments; a
# short cylinder (l = 3 d, one segment) 2 m away across the flow
expect_db=$(awk -v cl="$(norberg_lift_rms "$(speed_re 10 0.01)")" 'BEGIN { u = 10; d = 0.01; re = 1.225 * u * d / 1.81e-5
    st = 0.198 * (1 - 19.7 / re); p = 1.225 * u^3 * st * cl * 3 * d / (4 * 343 * 2)
    printf "%.3f", 20 * log(p / 20e-6) / log(10) }')
pd_render abs-level "aeolian~ -d 0.01 -l 0.03" 1 3000 "; aero-speed 10; aero-obj listener 0 2 0"
judge $ANALYZE level "$OUT/abs-level.wav" --expect "$expect_db" --tol 1

# 5. no tone below the shedding onset (Re 34), a tone just above it (Re 68)
pd_render onset-below "aeolian~ -d 0.0005" 1 2000 "; aero-speed 1"
pd_render onset-above "aeolian~ -d 0.0005" 1 2000 "; aero-speed 2"
judge $ANALYZE level "$OUT/onset-below.wav" --max -100
judge $ANALYZE level "$OUT/onset-above.wav" --min -30

# 6. directivity: lift (f) radiates across the flow, drag (2 f) along it
f=$(tone_hz 10 0.01)
pd_render dir-along "aeolian~ -d 0.01" 1 4000 "; aero-speed 10; aero-obj listener 1 0 0"
judge $ANALYZE peak "$OUT/dir-along.wav" --expect "$(awk -v f="$f" 'BEGIN{print 2*f}')" \
    --tol 0.02 --fmin 50 --fmax 1000 --smooth "$(awk -v f="$f" 'BEGIN{print f*0.08}')"
pd_render dir-across "aeolian~ -d 0.01" 1 3000 "; aero-speed 10; aero-obj listener 0 1 0"
# the drag tone is about 10x weaker in force, x2 in rate: -14 dB re lift
judge $ANALYZE leveldiff "$OUT/dir-across.wav" "$OUT/dir-along.wav" --max -10 --min -18

# 7. Doppler: a listener approaching at v hears f (c0 + v) / c0
pd_render dop-static "aeolian~ -d 0.01 -seed 7" 1 2000 "; aero-speed 10; aero-obj listener 0 50 0"
pd_render dop-moving "aeolian~ -d 0.01 -seed 7" 1 2000 "; aero-speed 10; aero-obj listener 0 50 0" 0 \
    "0 ; aero-obj ramp 2000; aero-obj listener 0 10 0"
judge $ANALYZE peakratio "$OUT/dop-static.wav" "$OUT/dop-moving.wav" \
    --expect "$(awk 'BEGIN{print (343 + 20) / 343}')" --tol 0.01 \
    --fmin 100 --fmax 400 --smooth 8

# 8. stereo: each ear hears its own distance
pd_render stereo "aeolian~ -d 0.01 -l 0.2 -stereo" 2 3000 "; aero-speed 10; aero-obj ears 0 1 0 0 2 0"
L=$($ANALYZE level "$OUT/stereo.wav" --ch 0 | sed 's/.*: \([-0-9.e]*\) dB.*/\1/')
judge $ANALYZE level "$OUT/stereo.wav" --ch 1 --expect "$(awk -v l="$L" 'BEGIN{print l-6}')" --tol 1

# 9. bad input: speeds of 0, negative, huge and NaN give finite output
pd_render bad-speeds "aeolian~" 1 2000 "; aero-speed 0" 0 \
    "400 ; aero-speed -10" "800 ; aero-speed 1e30" "1200 ; aero-speed 0" \
    "1600 ; aero-speed 10"
judge $ANALYZE finite "$OUT/bad-speeds.wav" --max 1000
if grep -q "Mach 0.3" "$OUT/bad-speeds.log"; then
    pass "a speed above Mach 0.3 is clamped with a warning"
else
    fail "no Mach 0.3 warning for a huge speed"
fi
pd_render negative-speed "aeolian~ -d 0.01" 1 4000 "; aero-speed -10"
judge $ANALYZE peak "$OUT/negative-speed.wav" --expect "$f" --tol 0.02 \
    --fmin 100 --fmax 400 --smooth 8
# NaN: inf - inf from [expr~] (checked to be NaN by the negative control)
pd_render nan-source "$nan_expr" 1 500 "; aero-speed 1"
judge_fails $ANALYZE finite "$OUT/nan-source.wav"
pd_render nan-speed "$nan_expr|aeolian~" 1 500 "; aero-speed 1"
judge $ANALYZE finite "$OUT/nan-speed.wav"
pd_render bad-messages "aeolian~ -d -1 -l 0 -bogus 3" 1 1000 \
    "; aero-speed 10; aero-obj diameter 0; aero-obj listener 1 2; aero-obj gain 1e9; aero-obj ears 1 2 3 4 5 6; aero-obj ramp -5"
judge $ANALYZE finite "$OUT/bad-messages.wav"
judge $ANALYZE level "$OUT/bad-messages.wav" --min 20
reports_at_least "$OUT/bad-messages.log" "[aeolian~]" 8

# 10. no clicks: a speed ramp, then diameter, listener and gain changes
pd_render ramps "aeolian~ -d 0.01" 1 3000 "; aero-speed 5" 0 \
    "300 ; aero-speed 25 1000" "1500 ; aero-obj diameter 0.02" \
    "2000 ; aero-obj listener 0 0.5 0" "2500 ; aero-obj gain 12"
judge $ANALYZE clicks "$OUT/ramps.wav" --max 3
# negative control: an unramped gain jump on a sine must count as a click
pd_render click-control "osc~|*~ 0.1" 1 1000 "; aero-speed 1000" 1 "500 ; aero-obj 1"
judge_fails $ANALYZE clicks "$OUT/click-control.wav" --max 3

# 11. another sample rate: the tone stays at St U / d
pd_render_sr 96000 sr96k "aeolian~ -d 0.005" 1 3000 "; aero-speed 20"
judge $ANALYZE peak "$OUT/sr96k.wav" --expect "$(tone_hz 20 0.005)" --tol 0.02 \
    --fmin 400 --fmax 1200 --smooth 30

