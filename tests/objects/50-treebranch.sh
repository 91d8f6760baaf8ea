# --- [treebranch~] in real Pd -------------------------------------------------
section "[treebranch~]: branch sound of a tree in the wind (Matsuyama et al. 2005) in Pd"

# One vertical rod (1 m, diameter d) at the origin: the simplest tree. A
# stiffness of 1000 keeps it still, so the wind it feels is the wind given.
rod_tree() { # NAME D
    printf '# a single vertical branch\nbranch 0 -1 0 0 0 0 0 1 %s %s\n' \
        "$2" "$2" >"$OUT/$1.tree"
}
# the published law, written here independently of src/core: Roshko's
# St = 0.198 (1 - 19.7/Re) (Re > 260; Roshko 1954), f = St U / d
tone_hz() {
    awk -v u="$1" -v d="$2" 'BEGIN { re = 1.225 * u * d / 1.81e-5
        printf "%.6g\n", 0.198 * (1 - 19.7 / re) * u / d }'
}
rod_tree rod10 0.01
rod_tree rod5 0.005
TB="treebranch~ $ROOT/$OUT/rod10.tree -stiffness 1000"

# 1. a single vertical branch in a steady horizontal wind: the spectral peak
# at St U / d ~ 0.2 U / d, within 3 % (the frames' Gaussian windows give the
# tone a width of ~15 Hz, hence the smoothing)
pd_render tb-peak-u10 "$TB -listener 0 -5 0.5" 1 4000 "; aero-speed 10"
f=$(tone_hz 10 0.01)
judge $ANALYZE peak "$OUT/tb-peak-u10.wav" --expect "$f" --tol 0.03 \
    --fmin 100 --fmax 300 --smooth 8
pd_render tb-peak-u20 "treebranch~ $ROOT/$OUT/rod5.tree -stiffness 1000 -listener 0 -5 0.5" \
    1 4000 "; aero-speed 20"
f=$(tone_hz 20 0.005)
judge $ANALYZE peak "$OUT/tb-peak-u20.wav" --expect "$f" --tol 0.03 \
    --fmin 400 --fmax 1200 --smooth 16
# the wind turned by a 'wind' vector across the rod (along y; the inlet's
# signal gives the speed along it) makes the same tone
pd_render tb-peak-vec "$TB -listener 5 0 0.5" 1 4000 "; aero-speed 10; aero-obj wind 0 1 0"
judge $ANALYZE peak "$OUT/tb-peak-vec.wav" --expect "$(tone_hz 10 0.01)" \
    --tol 0.03 --fmin 100 --fmax 300 --smooth 8
# negative control: wind along the rod sheds nothing
pd_render tb-along "$TB -listener 5 0 0.5" 1 1000 "; aero-speed 10; aero-obj wind 0 0 1"
judge $ANALYZE level "$OUT/tb-along.wav" --max -100

# 2. level: +18 dB per doubling of the wind (amplitude ~ U^3, Curle 1955; the
# paper's I ~ U^6 read as an amplitude would give +36)
pd_render tb-u5 "$TB -listener 0 -5 0.5" 1 4000 "; aero-speed 5"
pd_render tb-u20 "$TB -listener 0 -5 0.5" 1 4000 "; aero-speed 20"
judge $ANALYZE leveldiff "$OUT/tb-u5.wav" "$OUT/tb-peak-u10.wav" --expect 18 --tol 1.5
judge $ANALYZE leveldiff "$OUT/tb-peak-u10.wav" "$OUT/tb-u20.wav" --expect 18 --tol 1.5

# 3. -6 dB per doubling of distance (1/r)
pd_render tb-r10 "$TB -listener 0 -10 0.5" 1 3000 "; aero-speed 10"
pd_render tb-r20 "$TB -listener 0 -20 0.5" 1 3000 "; aero-speed 10"
judge $ANALYZE leveldiff "$OUT/tb-peak-u10.wav" "$OUT/tb-r10.wav" --expect -6 --tol 1
judge $ANALYZE leveldiff "$OUT/tb-r10.wav" "$OUT/tb-r20.wav" --expect -6 --tol 1

# 4. absolute level (Curle, a lift dipole coherent over 3 d, averaged over
# directions): p^2 = (rho U^3 St C_L' / (4 c0))^2 (3 d) l / 3 / r^2 with
# C_L' = 0.45, plus the tail (1/4 of the tone's power with alpha 2)
expect_db=$(awk 'BEGIN { u = 10; d = 0.01; l = 1; r = 5
    re = 1.225 * u * d / 1.81e-5; st = 0.198 * (1 - 19.7 / re)
    a = 1.225 * u^3 * st * 0.45 / (4 * 343); p2 = a * a * 3 * d * l / 3
    p2 = p2 * 1.25 / (r * r)
    printf "%.3f", 10 * log(p2 / 4e-10) / log(10) }')
judge $ANALYZE level "$OUT/tb-peak-u10.wav" --expect "$expect_db" --tol 1

# 5. Doppler: the listener runs at 20 m/s towards the tree: every frequency
# rises by (c0 + v) / c0 = 1.0583 (the stylus reads the delay line faster)
pd_render tb-doppler "$TB -listener 0 -65 0.5" 1 3000 "; aero-speed 10" 0 \
    "0 ; aero-obj ramp 3000; aero-obj listener 0 -5 0.5"
judge $ANALYZE peakratio "$OUT/tb-peak-u10.wav" "$OUT/tb-doppler.wav" \
    --expect 1.0583 --tol 0.01 --fmin 100 --fmax 300 --smooth 8

