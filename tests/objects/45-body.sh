# --- [body~]: 3D bodies from object textures (Dobashi et al. 2003, 3D case) ---------
section "[body~]: a sphere and a club from 3D object textures"

texture_meta() { # FILE KEY: a value of a texture's metadata
    build/aerotex info "textures/$1.wav" | sed -n "s/^$2=//p"
}

# 1. a sphere at rest in a wind through the inlet: U^3 (+18.06 dB per
#    doubling of speed), pitch St v / d (the whole spectrum moves with v:
#    centroid x2), 1/r (-6.02 dB per doubling of distance)
for u in 10 20; do
    pd_render "bd-u$u" "body~ -texture sphere -seed 1" 1 2000 \
        "; aero-speed $u; aero-obj listener 0 3 0"
done
judge $ANALYZE finite "$OUT/bd-u10.wav" --max 10
judge $ANALYZE leveldiff "$OUT/bd-u10.wav" "$OUT/bd-u20.wav" --expect 18.06 --tol 0.3
# (the window holds the whole band at both speeds: the calibrated texture,
# 5204 Hz, reaches ~2.5 kHz at 20 m/s)
judge $ANALYZE centroidratio "$OUT/bd-u10.wav" "$OUT/bd-u20.wav" --expect 2 \
    --tol 0.05 --fmin 5 --fmax 3000 --nfft 8192
pd_render bd-r6 "body~ -texture sphere -seed 1" 1 2000 \
    "; aero-speed 10; aero-obj listener 0 6 0"
judge $ANALYZE leveldiff "$OUT/bd-u10.wav" "$OUT/bd-r6.wav" --expect -6.02 --tol 0.3
# the sphere's measured St (aerotex info): its sound peaks there
st_sphere=$(texture_meta sphere st)
judge $ANALYZE peak "$OUT/bd-u10.wav" \
    --expect "$(awk -v s="$st_sphere" 'BEGIN { print s * 10 / 0.1 }')" \
    --tol 0.25 --fmin 5 --fmax 200 --nfft 32768 --smooth 3

# 1b. the shipped sphere against published data (aerotex info; Cd on the
#     frontal area): issue 17 asks for at least 16 cells per d, and the
#     subcritical sphere's mean Cd is 0.4-0.55 (Achenbach 1972, 1974).
#     The drag is the flow's own; its St is calibrated to the subcritical
#     sphere's 0.2 (`--calibrate sphere`) and checked in Pd by
#     46-sphere-pitch.sh
in_range "sphere cells per diameter" "$(texture_meta sphere grid)" 16 1000 \
    "issue 17: at least 16"
in_range "sphere mean Cd" "$(texture_meta sphere cd)" 0.4 0.55 \
    "Achenbach 1972, 1974"

