# --- [rotor~]: blade-passing tones of fans, propellers and drone rotors -------
section "[rotor~]: the blade-passing tone, its distance law, a stereo pair"

# 1. a drone rotor (2 blades) at 6000 rpm heard in its disc plane: the
#    tone at the blade-passing frequency B rpm / 60 = 200 Hz (Gutin 1936)
pd_render rt-drone "rotor~" 1 2000 \
    "; aero-speed 6000; aero-obj listener 2 0 0"
judge $ANALYZE finite "$OUT/rt-drone.wav" --max 10
judge $ANALYZE peak "$OUT/rt-drone.wav" --expect 200 --tol 0.01 \
    --fmin 50 --fmax 2000 --nfft 32768

# 2. a desk fan: 5 blades at 1200 rpm, 100 Hz (its tones alone: at tip
#    Mach 0.05 the blades' broadband self-noise is some 20 dB louder, as
#    a fan sounds)
pd_render rt-fan "rotor~ -blades 5 -radius 0.15 -chord 0.05 -thrust 0.5 -torque 0.02 -design 1200 -noise -200" 1 2000 \
    "; aero-speed 1200; aero-obj listener 1 0 0.3"
judge $ANALYZE finite "$OUT/rt-fan.wav" --max 10
judge $ANALYZE peak "$OUT/rt-fan.wav" --expect 100 --tol 0.01 \
    --fmin 30 --fmax 2000 --nfft 32768

# 3. twice as far, 6.02 dB lower (the far field's 1/r)
pd_render rt-drone-far "rotor~" 1 2000 \
    "; aero-speed 6000; aero-obj listener 4 0 0"
judge $ANALYZE leveldiff "$OUT/rt-drone.wav" "$OUT/rt-drone-far.wav" \
    --expect -6.02 --tol 0.3

# 4. -stereo: two outlets, both finite and sounding
pd_render rt-stereo "rotor~ -stereo" 2 1000 \
    "; aero-speed 6000; aero-obj ears -0.1 2 0 0.1 2 0"
judge $ANALYZE finite "$OUT/rt-stereo.wav" --max 10
