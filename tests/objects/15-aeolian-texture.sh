# --- [aeolian~] texture mode: moving sticks from CFD textures (Dobashi et al. 2003) ---
section "[aeolian~]: texture mode, moving and turning sticks"

# What the textures measured when they were made (aerotex info): the
# player must put the tone where St v / d of the texture says.
texture_st() {
    build/aerotex info "textures/$1.wav" | sed -n 's/^st=//p'
}
st_cyl=$(texture_st cylinder)
# tone of a stick of diameter D normal to a flow V: St V / D
st_tone() { awk -v st="$st_cyl" -v v="$1" -v d="$2" 'BEGIN { printf "%.6g\n", st * v / d }'; }
# c0 / (c0 -+ v): the Doppler ratio of a source approaching (receding)
doppler() { awk -v v="$1" 'BEGIN { printf "%.6g\n", 343 / (343 - v) }'; }

# 1. a static stick in a steady wind: the peak at St v / d, for the
#    texture's own diameter and for another one (coordinate by v/v0 d0/d)
pd_render tx-static "aeolian~ -texture cylinder -d 0.005" 1 1000 \
    "; aero-obj wind 10 0 0; aero-obj listener 0 60 0; aero-obj pose 0 20 -0.25 0 20 0.25"
judge $ANALYZE peak "$OUT/tx-static.wav" --expect "$(st_tone 10 0.005)" \
    --tol 0.01 --fmin 300 --fmax 800
pd_render tx-inlet "aeolian~ -texture cylinder" 1 1000 "; aero-speed 14"
judge $ANALYZE peak "$OUT/tx-inlet.wav" --expect "$(st_tone 14 0.01)" \
    --tol 0.01 --fmin 200 --fmax 600

# 2. Doppler: the stick flies at 30 m/s straight at (away from) the
#    listener, with a wind that leaves it the same 10 m/s across its axis
#    as the static one, so only the motion changes the pitch
PD_EXTRA="tests/pd/aero-mover 0 -10 -0.25 0 -10 0.25 0 30 0 5" \
    pd_render tx-approach "aeolian~ -texture cylinder -d 0.005" 1 1000 \
    "; aero-obj wind 10 30 0; aero-obj listener 0 60 0"
PD_EXTRA="tests/pd/aero-mover 0 50 -0.25 0 50 0.25 0 -30 0 5" \
    pd_render tx-recede "aeolian~ -texture cylinder -d 0.005" 1 1000 \
    "; aero-obj wind 10 -30 0; aero-obj listener 0 60 0"
judge $ANALYZE peakratio "$OUT/tx-static.wav" "$OUT/tx-approach.wav" \
    --expect "$(doppler 30)" --tol 0.01 --fmin 300 --fmax 800
judge $ANALYZE peakratio "$OUT/tx-static.wav" "$OUT/tx-recede.wav" \
    --expect "$(doppler -30)" --tol 0.01 --fmin 300 --fmax 800
# negative control: the moving stick is not at the static pitch
judge_fails $ANALYZE peakratio "$OUT/tx-static.wav" "$OUT/tx-approach.wav" \
    --expect 1 --tol 0.01 --fmin 300 --fmax 800

# 3. inclined stick (property 3): tilted 40 deg towards the flow, the
#    normal component v cos(phi) sheds, the peak falls by cos(40) = 0.766
pd_render tx-tilt "aeolian~ -texture cylinder -d 0.005" 1 1000 \
    "; aero-obj wind 10 0 0; aero-obj listener 0 60 0; aero-obj pose -0.1607 20 -0.1915 0.1607 20 0.1915"
judge $ANALYZE peakratio "$OUT/tx-static.wav" "$OUT/tx-tilt.wav" \
    --expect 0.766 --tol 0.01 --fmin 200 --fmax 800

# 4. turning a stick about its own axis plays the texture's other
#    directions (a player check): the square prism's spectrum at roll 45
#    differs from roll 0 by 1.5 times what another noise seed changes at
#    roll 0 (a player that ignored the roll would render the same samples);
#    the circle's does not change. The square texture's St rises from 0 to
#    12.9 deg as measured (Knisely 1990: a maximum at 12-15 deg) but has a
#    second maximum at 38.6 deg that measurements do not show (open,
#    textures/README.md)
for r in 0 45; do
    pd_render "tx-square-roll$r" "aeolian~ -texture square -seed 1" 1 4000 \
        "; aero-obj wind 10 0 0; aero-obj roll $r"
    pd_render "tx-circle-roll$r" "aeolian~ -texture cylinder -seed 1" 1 4000 \
        "; aero-obj wind 10 0 0; aero-obj roll $r"