# 2. a sphere whirled on a 10 m cord at 0.6 turns/s (37.7 m/s) in still
#    air, heard 40 m away in the plane of the circle: its sound rises by
#    c0 / (c0 - v) while it comes at the listener and falls by c0 / (c0 + v)
#    as it leaves, each turn. The texture is the unit tests' fixture
#    (build/tests/sine-sphere.wav: a sphere whose drag is a 100 Hz sine at
#    10 m/s), so the pitch is one peak: 377 Hz at 37.7 m/s before Doppler.
#    The sphere starts at (10, 0, 0) when the patch loads (200 ms before
#    recording) and turns anticlockwise: fastest towards the listener (-y)
#    at phase 1/2 of a turn, away at phase 0; windows of 1/8 turn centred
#    there in the second turn, heard 40 m / c0 later
whirl_window() { # PHASE [TURN_S]: start of the 1/8-turn window centred on
    # that phase of the second turn, in the recording, s (turn 1/0.6 s)
    awk -v p="$1" -v T="${2:-1.6666667}" 'BEGIN { print (p + 1 - 1/16) * T - 0.2 + 40 / 343 }'
}
whirl_peak() { # FILE PHASE: the peak frequency in that window, Hz
    $ANALYZE peak "$1" --skip "$(whirl_window "$2")" --dur 0.2083 \
        --fmin 200 --fmax 600 --nfft 8192 | sed -n 's/.*: \([0-9.e+-]*\) Hz.*/\1/p'
}
doppler_check() { # FILE WANT LABEL
    up=$(whirl_peak "$1" 0.5) down=$(whirl_peak "$1" 1)
    awk -v a="$up" -v b="$down" -v w="$2" \
        'BEGIN { r = a / b; exit !(b > 0 && r > w * 0.98 && r < w * 1.02) }'
}
want=$(awk 'BEGIN { v = 2 * 3.14159265 * 10 * 0.6; print (343 + v) / (343 - v) }')
if [ -f build/tests/sine-sphere.wav ]; then
    PD_EXTRA="tests/pd/aero-whirl 10 0.6 5" \
        pd_render bd-whirl "body~ -texture build/tests/sine-sphere -seed 2" 1 4000 \
        "; aero-obj listener 0 -40 0"
    judge $ANALYZE finite "$OUT/bd-whirl.wav" --max 10
    if doppler_check "$OUT/bd-whirl.wav" "$want"; then
        pass "whirled sphere: $up Hz coming, $down Hz going: ratio $(awk -v a="$up" -v b="$down" 'BEGIN { printf "%.4f", a / b }') (Doppler (c0 + v)/(c0 - v) = $want +- 2%)"
    else
        fail "whirled sphere: $up Hz coming, $down Hz going, want a ratio $want +- 2%"
    fi
    # negative control: heard from above the centre of the circle nothing
    # comes or goes
    PD_EXTRA="tests/pd/aero-whirl 10 0.6 5" \
        pd_render bd-whirl-centre "body~ -texture build/tests/sine-sphere -seed 2" 1 4000 \
        "; aero-obj listener 0 0 1"
    if doppler_check "$OUT/bd-whirl-centre.wav" "$want"; then
        fail "negative control: the whirl heard from its centre shows the Doppler ratio"
    else
        pass "negative control: from the centre of the circle $up Hz and $down Hz, not a ratio of $want"
    fi
else
    fail "build/tests/sine-sphere.wav is missing (written by test_body)"
fi
# 2b. the shipped sphere as a 5 cm ball (scale 0.5) whirled on a 1.2 m
#     cord at 2.5 turns/s (18.85 m/s, issue 17), as [aero.whirl~] does:
#     - heard from above the centre (no Doppler), its sound peaks where a
#       ball at rest in a wind of 18.85 m/s peaks (+-5 %, the spectral
#       peak smoothed over 0.3 of the tone, the width over which the
#       texture's St is measured: a broad band's single lines scatter),
#       and both at St v / d of the texture's
#       measured St (aerotex info), within test 1's 25 %;
#     - heard 40 m away in the circle's plane, the 1/8-turn windows coming
#       at the listener hold the same spectrum as those going away
#       stretched by (c0 + v k) / (c0 - v k), k = sin(pi/8) / (pi/8) the
#       mean cosine over a window: 1.113 (the Doppler shift is exact
#       physics; +-2 %, as the sine whirl above). Twenty turns from the
#       second on; aero-analyze scaleratio matches the two log spectra
#       over 100-3000 Hz, where the ball's broadband sound lies (its
#       St tone, 44 Hz, is too low to be read in a 50 ms window)
v_ball=$(awk 'BEGIN { print 2 * 3.14159265 * 1.2 * 2.5 }')
f_ball=$(awk -v s="$st_sphere" -v v="$v_ball" 'BEGIN { print s * v / 0.05 }')
PD_EXTRA="tests/pd/aero-whirl 1.2 2.5 5" \
    pd_render bd-ball-above "body~ -texture sphere -scale 0.5 -seed 1" 1 9000 \
    "; aero-obj listener 0 0 1"
PD_EXTRA="tests/pd/aero-whirl 1.2 2.5 5" \
    pd_render bd-ball-plane "body~ -texture sphere -scale 0.5 -seed 1" 1 9000 \
    "; aero-obj listener 0 -40 0"
pd_render bd-ball-wind "body~ -texture sphere -scale 0.5 -seed 1" 1 9000 \
    "; aero-obj wind $v_ball 0 0; aero-obj listener 0 1.2 1"
