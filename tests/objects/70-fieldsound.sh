# --- [fieldsound~] in real Pd ------------------------------------------------
section "[fieldsound~]: field auralization (Shin and Bajaj) in Pd"

# [fieldsound~] has no signal inlet: pd_render's [line~] goes into a
# [snapshot~] that is never banged, whose (control) outlet is the chain.
# -sync preprocesses at creation, so `play` at the start of the recording
# is heard from there (the threaded default is tested in 4.)
FS="snapshot~|fieldsound~"

# 1. 1/r: the synthetic burst (24^3, a 1.28 m cube at the origin) heard at
# 4 m and 8 m in the same direction (the burst's turbulence is not
# isotropic: +-3 dB between directions): -6 dB per doubling of distance.
# The sources spread over +-0.6 m, which moves the mean 1/D and the
# cancellation between them by < 0.2 dB at these distances: 1 dB.
pd_render fs-r4 "$FS -demo 24 -sync -listener 4 0 0" 1 400 "" 0 "0 ; aero-obj play"
pd_render fs-r8 "$FS -demo 24 -sync -listener 8 0 0" 1 400 "" 0 "0 ; aero-obj play"
log_clean "$OUT/fs-r4.log" "[fieldsound~ -demo 24 -sync] creates and preprocesses"
if grep -q "preprocessed in" "$OUT/fs-r4.log"; then
    pass "total preprocessing time reported: $(grep -o 'preprocessed in [0-9.]* s ([0-9.]* ms per frame)' "$OUT/fs-r4.log")"
else
    fail "no preprocessing time in the Pd window"; cat "$OUT/fs-r4.log"
fi
judge $ANALYZE finite "$OUT/fs-r4.wav"
judge $ANALYZE level "$OUT/fs-r4.wav" --min 40
judge $ANALYZE leveldiff "$OUT/fs-r4.wav" "$OUT/fs-r8.wav" --expect -6.02 --tol 1

# 2. arrival delay r/c0: at 34.3 m nothing before (34.3 - 1.11)/343 s (the
# cube's half diagonal is 1.11 m), sound within 10 ms of 0.1 s; the 4 m
# render (arrival ~12 ms) fails the same window (negative control)
pd_render fs-far "$FS -demo 24 -sync -listener 34.3 0 0" 1 400 "" 0 "0 ; aero-obj play"
judge $ANALYZE onset "$OUT/fs-far.wav" --min 0.0968 --max 0.11
judge_fails $ANALYZE onset "$OUT/fs-r4.wav" --min 0.0968 --max 0.11

# 3. a volume on disk (aerotex field-demo, same burst) sounds the same as
# the in-memory demo; speed 500 frames/s (half) lowers the monopole level
# (two time derivatives: -12 dB at the same data)
mkdir -p "$OUT/fsvol"
build/aerotex field-demo --size 24 --spacing 0.05333333333 -q \
    -o "$OUT/fsvol/burst24" >/dev/null
pd_render fsvol/fs-disk "$FS burst24 -sync -listener 4 0 0" 1 400 "" 0 "0 ; aero-obj play"
judge $ANALYZE leveldiff "$OUT/fs-r4.wav" "$OUT/fsvol/fs-disk.wav" --expect 0 --tol 0.1
pd_render fs-slow "$FS -demo 24 -sync -listener 4 0 0 -speed 500" 1 400 "" 0 "0 ; aero-obj play"
judge $ANALYZE leveldiff "$OUT/fs-r4.wav" "$OUT/fs-slow.wav" --max -6