done
pd_render tx-square-roll0-seed2 "aeolian~ -texture square -seed 2" 1 4000 \
    "; aero-obj wind 10 0 0; aero-obj roll 0"
seed_db=$($ANALYZE specdist "$OUT/tx-square-roll0.wav" "$OUT/tx-square-roll0-seed2.wav" \
    --fmin 40 --fmax 1500 --smooth 50 | sed -n 's/.*: \([-0-9.e+]*\) dB.*/\1/p')
judge $ANALYZE specdist "$OUT/tx-square-roll0.wav" "$OUT/tx-square-roll45.wav" \
    --min "$(awk -v d="${seed_db:-1e9}" 'BEGIN { print 1.5 * d }')" \
    --fmin 40 --fmax 1500 --smooth 50
judge $ANALYZE specdist "$OUT/tx-circle-roll0.wav" "$OUT/tx-circle-roll45.wav" \
    --max 0.1 --fmin 40 --fmax 1500 --smooth 20

# 5. level: p ~ U^3 (+18.06 dB per doubling), not the paper's U^6, and the
#    exponent message brings the paper's law back (+36.1 dB). One source
#    (a 3 cm stick): the incoherent sum of several is only +18 on average.
#    The cylinder texture (corrected to 3D) also follows the circle's
#    C_L'(Re) (Norberg 2003) and St(Re) (Roshko 1954) away from its Re, as
#    model mode does: Re 6768 -> 13536 adds 20 log10(C' St ratio)
re_law_db=$(awk 'function cl(re, x) { x = log(re / 1600) / log(10)
        return (re < 5400) ? 0.045 + 3 * x^4.6 : 0.52 - 0.06 * x^-2.6 }
    BEGIN { r1 = 1.225 * 10 * 0.01 / 1.81e-5; r2 = 2 * r1
        printf "%.3f", 20 * log(cl(r2) * (1 - 19.7 / r2) / (cl(r1) * (1 - 19.7 / r1))) / log(10) }')
pd_render tx-u10 "aeolian~ -texture cylinder -l 0.03" 1 1000 "; aero-obj wind 10 0 0"
pd_render tx-u20 "aeolian~ -texture cylinder -l 0.03" 1 1000 "; aero-obj wind 20 0 0"
pd_render tx-u20-paper "aeolian~ -texture cylinder -l 0.03 -exponent 6" 1 1000 \
    "; aero-obj wind 20 0 0"
judge $ANALYZE leveldiff "$OUT/tx-u10.wav" "$OUT/tx-u20.wav" \
    --expect "$(awk -v r="$re_law_db" 'BEGIN { print 18.06 + r }')" --tol 0.2
pd_render tx-u10-paper "aeolian~ -texture cylinder -l 0.03 -exponent 6" 1 1000 \
    "; aero-obj wind 10 0 0"
judge $ANALYZE leveldiff "$OUT/tx-u10-paper.wav" "$OUT/tx-u20-paper.wav" \
    --expect "$(awk -v r="$re_law_db" 'BEGIN { print 36.12 + r }')" --tol 0.3