judge $ANALYZE finite "$OUT/bd-ball-plane.wav" --max 10
smooth_ball=$(awk -v f="$f_ball" 'BEGIN { print 0.3 * f }')
judge $ANALYZE peakratio "$OUT/bd-ball-wind.wav" "$OUT/bd-ball-above.wav" \
    --expect 1 --tol 0.05 --skip 1 --fmin 10 --fmax 400 --nfft 32768 \
    --smooth "$smooth_ball"
judge $ANALYZE peak "$OUT/bd-ball-above.wav" --expect "$f_ball" --tol 0.25 \
    --skip 1 --fmin 10 --fmax 400 --nfft 32768 --smooth "$smooth_ball"
ball_doppler=$(awk -v v="$v_ball" 'BEGIN { k = sin(3.14159265 / 8) / (3.14159265 / 8)
    printf "%.5f", (343 + v * k) / (343 - v * k) }')
ball_scale() { # FILE: spectrum coming at the listener over going away
    $ANALYZE scaleratio "$1" "$1" --skip "$(whirl_window 1 0.4)" \
        --skip2 "$(whirl_window 0.5 0.4)" --dur 0.05 --every 0.4 --count 20 \
        --nfft 2048 --fmin 100 --fmax 3000 --expect "$ball_doppler" --tol 0.02
}
judge ball_scale "$OUT/bd-ball-plane.wav"
# negative control: above the centre nothing comes or goes
judge_fails ball_scale "$OUT/bd-ball-above.wav"

# the shipped sphere whirled past stereo ears: finite, no clicks from the
# pose stream's steps
PD_EXTRA="tests/pd/aero-whirl 1.2 2 5" \
    pd_render bd-whirl-real "body~ -texture sphere -stereo" 2 2000 \
    "; aero-obj ears -0.1 3 0 0.1 3 0"
judge $ANALYZE finite "$OUT/bd-whirl-real.wav" --max 10
judge $ANALYZE clicks "$OUT/bd-whirl-real.wav" --max 3
judge $ANALYZE clicks "$OUT/bd-whirl-real.wav" --ch 1 --max 3

# 3. the club (10 regions along a tapered body) broadside in a 10 m/s
#    wind: a tapered cylinder sheds in cells whose frequency follows the
#    local diameter (Gaster 1969; Piccirillo and Van Atta 1993, St ~0.2 on
#    the local d), so its tone lies in the band between the tip's tone and
#    the handle's, St(Re) v / d by Roshko (1954) for each end's diameter;
#    +-5 %, Roshko's scatter. The spectral peak, smoothed over 5 Hz (the 3D
#    texture also holds a broadband rest up to ~700 Hz).
#    (the club's axis, body z, turned -90 deg about x onto +y: across the
#    wind; the stick of the tip's diameter from (0, -0.4, 0) to (0, 0.4, 0))
tip=$(texture_meta club diameter)
handle=$(texture_meta club shape | sed 's/.*handle=\([0-9.e+-]*\).*/\1/' |
    awk '{ print 2 * $1 }')
band_lo=$(awk -v f="$(tone_hz 10 "$tip")" 'BEGIN { print 0.95 * f }')
band_hi=$(awk -v f="$(tone_hz 10 "$handle")" 'BEGIN { print 1.05 * f }')
pd_render bd-club "body~ -texture club -seed 3" 1 4000 \
    "; aero-obj wind 10 0 0; aero-obj listener 0.5 0 2; aero-obj place 0 -0.4 0 -90 0 0"
pd_render bd-stick "aeolian~ -texture cylinder -d $tip -seed 3" 1 4000 \
    "; aero-obj wind 10 0 0; aero-obj listener 0.5 0 2; aero-obj place 0 -0.4 0 0 0.4 0"
judge $ANALYZE finite "$OUT/bd-club.wav" --max 10
judge $ANALYZE level "$OUT/bd-club.wav" --min 10
judge $ANALYZE peak "$OUT/bd-club.wav" --min "$band_lo" --max "$band_hi" \
    --fmin 5 --fmax 1000 --nfft 16384 --smooth 5
# the stick of the tip's diameter sounds at the band's low edge
judge $ANALYZE peak "$OUT/bd-stick.wav" --expect "$(tone_hz 10 "$tip")" \
    --tol 0.05 --fmin 5 --fmax 1000 --nfft 16384 --smooth 5