# 4. the worker thread: preprocessing does not block Pd; progress and the
# total time are posted, the right outlet says `ready`, which starts the
# recording and `play`; 2.5 s later the recording is written and Pd
# quits. Batch mode runs logical time far ahead of any thread, so this one
# runs Pd in real time (-nosound), as long as the preprocessing takes (a
# fixed 5 s was not always enough on a busy machine), at most 60 s. The
# `demo 64` message starts the preprocessing 200 ms after the scheduler
# runs (with the creation flag it started while Pd was still starting up),
# and the burst is 64^3 (48 frames, ~4 s of work): on a busy machine (two
# Pds side by side in check-pd056) Pd's polls of a 1 s job came too late
# to see it between its quarters, so that no progress was posted.
{
    echo "#N canvas 0 50 450 300 12;"
    echo "#X obj 10 10 loadbang;"                                   # 0
    echo "#X obj 10 40 fieldsound~ -listener 2 0 0;"                # 1
    echo "#X obj 10 70 route ready done;"                           # 2
    echo "#X obj 10 100 t b b;"                                     # 3
    echo "#X msg 100 130 play;"                                     # 4
    echo "#X obj 10 160 tabwrite~ fs-rec;"                          # 5
    echo "#X obj 200 10 array define fs-rec $((2 * PD_RATE));"      # 6
    echo "#X obj 200 70 print ready;"                               # 7
    echo "#X obj 200 100 delay 2500;"                               # 8
    echo "#X msg 200 130 write -bytes 4 $ROOT/$OUT/fs-thread.wav fs-rec;"
    echo "#X obj 200 160 soundfiler;"                               # 10
    echo "#X msg 200 190 \\; pd quit;"                             # 11
    echo "#X msg 300 10 \\; pd dsp 1;"                             # 12
    echo "#X obj 300 40 delay 200;"                                 # 13
    echo "#X msg 300 70 demo 64;"                                   # 14
    for c in "0 0 12 0" "0 0 13 0" "13 0 14 0" "14 0 1 0" "3 0 8 0" "1 1 2 0" "2 0 3 0" "2 0 7 0" "3 0 5 0" \
        "3 1 4 0" "4 0 1 0" "1 0 5 0" "8 0 9 0" "9 0 10 0" "10 0 11 0"; do
        echo "#X connect $c;"
    done
} >"$OUT/fs-thread.pd"
rm -f "$OUT/fs-thread.wav"
timeout 60 "$PD" -nogui -nosound -noprefs -stderr -nostdpath -r "$PD_RATE" -path "$ROOT" \
    -open "$OUT/fs-thread.pd" >"$OUT/fs-thread.log" 2>&1
if grep -q "preprocessed in" "$OUT/fs-thread.log" &&
    grep -q "^ready:" "$OUT/fs-thread.log" &&
    grep -q "preprocessing demo burst 64^3: [0-9]*% " "$OUT/fs-thread.log"; then
    pass "threaded preprocessing: progress posted ($(grep -c '[0-9]*% (' "$OUT/fs-thread.log") lines), $(grep -o 'preprocessed in [0-9.]* s' "$OUT/fs-thread.log"), then 'ready' on the right outlet"
else
    fail "threaded preprocessing did not report"; cat "$OUT/fs-thread.log"
fi
judge $ANALYZE finite "$OUT/fs-thread.wav"
judge $ANALYZE level "$OUT/fs-thread.wav" --min 60

# 5. malformed volumes: clear errors naming the file, the object still
# works (silent until something is opened)
mkdir -p "$OUT/fsvol/badhdr" "$OUT/fsvol/trunc"
printf 'aero-volume 1\ndims 4 4\n' >"$OUT/fsvol/badhdr/volume.txt"
printf 'aero-volume 1\ndims 4 4 4\nspacing 1 1 1\nrate 10\nframes 2\nfields density\n' \
    >"$OUT/fsvol/trunc/volume.txt"
head -c 256 /dev/zero >"$OUT/fsvol/trunc/frame00000.f32"
head -c 100 /dev/zero >"$OUT/fsvol/trunc/frame00001.f32"
pd_render fsvol/fs-badhdr "$FS badhdr -sync" 1 300 "" 0 "0 ; aero-obj play"
pd_render fsvol/fs-trunc "$FS trunc -sync" 1 300 "" 0 "0 ; aero-obj play"
for c in "fs-badhdr:'dims' needs three whole numbers" \
    "fs-trunc:frame00001.f32 is 100 bytes, expected 256" \
    "fs-trunc:truncated"; do
    if grep -q -F "${c#*:}" "$OUT/fsvol/${c%%:*}.log"; then
        pass "${c%%:*}: error says '${c#*:}'"
    else
        fail "${c%%:*}: no error '${c#*:}'"; cat "$OUT/fsvol/${c%%:*}.log"
    fi
done
judge $ANALYZE finite "$OUT/fsvol/fs-trunc.wav"

# 6. bad flags and messages: each reported, output finite
pd_render fs-bad "$FS no-such-volume -sync -bogus -speed -1 -threshold 0 1 1 -demo 1" \
    1 1000 "" 0 "0 ; aero-obj play" \
    "100 ; aero-obj listener 1; aero-obj map 0 0 0 1; aero-obj speed 0" \
    "200 ; aero-obj demo 2000; aero-obj zero 3; aero-obj gain 1e9" \
    "300 ; aero-obj listener 1e9 0 0; aero-obj open nowhere; aero-obj ramp -1" \
    "400 ; aero-obj demo 12; aero-obj play; aero-obj listener 0 0 0"
judge $ANALYZE finite "$OUT/fs-bad.wav" --max 1e5
reports_at_least "$OUT/fs-bad.log" "[fieldsound~]" 13
