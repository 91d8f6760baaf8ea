# --- the sword blade (textures/sword.wav) whirled at every chord angle -------
section "[aeolian~]: the sword blade, whirled with its chord at 0-90 deg (issue 39)"

# SWORD_TEXTURE=FILE runs these checks on another texture. What the
# shipped texture does not meet yet (issue 39, textures/README.md sword.wav)
# is named in SWORD_OPEN: a known failure, printed as "open" and not
# counted, which fails the test once it passes (so that it is taken off
# the list); SWORD_OPEN= (empty) counts every check as usual.
sword=${SWORD_TEXTURE:-sword}
sword_wav=$sword
case $sword_wav in */*) ;; *) sword_wav=textures/$sword ;; esac
sword_wav=${sword_wav%.wav}.wav
sword_open=${SWORD_OPEN-}
verdict() { # KEY OK MESSAGE: pass or fail; KEY in SWORD_OPEN: the reverse
    case " $sword_open " in
    *" $1 "*)
        if [ "$2" -eq 1 ]; then
            fail "$3: passes now, take $1 off SWORD_OPEN (issue 39)"
        else
            echo "  open  $3 (a known failure, issue 39; not counted)"
        fi ;;
    *) if [ "$2" -eq 1 ]; then pass "$3"; else fail "$3"; fi ;;
    esac
}
click_of() { # FILE CHANNEL: aero-analyze's click measure
    $ANALYZE clicks "$1" --ch "$2" | sed -n 's/.*: \([0-9.]*\).*/\1/p'
}
holds() { if awk "BEGIN { exit !($1) }"; then echo 1; else echo 0; fi; }
meta() { build/aerotex info "$sword_wav" | sed -n "s/^$1=//p"; }
chord=$(meta diameter) step=$(meta angle_step) st_list=$(meta st_list)