# its level is that of strip theory (issue 17): the same club heard as
# four [aeolian~] model-mode segments of 20 cm, each of the club's mean
# diameter over it (the shape's own law, as body_shape.c draws it: a
# smoothstep swell from a quarter of the length to the tip's cap), each
# with Roshko's St and Norberg's (2003) C_L' at its Re and its own
# incoherent segments ~3 d long; within 6 dB, the tolerance issue 17 sets
# (the 3D texture the strip texture replaced was 34 dB below). Model
# mode's stick stands at the origin along z, the flow along x, the lift
# along y; the club stands along z here too (no turn), the listener 2 m
# out along y, where the segments' offsets of 0.1-0.3 m along z change the
# distance by less than 0.1 dB
club_d() { # SEGMENT(0..3): the club's mean diameter over it, m
    texture_meta club shape | awk -v seg="$1" '{
        for (i = 1; i <= NF; i++) { split($i, kv, "="); m[kv[1]] = kv[2] }
        r0 = m["handle"]; r1 = m["tip"]; l = m["length"]; s = 0
        for (k = 0; k < 64; k++) {
            z = (seg + (k + 0.5) / 64) * l / 4; z0 = 0.25 * l; z1 = l - r1
            if (z > z1) r = sqrt(r1 * r1 - (z - z1) * (z - z1))
            else if (z <= z0) r = r0
            else { q = (z - z0) / (z1 - z0); q = q * q * (3 - 2 * q)
                   r = r0 + (r1 - r0) * q }
            s += 2 * r
        }
        printf "%.5f", s / 64 }'
}
level_of() { $ANALYZE level "$1" | sed -n 's/.*: \([-0-9.]*\) dB SPL.*/\1/p'; }
within_6db() { # WHAT A B
    if [ -n "$2" ] && [ -n "$3" ] &&
        awk -v a="$2" -v b="$3" 'BEGIN { exit !(a - b <= 6 && b - a <= 6) }'; then
        pass "$1: $2 dB SPL, strip theory ([aeolian~] model mode) $3 dB (within 6 dB)"
    else
        fail "$1: '$2' dB SPL against strip theory '$3' dB: not within 6 dB"
    fi
}
pd_render bd-club-z "body~ -texture club -seed 3" 1 4000 \
    "; aero-obj wind 10 0 0; aero-obj listener 0 2 0; aero-obj place 0 0 -0.4 0 0 0"
strip_sum=""
for seg in 0 1 2 3; do
    pd_render "bd-strip$seg" "aeolian~ -d $(club_d $seg) -l 0.2 -seed $((seg + 3))" \
        1 4000 "; aero-speed 10; aero-obj listener 0 2 0"
    strip_sum="$strip_sum $(level_of "$OUT/bd-strip$seg.wav")"
done
within_6db "club broadside" "$(level_of "$OUT/bd-club-z.wav")" \
    "$(echo "$strip_sum" | awk '{ for (i = 1; i <= NF; i++) p += 10 ^ ($i / 10)
        if (NF == 4) printf "%.2f", 10 * log(p) / log(10) }')"