# absolute level: one 3 cm segment 1 m away across the flow hears the lift
# only, p = g' l / (4 pi c0 r) with g' = 2 pi f F', F' = rho v0^2 d Cl'/2
# from the texture's own measured f and rms lift (a sinusoidal lift)
curle_db=$(build/aerotex info textures/cylinder.wav | awk -F= '
    { m[$1] = $2 }
    END { F = 0.5 * m["rho"] * m["v0"]^2 * m["diameter"] * m["cl_rms"]
          p = 2 * 3.14159265 * m["f"] * F * 0.03 / (4 * 3.14159265 * 343)
          printf "%.4g\n", 20 * log(p / 2e-5) / log(10) }')
judge $ANALYZE level "$OUT/tx-u10.wav" --expect "$curle_db" --tol 1

# 6. 1/r: a short stick (one source), listener at 2 m and at 4 m
pd_render tx-r2 "aeolian~ -texture cylinder -l 0.03" 1 1000 \
    "; aero-obj wind 10 0 0; aero-obj listener 0 2 0"
pd_render tx-r4 "aeolian~ -texture cylinder -l 0.03" 1 1000 \
    "; aero-obj wind 10 0 0; aero-obj listener 0 4 0"
judge $ANALYZE leveldiff "$OUT/tx-r2.wav" "$OUT/tx-r4.wav" --expect -6.02 --tol 0.2

# 7. ears at 2 m and 4 m: the far ear hears the onset (4 - 2) / 343 s later
pd_render tx-ears "aeolian~ -texture cylinder -l 0.03 -stereo" 2 500 \
    "; aero-obj ears 0 2 0 0 4 0; aero-obj ramp 5" 0 "100 ; aero-obj wind 10 0 0"
judge $ANALYZE onsetdiff "$OUT/tx-ears.wav" \
    --expect "$(awk 'BEGIN { print 2000 / 343 }')" --tol 0.1

# 8. a whirled stick (1 turn/s, ends at 0.5 and 1.5 m) passing the ears:
#    finite, audible (30 dB SPL for the uncorrected 2D texture, lowered by
#    the texture's own 2D-to-3D correction of g = dF/dt, textures/README.md),
#    no clicks from the pose stream's steps
PD_EXTRA="tests/pd/aero-rotor 0.5 1.5 0 360 5" \
    pd_render tx-whirl "aeolian~ -texture cylinder -stereo" 2 2000 \
    "; aero-obj ears -0.1 3 0 0.1 3 0"
judge $ANALYZE finite "$OUT/tx-whirl.wav" --max 100
whirl_floor=$(build/aerotex info textures/cylinder.wav | awk -F= '
    { m[$1] = $2 }
    END { f = m["span3d_force_scale"] * m["span3d_frequency_scale"]
          printf "%.2f", 30 + (f > 0 ? 20 * log(f) / log(10) : 0) }')
judge $ANALYZE level "$OUT/tx-whirl.wav" --min "$whirl_floor"
judge $ANALYZE clicks "$OUT/tx-whirl.wav" --max 3
judge $ANALYZE clicks "$OUT/tx-whirl.wav" --ch 1 --max 3

# 9. bad textures: missing, corrupt, the wrong kind. Each is reported with
#    its name and the object falls back to the Strouhal/Reynolds model
#    (still a tone at St(Re) U / d), finite
printf 'RIFF\001\000\000\000WAVEjunk' >"$OUT/corrupt.wav"
for bad in "nosuch:nosuch" "corrupt:$ROOT/$OUT/corrupt.wav" "cavity:cavity"; do
    name=${bad%%:*} file=${bad#*:}
    pd_render "tx-bad-$name" "aeolian~ -texture $file -d 0.01" 1 1000 \
        "; aero-speed 10; aero-obj pose 0 0 -0.1 0 0 0.1; aero-obj wind 5 0 0"
    if grep -q "\[aeolian~\].*$(basename "$file" .wav).*Strouhal/Reynolds" \
        "$OUT/tx-bad-$name.log"; then
        pass "texture '$name': error names the file and falls back to the model"
    else
        fail "texture '$name': no clear error"; cat "$OUT/tx-bad-$name.log"
    fi
    judge $ANALYZE finite "$OUT/tx-bad-$name.wav"
    judge $ANALYZE peak "$OUT/tx-bad-$name.wav" --expect "$(tone_hz 10 0.01)" \
        --tol 0.03 --fmin 100 --fmax 300 --smooth 8
done

# 10. bad messages in texture mode: reported, output stays finite
pd_render tx-bad-msgs "aeolian~ -texture cylinder -n -3 -exponent 99" 1 1000 \
    "; aero-obj wind 10 0 0" 0 \
    "100 ; aero-obj pose 0 0 0 0 0 0" "200 ; aero-obj pose 1 2 3" \
    "300 ; aero-obj wind 1e30 0 0" "400 ; aero-obj roll nan" \
    "500 ; aero-obj pose 0 0 0 0 0 1 0 0 0" "600 ; aero-obj n 3.5" \
    "700 ; aero-obj texture nosuch2" "800 ; aero-obj texture cylinder"
judge $ANALYZE finite "$OUT/tx-bad-msgs.wav" --max 100
reports_at_least "$OUT/tx-bad-msgs.log" "[aeolian~]" 8

# 11. the shipped cylinder texture against published flow data (aerotex
#     info: St of the lift's spectral peak, coefficients per unit span).
#     St and C_L' are what the 2D-to-3D correction is calibrated on
#     (textures/README.md), so these check that it was applied. Still open
#     and not asserted here (textures/README.md, "Open"): the 2D mean drag
#     (Cd 1.0-1.3, Roshko 1961; the texture's is ~1.76), the square
#     prism's St and Cd onto a face (the sword: 16-sword.sh)
tex_meta() { build/aerotex info "textures/$1.wav" | sed -n "s/^$2=//p"; }
cyl_re=$(tex_meta cylinder re)
in_range "cylinder St" "$(tex_meta cylinder st)" 0.19 0.21 "Roshko 1954"
cl_fit=$(awk -v re="$cyl_re" 'BEGIN { x = log(re / 1600) / log(10)
    print (re < 5400) ? 0.045 + 3 * x^4.6 : 0.52 - 0.06 * x^-2.6 }')
in_range "cylinder sectional C_L'" "$(tex_meta cylinder cl_rms)" \
    "$(awk -v c="$cl_fit" 'BEGIN { print 0.7 * c }')" \
    "$(awk -v c="$cl_fit" 'BEGIN { print 1.3 * c }')" "Norberg 2003 fit +-30 %"
in_range "cylinder cells per diameter" "$(tex_meta cylinder cells)" 24 1000 \
    "issue 19: at least 24"

# 12. texture mode and model mode agree on the same stick (d = 1 cm,
#     l = 30 cm), speed and listener (3 m across the flow): the spectral
#     peak within 5 %, the level within 3 dB, at four speeds (Re 2700 to
#     16900, where Norberg's C_L' rises tenfold). Model mode's tone follows
#     Roshko (1954) St(Re) and Norberg (2003) C_L'(Re); the texture, made
#     at Re 6768, follows them away from its Re (aeolian_texture.c)
for u in 4 10 14 25; do
    pd_render "agree-model-u$u" "aeolian~ -d 0.01 -l 0.3 -seed 4" 1 4000 \
        "; aero-speed $u; aero-obj listener 0 3 0"
    pd_render "agree-texture-u$u" "aeolian~ -texture cylinder -d 0.01 -l 0.3 -seed 4" 1 4000 \
        "; aero-speed $u; aero-obj listener 0 3 0"
    f=$(awk -v u="$u" 'BEGIN { re = 1.225 * u * 0.01 / 1.81e-5
        printf "%.1f", 0.198 * (1 - 19.7 / re) * u / 0.01 }')
    judge $ANALYZE peakratio "$OUT/agree-model-u$u.wav" "$OUT/agree-texture-u$u.wav" \
        --expect 1 --tol 0.05 --fmin "$(awk -v f="$f" 'BEGIN{print f/2}')" \
        --fmax "$(awk -v f="$f" 'BEGIN{print f*1.5}')" --smooth "$(awk -v f="$f" 'BEGIN{print f*0.04}')"
    judge $ANALYZE leveldiff "$OUT/agree-model-u$u.wav" "$OUT/agree-texture-u$u.wav" \
        --expect 0 --tol 3
done

# 13. a long stick's sources add their powers, as model mode's segments do
#     (spanwise correlation length ~3-5 d, Norberg 2003): a 30 cm stick of
#     d = 1 cm carries 10 sources 3 d apart, a 3 cm one a single source, so
#     the tone band (St v / d +- 2 %) is 10 log10(10) = 10 dB louder, for
#     every seed. Sources that read the same texture with frozen phases
#     would sum at random gains instead (their sum in one line is a random
#     phasor sum: off by more than 2 dB for about 2 seeds in 3). The
#     tolerance is the spread of an 8 s estimate of a line of 1 % width
#     (about 50 coherence times 1 / (pi B): 0.6 dB rms)
f=$(st_tone 10 0.01)
lo=$(awk -v f="$f" 'BEGIN { print f * 0.98 }')
hi=$(awk -v f="$f" 'BEGIN { print f * 1.02 }')
for seed in 1 2 3 4; do
    for l in 0.3 0.03; do
        pd_render "tx-span-$l-s$seed" "aeolian~ -texture cylinder -d 0.01 -l $l -seed $seed" \
            1 8000 "; aero-speed 10; aero-obj listener 0 3 0"
    done
    long=$($ANALYZE band "$OUT/tx-span-0.3-s$seed.wav" "$lo" "$hi" | awk '{ print $(NF-2) }')
    short=$($ANALYZE band "$OUT/tx-span-0.03-s$seed.wav" "$lo" "$hi" | awk '{ print $(NF-2) }')
    if awk -v a="$long" -v b="$short" 'BEGIN { d = a - b; exit !(d >= 8 && d <= 12) }'; then
        pass "seed $seed: 10 sources over 1 in the tone band: $(awk -v a="$long" -v b="$short" 'BEGIN { printf "%+.2f", a - b }') dB (want +10 +- 2)"
    else
        fail "seed $seed: 10 sources over 1 in the tone band: ${long:-?} - ${short:-?} dB (want +10 +- 2)"
    fi
done