# 1. A blade from 0.5 to 1.5 m turning at 2 turns/s (tip 18.8 m/s) past
#    stereo ears 3 m out, its chord (the body x axis, the optional axis of
#    pose) held at 0, 30, 45, 60 and 90 deg to its path (tests/pd/
#    aero-blade), against the cylinder whirled the same way in the same
#    run (tests/pd/aero-rotor, as test 8 of 15-aeolian-texture.sh): each
#    ear's click measure (the worst 2 ms window's peak second difference
#    over its 6 ms neighbourhood) within the cylinder's + 0.5, the
#    measure's scatter from run to run of the flow (textures/README.md).
#    One 2 s render's measure moves by about +-0.4 with the sources'
#    random offsets and phase wander (the seed), the cylinder's as much
#    as the blade's, so both are the median over five seeds. A blade held
#    at one angle reads one pair of texture directions all the time;
#    these ears, in the plane of the turn, hear only its drag, and the
#    measure weighs the tip's source most.
sword_seeds="1 2 3 4 5"
median() { # the median of the numbers on stdin
    sort -n | awk '{ v[NR] = $1 } END { if (NR == 0) exit
        print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
render_whirls() { # NAME ANGLE|cylinder [EARS]: NAME-SEED.wav for each seed
    ears=${3:--0.1 3 0 0.1 3 0}
    for seed in $sword_seeds; do
        if [ "$2" = cylinder ]; then
            PD_EXTRA="tests/pd/aero-rotor 0.5 1.5 0 720 5" \
                pd_render "$1-$seed" "aeolian~ -texture cylinder -stereo -seed $seed" \
                2 2000 "; aero-obj ears $ears"
        else
            PD_EXTRA="tests/pd/aero-blade 0.5 1.5 0 720 5 $2" \
                pd_render "$1-$seed" "aeolian~ -texture $sword -stereo -seed $seed" \
                2 2000 "; aero-obj ears $ears"
        fi
        judge $ANALYZE finite "$OUT/$1-$seed.wav" --max 100
    done
}
median_clicks() { # NAME EAR: the median of the ear's measures over seeds
    for seed in $sword_seeds; do click_of "$OUT/$1-$seed.wav" "$2"; done | median
}
render_whirls sw-cyl cylinder
cyl0=$(median_clicks sw-cyl 0) cyl1=$(median_clicks sw-cyl 1)
for angle in 0 30 45 60 90; do
    render_whirls "sw-whirl-$angle" "$angle"
    for ch in 0 1; do
        eval "ref=\${cyl$ch:-?}"
        c=$(median_clicks "sw-whirl-$angle" "$ch")
        eval "steady_${angle}_$ch=\$c"
        verdict "whirl$angle" "$(holds "\"$c\" != \"\" && \"$ref\" != \"?\" && $c <= $ref + 0.5")" \
            "whirled blade, chord at $angle deg, ear $ch: click measure ${c:-?} (median of seeds $sword_seeds; the cylinder's ${ref} + 0.5)"
    done
done

# 1b. the same whirl started, stopped and placed, recorded from before the
#    first pose (issue 48: a blade whirled from rest clicked ~20 ms in, its
#    ears given as the poses began still gliding there; a stream resumed
#    after a pause caught up the pause's way in one interval): the ears
#    and the first pose 0.1 s in (from rest), stopped at 0.4 s, started
#    again at 0.55 s (after a pause, mid-swing), stopped at 0.8 s with a
#    placement elsewhere (a jump while sounding), started again from there
#    at 1 s, its texture changed to the cylinder's at 1.15 s (while
#    moving), stopped at 1.3 s. Each ear's click measure over the whole
#    1.5 s (median of the seeds) within the steady whirl's above + 0.5.
render_gestures() { # NAME ANGLE: NAME-SEED.wav for each seed
    for seed in $sword_seeds; do
        PD_EXTRA="tests/pd/aero-blade-start 0.5 1.5 0 720 5 $2" \
            pd_render "$1-$seed" "aeolian~ -texture $sword -stereo -seed $seed" \
            2 1500 "" 0 "100 ; aero-obj ears -0.1 3 0 0.1 3 0; aero-whirl 1" \
            "400 ; aero-whirl 0" "550 ; aero-whirl 1" \
            "800 ; aero-whirl 0; aero-obj place 0 -0.5 0 0 -1.5 0 0 0 1" \
            "1000 ; aero-whirl 1" "1150 ; aero-obj texture cylinder" \
            "1300 ; aero-whirl 0"
        judge $ANALYZE finite "$OUT/$1-$seed.wav" --max 100
    done
}
for angle in 0 30 45 60 90; do
    render_gestures "sw-start-$angle" "$angle"
    for ch in 0 1; do
        eval "ref=\${steady_${angle}_$ch:-?}"
        c=$(median_clicks "sw-start-$angle" "$ch")
        verdict "start$angle" "$(holds "\"$c\" != \"\" && \"$ref\" != \"?\" && $c <= $ref + 0.5")" \
            "blade started, stopped, placed and retextured, chord at $angle deg, ear $ch, from before the first pose: click measure ${c:-?} (median of seeds $sword_seeds; the steady whirl's ${ref} + 0.5)"
    done
done

# 2. every force channel of the texture (drag and lift of each direction)
#    has a click measure of at most 3
directions=$(meta directions)
[ -n "$directions" ] || fail "$sword_wav: no directions in its metadata"
k=0
while [ "$k" -lt "${directions:-0}" ]; do
    x=$(click_of "$sword_wav" $((3 * k))) y=$(click_of "$sword_wav" $((3 * k + 1)))
    a=$(awk -v k="$k" -v s="$step" 'BEGIN { print k * s }')
    verdict channels "$(holds "\"$x\" != \"\" && \"$y\" != \"\" && $x <= 3 && $y <= 3")" \
        "sword texture at $a deg: click measure of the drag ${x:-?}, the lift ${y:-?} (at most 3)"
    k=$((k + 1))
done