# the same for a uniform rod, a capsule of 4 cm by 0.8 m made by strip
# theory here, against one [aeolian~] of its diameter and length
if build/aerotex object --shape capsule --radius 0.02 --length 0.8 \
    --sources 10 --directions 3 --method strip \
    --section textures/cylinder.wav -q -o "$OUT/strip-rod.wav" >/dev/null 2>&1; then
    pd_render bd-strip-rod "body~ -texture $OUT/strip-rod -seed 3" 1 4000 \
        "; aero-obj wind 10 0 0; aero-obj listener 0 2 0; aero-obj place 0 0 -0.4 0 0 0"
    pd_render bd-model-rod "aeolian~ -d 0.04 -l 0.8 -seed 3" 1 4000 \
        "; aero-speed 10; aero-obj listener 0 2 0"
    within_6db "a 4 cm rod by strip theory" "$(level_of "$OUT/bd-strip-rod.wav")" \
        "$(level_of "$OUT/bd-model-rod.wav")"
    judge $ANALYZE peakratio "$OUT/bd-model-rod.wav" "$OUT/bd-strip-rod.wav" \
        --expect 1 --tol 0.05 --fmin 20 --fmax 100 --nfft 16384 --smooth 2
    # away from the texture's speed [body~] follows the circle's laws as
    # model mode does: at 2 m/s (Re 5400) Norberg's C_L' is 0.42 of its
    # value at 10 m/s (-7.6 dB, which (v/v0)^3 alone would miss), at 25
    # m/s 1.03 of it. The rod's level against model mode's at 2 and 25 m/s
    # stays within 3 dB of what it is at 10 m/s (the tolerance test 12 of
    # 15-aeolian-texture.sh gives [aeolian~]'s two modes); 8 s, since the
    # tone at 2 m/s is at 10 Hz
    base=$(awk -v a="$(level_of "$OUT/bd-strip-rod.wav")" \
        -v b="$(level_of "$OUT/bd-model-rod.wav")" 'BEGIN { print a - b }')
    for u in 2 25; do
        pd_render "bd-strip-rod-u$u" "body~ -texture $OUT/strip-rod -seed 3" 1 8000 \
            "; aero-obj wind $u 0 0; aero-obj listener 0 2 0; aero-obj place 0 0 -0.4 0 0 0"
        pd_render "bd-model-rod-u$u" "aeolian~ -d 0.04 -l 0.8 -seed 3" 1 8000 \
            "; aero-speed $u; aero-obj listener 0 2 0"
        judge $ANALYZE leveldiff "$OUT/bd-model-rod-u$u.wav" "$OUT/bd-strip-rod-u$u.wav" \
            --expect "$base" --tol 3
    done
else
    fail "aerotex object --method strip: the capsule"
fi
# negative control: the club three times as fast leaves the 10 m/s band
pd_render bd-club-fast "body~ -texture club -seed 3" 1 4000 \
    "; aero-obj wind 30 0 0; aero-obj listener 0.5 0 2; aero-obj place 0 -0.4 0 -90 0 0"
judge_fails $ANALYZE peak "$OUT/bd-club-fast.wav" --min "$band_lo" \
    --max "$band_hi" --fmin 5 --fmax 1000 --nfft 16384 --smooth 5

# 4. bad input: a missing texture, an aeolian one, wrong pose forms, NaN:
#    every error names [body~], the object stays silent or finite
pd_render bd-bad "body~ -texture nosuch -bogus 3" 1 500 \
    "; aero-speed 10; aero-obj texture cylinder; aero-obj pose 1 2; aero-obj pose a b c; aero-obj scale 0; aero-obj texture sphere; aero-obj pose 0 0 0 0 0 0 0; aero-obj wind 1e9 0 0; aero-obj ears 1 2 3 4 5 6"
reports_at_least "$OUT/bd-bad.log" "[body~]" 8
for what in "can't find texture 'nosuch'" "not an object texture" "unknown argument '-bogus'"; do
    if grep -q -F "$what" "$OUT/bd-bad.log"; then
        pass "[body~] reports: $what"
    else
        fail "[body~] does not report: $what"; cat "$OUT/bd-bad.log"
    fi
done
judge $ANALYZE finite "$OUT/bd-bad.wav" --max 10

# 5. aerotex object on the command line: bad bodies and sections are
#    refused with a message naming the problem (exit 2), a tiny sphere
#    texture is made with vorticity slices, and [body~] plays it
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 1 2 3\n' \
    >"$OUT/open.obj"
