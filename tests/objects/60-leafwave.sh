# --- [leafwave~] in real Pd --------------------------------------------------
section "[leafwave~]: leaves of a tree in the wind (Matsuyama et al. 2005) in Pd"

# tests/data/leafwave-small.tree: 32 branches, 400 leaves of 8 x 5 cm (its
# header says how it was made); the trunk runs from z = 0 to 3 m, so its
# midpoint, where distances are measured from, is (0, 0, 1.5)
LW_TREE=tests/data/leafwave-small.tree
LW="leafwave~ $LW_TREE -seed 1"

# 1. wind makes leaves collide and rub: a sound, finite, at a plausible
# level (10 m from the trunk: rustling is ~30-60 dB SPL nearby)
pd_render lw-u8 "$LW" 1 2000 "; aero-speed 8"
log_clean "$OUT/lw-u8.log" "[leafwave~] loads $LW_TREE"
judge $ANALYZE finite "$OUT/lw-u8.wav" --max 10
judge $ANALYZE level "$OUT/lw-u8.wav" --min 30 --max 75
# notes start at zero crossings with a 1 ms attack (paper: no pulse-shaped
# noise): no 2 ms window's sharpest jump stands out from its neighbours' by
# more than 4x (collisions are impulsive, so not the 3x of a steady tone)
judge $ANALYZE clicks "$OUT/lw-u8.wav" --max 4

# 2. no wind, leaves apart: silence (the motion is zero, no pair keys on)
pd_render lw-u0 "$LW" 1 1000 "; aero-speed 0"
judge $ANALYZE level "$OUT/lw-u0.wav" --max 0
# negative control: the same check fails on the sound in wind
judge_fails $ANALYZE level "$OUT/lw-u8.wav" --max 0

# 3. more wind, louder: leaf amplitudes follow the drag load (U^2) and
# flutter faster, collisions are harder and more frequent; from 8 to
# 16 m/s at least +3 dB (the unit test counts the key ons)
pd_render lw-u16 "$LW" 1 2000 "; aero-speed 16"
judge $ANALYZE leveldiff "$OUT/lw-u8.wav" "$OUT/lw-u16.wav" --min 3
# `wind vx vy vz` turns the wind (the inlet stays its speed, as in
# [treebranch~]): across the crown instead of along x, still rustling
pd_render lw-wind "$LW" 1 2000 "; aero-speed 8; aero-obj wind 0 1 0"
judge $ANALYZE level "$OUT/lw-wind.wav" --min 30

# 4. 1/r: twice the distance from the trunk, -6 dB (the same seed, so the
# same leaves; only the delay and the level differ)
pd_render lw-r10 "$LW -listener 0 -10 1.5" 1 2000 "; aero-speed 8"
pd_render lw-r20 "$LW -listener 0 -20 1.5" 1 2000 "; aero-speed 8"
judge $ANALYZE leveldiff "$OUT/lw-r10.wav" "$OUT/lw-r20.wav" --expect -6.02 --tol 0.5

# 5. -stereo: two ears, both sound; the cardioid mic turned away silences
pd_render lw-stereo "$LW -stereo -ears -0.1 -10 1.5 0.1 -10 1.5" 2 1500 "; aero-speed 8"
judge $ANALYZE level "$OUT/lw-stereo.wav" --ch 0 --min 30
judge $ANALYZE level "$OUT/lw-stereo.wav" --ch 1 --min 30
pd_render lw-away "$LW -mic 0 -1 0 -k 1" 1 1500 "; aero-speed 8"
judge $ANALYZE level "$OUT/lw-away.wav" --max 0

# 6. a missing tree file: a clear error, the object is created and silent
pd_render lw-missing "leafwave~ no-such.tree" 1 500 "; aero-speed 8"
if grep -q "can't find tree 'no-such.tree'" "$OUT/lw-missing.log" &&
    ! grep -q "couldn't create" "$OUT/lw-missing.log"; then
    pass "missing tree reported, object created: $(grep -o "can't find.*" "$OUT/lw-missing.log" | head -1)"
else
    fail "missing tree file"; cat "$OUT/lw-missing.log"
fi
judge $ANALYZE level "$OUT/lw-missing.wav" --max 0

# 7. a tree file with bad lines: each reported with its line number, the
# rest loads and plays
pd_render lw-badfile "leafwave~ tests/data/leafwave-bad.tree" 1 500 "; aero-speed 8"
for line in 5 7 8 9; do
    if grep -q "leafwave-bad.tree:$line:" "$OUT/lw-badfile.log"; then
        pass "bad tree line $line reported: $(grep -o "leafwave-bad.tree:$line:.*" "$OUT/lw-badfile.log")"
    else
        fail "bad tree line $line not reported"; cat "$OUT/lw-badfile.log"
    fi
done
judge $ANALYZE finite "$OUT/lw-badfile.wav"

# 8. bad input: hostile flags, messages and speeds; finite output, every
# bad value reported with the object's name
pd_render lw-bad "$LW -gain nan -stiffness 0 -bogus 3" 1 2000 "; aero-speed 8" 0 \
    "200 ; aero-speed -50" "400 ; aero-speed 1e30" \
    "600 ; aero-obj wind 1 2; aero-obj listener 1; aero-obj beta 9; aero-obj tables 0; aero-obj reach -1" \
    "800 ; aero-obj ears 1 2 3 4 5 6; aero-obj voices 0; aero-obj fm 1e9; aero-obj open no-such.tree" \
    "1200 ; aero-obj open $LW_TREE; aero-speed 10"
judge $ANALYZE finite "$OUT/lw-bad.wav" --max 100
reports_at_least "$OUT/lw-bad.log" "[leafwave~]" 12
pd_render lw-nan "$nan_expr|$LW" 1 500 "; aero-speed 8"
judge $ANALYZE finite "$OUT/lw-nan.wav"