# 6. the cardioid mic ((1 + cos mu)/2)^k: facing sideways halves the
# pressure with k 1 (-6 dB)
pd_render tb-mic "$TB -listener 0 -5 0.5 -mic 1 0 0 -k 1" 1 3000 "; aero-speed 10"
judge $ANALYZE leveldiff "$OUT/tb-peak-u10.wav" "$OUT/tb-mic.wav" --expect -6 --tol 1

# 7. stereo: the ear twice as far is 6 dB softer
pd_render tb-stereo "$TB -stereo -ears 0 -5 0.5 0 -10 0.5" 2 3000 "; aero-speed 10"
judge $ANALYZE level "$OUT/tb-stereo.wav" --ch 0 --expect "$expect_db" --tol 1
judge $ANALYZE level "$OUT/tb-stereo.wav" --ch 1 \
    --expect "$(awk -v e="$expect_db" 'BEGIN { print e - 6.02 }')" --tol 1

# 8. no clicks where frames join, even when the wind jumps from 5 to 20 m/s
# (a line~ step) and the listener moves
pd_render tb-steps "$TB -listener 0 -5 0.5" 1 3000 "; aero-speed 5" 0 \
    "1000 ; aero-speed 20" "2000 ; aero-obj listener 0 -3 0.5"
judge $ANALYZE clicks "$OUT/tb-steps.wav" --skip 0.2 --max 3

# 9. the shipped trees load and sound in a wind; no error in the log
for t in small medium large; do
    pd_render "tb-$t" "treebranch~ $t -listener 0 -12 1.7" 1 1500 "; aero-speed 8"
    log_clean "$OUT/tb-$t.log" "[treebranch~ $t] loads trees/$t.tree"
    judge $ANALYZE finite "$OUT/tb-$t.wav"
    judge $ANALYZE level "$OUT/tb-$t.wav" --min 30
done
# no wind, no sound
pd_render tb-still "treebranch~ small" 1 1000 "; aero-speed 0"
judge $ANALYZE level "$OUT/tb-still.wav" --max -100

# 10. a tree file with bad lines: each reported with its line number, the
# good lines load and sound
cat >"$OUT/bad.tree" <<'EOF'
# line 1: a comment
branch 0 -1 0 0 0 0 0 1 0.01 0.01
branch 1 0 0 0 1 0 1 2
branch 2 7 0 0 1 0 1 2 0.01 0.01
twig 3 0 0 0 1 0 1 2 0.01 0.01
branch 4 0 0 0 1 0 0 2 nan 0.01
leaf 9 0 0 1 0 0.1 1 0.05 0.03
EOF
pd_render tb-badfile "treebranch~ $ROOT/$OUT/bad.tree -stiffness 1000 -listener 0 -5 0.5" \
    1 2000 "; aero-speed 10"
for line in 3 4 5 6 7; do
    if grep -q "bad.tree:$line:" "$OUT/tb-badfile.log"; then
        pass "bad line $line reported: $(grep -o "bad.tree:$line:.*" "$OUT/tb-badfile.log" | head -1)"
    else
        fail "bad line $line not reported"; cat "$OUT/tb-badfile.log"
    fi
done
if grep -q "bad.tree:2:" "$OUT/tb-badfile.log"; then
    fail "the good line 2 was reported"
else
    pass "the good line 2 is not reported (negative control)"
fi
judge $ANALYZE peak "$OUT/tb-badfile.wav" --expect "$(tone_hz 10 0.01)" \
    --tol 0.03 --fmin 100 --fmax 300 --smooth 8

# 11. a missing file and a file without any valid branch: a clear error,
# silence, the object alive (a later 'open' works)
printf 'leaf 0 0 0 0 0 0 1 1 1\n' >"$OUT/empty.tree"
pd_render tb-missing "treebranch~ no-such-tree" 1 2000 "; aero-speed 10" 0 \
    "1000 ; aero-obj open $ROOT/$OUT/rod10.tree"
if grep -q "can't find tree 'no-such-tree'" "$OUT/tb-missing.log"; then
    pass "missing tree reported: $(grep -o "can't find tree[^(]*" "$OUT/tb-missing.log" | head -1)"
else
    fail "no error for a missing tree"; cat "$OUT/tb-missing.log"
fi
judge $ANALYZE finite "$OUT/tb-missing.wav"
# sounding after the 'open' at 1 s (the rod's tone)
judge $ANALYZE peak "$OUT/tb-missing.wav" --skip 1.1 --expect "$(tone_hz 10 0.01)" \
    --tol 0.03 --fmin 100 --fmax 300 --smooth 8
pd_render tb-empty "treebranch~ $ROOT/$OUT/empty.tree" 1 1000 "; aero-speed 10"
if grep -q "no valid branch" "$OUT/tb-empty.log"; then
    pass "a tree without branches is reported: $(grep -o "no valid branch.*" "$OUT/tb-empty.log" | head -1)"
else
    fail "no error for a tree without branches"; cat "$OUT/tb-empty.log"
fi
judge $ANALYZE level "$OUT/tb-empty.wav" --max -100

# 12. hostile input: NaN speed, absurd wind and messages; finite output and
# every bad value reported
pd_render tb-nan "$nan_expr|treebranch~ small" 1 500 "; aero-speed 1"
judge $ANALYZE finite "$OUT/tb-nan.wav"
pd_render tb-bad "treebranch~ small -seed -3 -alpha 0 -k 99 -bogus 2" 1 1500 \
    "; aero-speed 1e30; aero-obj gain 1e9; aero-obj listener 1 2; aero-obj stiffness 0; aero-obj beta 9; aero-obj ears 1 2 3 4 5 6; aero-obj wind 1 2"
judge $ANALYZE finite "$OUT/tb-bad.wav" --max 1e4
reports_at_least "$OUT/tb-bad.log" "[treebranch~]" 10