# 3. the tone's St on the projected width w (the blade's extent across the
#    flow) from 20 to 90 deg: 0.14-0.20 (issue 39), the inclined flat
#    plate's (Fage and Johansen 1927: 0.146 broadside, near it on the
#    projected width when inclined). The texture's own measure (aerotex
#    info st_list, St on the chord) ...
projected_width() { # DEG: the blade's extent across a flow at DEG, m
    awk -v a="$1" -v c="$chord" '
        !/^#/ && NF >= 2 { gsub(",", " "); n++; x[n] = $1; y[n] = $2 }
        END { xmin = 1e9; xmax = -1e9
              for (i = 1; i <= n; i++) { if (x[i] < xmin) xmin = x[i]; if (x[i] > xmax) xmax = x[i] }
              r = a * 3.14159265358979 / 180; lo = 1e9; hi = -1e9
              for (i = 1; i <= n; i++) { p = -sin(r) * x[i] + cos(r) * y[i]
                  if (p < lo) lo = p; if (p > hi) hi = p }
              printf "%.6g\n", c / (xmax - xmin) * (hi - lo) }' textures/sword.poly
}
k=0
for st in $(echo "$st_list" | tr ',' ' '); do
    a=$(awk -v k="$k" -v s="$step" 'BEGIN { print k * s }')
    k=$((k + 1))
    [ "$(holds "$a >= 20")" -eq 1 ] || continue
    stw=$(awk -v s="$st" -v w="$(projected_width "$a")" -v c="$chord" \
        'BEGIN { printf "%.4f", s * w / c }')
    verdict "st$a" "$(holds "$stw >= 0.14 && $stw <= 0.20")" \
        "sword St on the projected width at $a deg: $stw (0.14-0.20, Fage and Johansen 1927)"
done
[ "$k" -eq "${directions:-0}" ] || fail "$sword_wav: st_list has $k of $directions directions"

#    ... and as heard: a blade at rest in a 15 m/s wind, an ear 3 m across
#    the flow (the lift) and one 3 m along it (the drag): at 45 and 90 deg
#    the lift ear's spectral peak (smoothed over 3 Hz) is at St_w 0.14-0.20
rest_in() { # DEG [SPEED]: render the blade at rest with its chord at DEG
    # to the wind (15 m/s: sw-rest-DEG.wav; else sw-rest-DEG-SPEED.wav)
    ux=$(awk -v a="$1" 'BEGIN { printf "%.6f", cos(a * 3.14159265358979 / 180) }')
    uy=$(awk -v a="$1" 'BEGIN { printf "%.6f", sin(a * 3.14159265358979 / 180) }')
    name=sw-rest-$1${2:+-$2}
    pd_render "$name" "aeolian~ -texture $sword -seed 5 -stereo" 2 4000 \
        "; aero-obj wind ${2:-15} 0 0; aero-obj place 0 0 -0.5 0 0 0.5 $ux $uy 0; aero-obj ears 3 0 0 0 3 0"
}
rest() { rest_in "$1"; }
for angle in 45 90; do
    rest "$angle"
    f=$($ANALYZE peak "$OUT/sw-rest-$angle.wav" --ch 1 --fmin 10 --fmax 2000 \
        --nfft 16384 --smooth 3 | sed -n 's/.*: \([0-9.e+-]*\) Hz.*/\1/p')
    stw=$(awk -v f="$f" -v w="$(projected_width "$angle")" 'BEGIN { printf "%.4f", f * w / 15 }')
    verdict heard "$(holds "\"$f\" != \"\" && $stw >= 0.14 && $stw <= 0.20")" \
        "blade at rest at $angle deg: heard peak ${f:-?} Hz, St on the projected width $stw (0.14-0.20, Fage and Johansen 1927)"
done

# 4. below 20 deg the blade is not silent: edge-on, a weak tone from its
#    thin wake, below the broadside level (the power of both ears, drag
#    and lift) and within 30 dB of it (audible beside it: a choice, not a
#    published bound)
rest 0
level_of() { # FILE: the power sum of both channels, dB SPL
    a=$($ANALYZE level "$1" --ch 0 | sed -n 's/.*: \([-0-9.]*\) dB SPL.*/\1/p')
    b=$($ANALYZE level "$1" --ch 1 | sed -n 's/.*: \([-0-9.]*\) dB SPL.*/\1/p')
    [ -n "$a" ] && [ -n "$b" ] &&
        awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f", 10 * log(10^(a / 10) + 10^(b / 10)) / log(10) }'
}
edge=$(level_of "$OUT/sw-rest-0.wav") broad=$(level_of "$OUT/sw-rest-90.wav")
verdict level "$(holds "\"$edge\" != \"\" && \"$broad\" != \"\" && $edge < $broad && $edge > $broad - 30")" \
    "edge-on blade: ${edge:-?} dB SPL, broadside ${broad:-?} dB (below it by less than 30 dB)"