for bad in "--mesh $OUT/open.obj:not closed" "--mesh /nonexistent.obj:can't open" \
    "--shape cube:takes sphere, capsule or club" \
    "--shape sphere --radius -1:out of range" \
    "--shape sphere --directions 3:--directions 1" \
    "--shape club --handle 0.05 --tip 0.03:handle <= tip" \
    "--shape sphere --limiter maybe:takes off or on" \
    "--shape club --sources 64 --directions 91:at most 4096" \
    "--shape sphere --method strip --section textures/cylinder.wav:not slender" \
    "--shape club --method strip:needs --section" \
    "--shape club --method strip --section textures/square.wav:a circle's aeolian texture"; do
    args=${bad%%:*} want=${bad#*:}
    # shellcheck disable=SC2086
    msg=$(build/aerotex object $args -q -o "$OUT/bad-object.wav" 2>&1)
    status=$?
    if [ "$status" -eq 2 ] && printf '%s' "$msg" | grep -q -F -- "$want"; then
        pass "'aerotex object $args' -> exit 2, says '$want'"
    else
        fail "'aerotex object $args' -> exit $status: $msg"
    fi
done
rm -rf "$OUT/object-png"
if build/aerotex object --shape sphere --radius 0.05 --grid 6 --duration 0.05 \
    --settle 5 --png "$OUT/object-png" -q -o "$OUT/tiny-sphere.wav" \
    >"$OUT/tiny-sphere.txt" 2>&1 &&
    [ "$(ls "$OUT/object-png" | wc -l)" -ge 3 ] &&
    build/aerotex info "$OUT/tiny-sphere.wav" | grep -q "^kind=object" &&
    build/aerotex info "$OUT/tiny-sphere.wav" | grep -q "^solver=.*limited MacCormack"; then
    pass "aerotex object: a tiny sphere texture and $(ls "$OUT/object-png" | wc -l) vorticity slices"
else
    fail "aerotex object: the tiny sphere"; cat "$OUT/tiny-sphere.txt"
fi
pd_render bd-tiny "body~ -texture $OUT/tiny-sphere" 1 500 "; aero-speed 10"
judge $ANALYZE level "$OUT/bd-tiny.wav" --min 0

# the club whirled on a 0.5 m radius at 2 turns/s (its axis along the
# radius) past stereo ears 3 m out, started, stopped, paused, placed and
# its texture loaded again while it whirls, as 16-sword.sh 1b does with
# the blade, recorded from before the first
# pose (issue 48: the ears given as the poses began were still gliding
# there when the sound started, 5.5-7; a stream resumed after a placement
# caught up its wait in one interval, 117-229): each ear's click measure
# over the whole 1.5 s (median of five seeds) within the steady whirl's
# (the same whirl started at load, recorded after the settle) + 0.5
bd_holds() { if awk "BEGIN { exit !($1) }"; then echo 1; else echo 0; fi; }
bd_median_clicks() { # NAME EAR: the median over the seeds
    for seed in 1 2 3 4 5; do
        $ANALYZE clicks "$OUT/$1-$seed.wav" --ch "$2" | sed -n 's/.*: \([0-9.]*\).*/\1/p'
    done | sort -n | awk '{ v[NR] = $1 } END { if (NR == 5) print v[3] }'
}
for seed in 1 2 3 4 5; do
    PD_EXTRA="tests/pd/aero-club-start 0.5 2 5" \
        pd_render "bd-club-whirl-$seed" "body~ -texture club -stereo -seed $seed" 2 2000 \
        "; aero-obj ears -0.1 3 0 0.1 3 0; aero-whirl 1"
    PD_EXTRA="tests/pd/aero-club-start 0.5 2 5" \
        pd_render "bd-club-start-$seed" "body~ -texture club -stereo -seed $seed" 2 1500 \
        "" 0 "100 ; aero-obj ears -0.1 3 0 0.1 3 0; aero-whirl 1" \
        "400 ; aero-whirl 0" "550 ; aero-whirl 1" \
        "800 ; aero-whirl 0; aero-obj place 0 -0.5 0 0.70710678 0.70710678 0 0" \
        "1000 ; aero-whirl 1" "1150 ; aero-obj texture club" \
        "1300 ; aero-whirl 0"
    judge $ANALYZE finite "$OUT/bd-club-start-$seed.wav" --max 100
done
for ch in 0 1; do
    ref=$(bd_median_clicks bd-club-whirl "$ch") c=$(bd_median_clicks bd-club-start "$ch")
    if [ "$(bd_holds "\"$c\" != \"\" && \"$ref\" != \"\" && $c <= $ref + 0.5")" -eq 1 ]; then
        pass "club started, stopped, placed and retextured, ear $ch, from before the first pose: click measure $c (median of 5 seeds; the steady whirl's $ref + 0.5)"
    else
        fail "club started, stopped, placed and retextured, ear $ch, from before the first pose: click measure ${c:-?} (median of 5 seeds; the steady whirl's ${ref:-?} + 0.5)"
    fi
done
