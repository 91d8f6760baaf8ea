# Sourced by the Pd cost benchmarks (bench/object.sh, bench/rotor.sh), not
# run alone: the CPU time of a batch-mode Pd render of $DIR/NAME.pd at $RATE
# (user + system, /usr/bin/time), and the fastest of three (the least
# disturbed by the machine). Needs ROOT, DIR and RATE set.
brun() { # NAME: seconds of CPU
    /usr/bin/time -f "%U %S" -o "$DIR/$1.time" timeout 3600 pd -batch \
        -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
        -path "$ROOT" -open "$DIR/$1.pd" >"$DIR/$1.log" 2>&1
    awk '{ printf "%.3f", $1 + $2 }' "$DIR/$1.time"
}
bbest() { # NAME: the fastest of three brun
    b=""
    for k in 1 2 3; do
        t=$(brun "$1")
        b=$(echo "$b $t" | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i < m) m = $i; print m }')
    done
    echo "$b"
}