# 5. above the texture's band limit the blade's top comes from the airfoil
#    self-noise model (Brooks et al. 1989; src/core/play/blade_noise.h):
#    a blade at rest edge-on (0 deg) and at 5 deg in a 22.8 m/s wind, the
#    tip speed of make demo's fastest swing (150 deg in 180 ms at 1 m: the
#    tip's 22.8 m/s at mid-swing, Rc 6.2e4), heard by the lift ear 3 m
#    across the flow. Each one-third-octave band from 2.5 kHz (above the
#    band limit's 1.14-2.28 kHz at that speed) to 12.5 kHz (30 dB under
#    the model's peak) against the model's prediction for the whole 1 m
#    span at 3 m (`aerotex airfoil`), within 1 dB: the player's bank holds
#    each band within 1 dB of the model (tests/unit/test_blade_noise.c)
#    and a 3.5 s render's band level scatters by 0.1-0.3 dB; the sources'
#    spread along the span moves the level by 0.08 dB
top_band() { # FILE CENTRE: the band's level on the lift ear, dB SPL
    $ANALYZE band "$1" "$(awk -v f="$2" 'BEGIN { print f / 1.122462 }')" \
        "$(awk -v f="$2" 'BEGIN { print f * 1.122462 }')" --ch 1 --skip 0.5 |
        sed -n 's/.*: \([-0-9.]*\) dB SPL.*/\1/p'
}
case $sword in
sword)
    for angle in 0 5; do
        rest_in "$angle" 22.8
        build/aerotex airfoil --speed 22.8 --alpha "$angle" --span 1 \
            --distance 3 --from 2500 --to 12500 | grep -v '^#' \
            >"$OUT/sw-top-$angle.txt"
        [ -s "$OUT/sw-top-$angle.txt" ] || fail "aerotex airfoil printed no band"
        while read -r hz _ _ _ _ _ _ want; do
            got=$(top_band "$OUT/sw-rest-$angle-22.8.wav" "$hz")
            verdict top "$(holds "\"$got\" != \"\" && $got >= $want - 1 && $got <= $want + 1")" \
                "blade at $angle deg in 22.8 m/s, ${hz} Hz band: ${got:-?} dB SPL, the model $want (+-1; Brooks et al. 1989)"
        done <"$OUT/sw-top-$angle.txt"
    done ;;
esac

# 6. test 1 with the ears 1 m above the plane of the turn: there the model's
#    noise is heard (in the plane its dipole, normal to the blade's path
#    and axis, gives nothing; 3-8 kHz at the ear: 20.7 dB SPL, 52 dB over
#    the texture alone), and the whirled blade still clicks no more than
#    the cylinder whirled the same way + 0.5 (each ear the median of five
#    seeds)
case $sword in
sword)
    for what in cylinder 0 45; do
        render_whirls "sw-up-$what" "$what" "-0.1 3 1 0.1 3 1"
    done
    up0=$(median_clicks sw-up-cylinder 0) up1=$(median_clicks sw-up-cylinder 1)
    for angle in 0 45; do
        for ch in 0 1; do
            eval "ref=\${up$ch:-?}"
            c=$(median_clicks "sw-up-$angle" "$ch")
            verdict whirlup "$(holds "\"$c\" != \"\" && \"$ref\" != \"?\" && $c <= $ref + 0.5")" \
                "whirled blade heard from above the turn, chord at $angle deg, ear $ch: click measure ${c:-?} (median of seeds $sword_seeds; the cylinder's ${ref} + 0.5)"
        done
    done ;;
esac
