# --- hostile input for every object, from each object's own configurations
# (tests/robust/objects/CLASS.txt, gathered by tests/robust/object-table.sh)
# Per configuration line and sample rate (22050 ... 192000 Hz) one Pd run
# of ~1 s of logical time with, for the object:
#   - one instance per block size 1, 2, 4, ... 8192 ([block~ N]
#     subpatches), fed speeds 10, 0, -10, 1e30, NaN, Inf, a denormal, 100;
#     after each instance its outlets go through "is it finite?" into
#     [rpole~ 1] counters, printed at the end with the samples each ran;
#   - the table's hostile messages (NaN/Inf made by [expr]) before DSP
#     starts and again while it runs, plus generic abuse (bang, unknown
#     selectors, symbol lists);
#   - the file message with a missing file, a directory, an empty file, a
#     truncated and a garbage file, a WAV without metadata, a path in a
#     missing folder, an unreadable file (chmod 000; root reads it anyway);
#   - the good file loaded while DSP is switched off and on around it;
#   - in a subpatch, instances created by dynamic patching with the table's
#     hostile creation args (NaN/Inf included) and a working one, all
#     deleted while DSP runs, re-created, deleted again.
# Pass: every instance was created, Pd quits normally and prints every
# counter, no NaN/Inf reached an
# outlet, every instance ran, every "error:" line names the object.
# ONLY=name (tests/run.sh) runs the lines of the classes whose name contains
# it, unless it names this script; HOSTILE_ONLY=class and
# HOSTILE_RATES="..." narrow it down by hand; HOSTILE_TIMEOUT (300 s of
# wall time per Pd run: a hang, not a slow shared machine) is raised by
# check-asan.sh; HOSTILE_JOBS (default 1) Pd runs go side by side.
case "tests/objects/90-hostile.sh" in
    *"${ONLY:-}"*) hostile_only=${HOSTILE_ONLY:-} ;;
    *) hostile_only=${ONLY:-} ;;
esac
hostile_table=$(sh tests/robust/object-table.sh hostile)
if ! printf '%s\n' "$hostile_table" | cut -d'|' -f1 |
    grep -q -F -e "$hostile_only"; then
    return 0 2>/dev/null || exit 0 # no class of the table in this run
fi
section "hostile input: every object of tests/robust/objects/*.txt in Pd"
HOSTILE=$OUT/hostile
mkdir -p "$HOSTILE"
# The bad files, next to the patches (where canvas_open looks first), one
# maker per kind of file an object loads; the file field of the table
# names the kind (sel:good:kind, default wav). A new kind joins with one
# hostile_files_KIND function that makes its bad files in $HOSTILE and sets
# hostile_bad to their names (as given to the file message).
hostile_bad_common="no-such-file dir empty truncated garbage plain short unreadable"
awk 'BEGIN { srand(7); for (i = 0; i < 4096; i++) printf "%c", int(rand() * 256) }' \
    >"$HOSTILE/garbage.bin" 2>/dev/null
hostile_files_wav() { # textures (libsndfile WAV)
    rm -rf "$HOSTILE/dir.wav"
    mkdir -p "$HOSTILE/dir.wav"
    : >"$HOSTILE/empty.wav"
    head -c 1000 textures/cylinder.wav >"$HOSTILE/truncated.wav"
    cp "$HOSTILE/garbage.bin" "$HOSTILE/garbage.wav"
    cp textures/cylinder.wav "$HOSTILE/unreadable.wav"
    chmod 000 "$HOSTILE/unreadable.wav"
    sox -n -r 16000 -c 3 -b 32 -e floating-point "$HOSTILE/plain.wav" synth 0.1 sine 300 \
        2>/dev/null || cp "$HOSTILE/garbage.wav" "$HOSTILE/plain.wav"
    # a texture whose header claims more frames than it holds
    cp textures/cylinder.wav "$HOSTILE/short.wav"
    truncate -s 20000 "$HOSTILE/short.wav"
    hostile_bad="$hostile_bad_common /no/such/folder/x.wav 12"
}
hostile_files_tree() { # tree files (trees/README.md)
    rm -rf "$HOSTILE/dir.tree"
    mkdir -p "$HOSTILE/dir.tree"
    : >"$HOSTILE/empty.tree"
    head -c 1000 trees/small.tree >"$HOSTILE/truncated.tree" # cut mid-line
    cp "$HOSTILE/garbage.bin" "$HOSTILE/garbage.tree"
    cp trees/small.tree "$HOSTILE/unreadable.tree"
    chmod 000 "$HOSTILE/unreadable.tree"
    # every kind of bad record, between good ones
    {
        echo "branch 0 -1 0 0 0 0 0 1 0.05 0.04"
        echo "branch 1 0 0 0 1 nan 0 2 0.02 0.02"
        echo "branch 2 0 0 0 1 inf 0 2 0.02 0.02"
        echo "branch 3 3 0 0 1 0 1 2 0.02 0.02"
        echo "branch 4 99 0 0 1 0 1 2 0.02 0.02"
        echo "branch 5 0 0 0 1 0 0 1 0.02 0.02"
        echo "branch 6 0 0 0 1 1e30 0 1e30 0.02 0.02"
        echo "branch 7 0 0 0 1 0 1 2 -1 0.02"
        echo "branch 8 0 0 0 1 0 1 2 0 0"
        echo "branch 0 -1 0 0 0 0 0 1 0.05 0.04"
        echo "branch -3 -1 0 0 0 0 0 1 0.05 0.04"
        echo "branch 99999999999999999999 -1 0 0 0 0 0 1 0.05 0.04"
        echo "branch 2147483647 0 0 0 1 0 0 1.5 1e-30 1e-30"
        echo "branch 9 0 0 0 1 0 0 2"
        echo "branch 10 0 0 0 1 0 0 2 0.1 0.1 0.1 0.1"
        echo "branch 0x10 0 0 0 1 0 0 2 0.1 0.1"
        echo "leaf 0 0 0 0.5 0.1 0 0.5 0.05 0.03"
        echo "leaf 77 0 0 0.5 0.1 0 0.5 0.05 0.03"
        echo "leaf 0 0 0 0.5 0 0 0.5 0.05 0.03"
        echo "leaf 0 0 0 0.5 0.1 0 0.5 -1 0.03"
        echo "leaf 0 0 0 0.5 0.1 0 0.5 1e30 1e30"
        echo "leaf 0 nan 0 0.5 0.1 0 0.5 0.05 0.03"
        echo "twig 1 2 3"
        printf 'branch 11 0 0 0 1 0 0 2 0.1 0.1\r\n'
        printf 'leaf\t0\t0 0 0.5 0 0.1 0.5 0.05 0.03\n'
        awk 'BEGIN { printf "branch 12 0"; for (i = 0; i < 20000; i++) printf " 1"; print "" }'
        printf 'branch 13 0 0 0 1 0 0 2 0.1 0.1'   # no newline at the end
    } >"$HOSTILE/plain.tree"
    # valid but extreme: 1500 leaves at one point (every pair a neighbour),
    # a branch of 1e4 m and one of a micrometre
    {
        echo "branch 0 -1 0 0 0 0 0 1 0.05 0.04"
        echo "branch 1 0 0 0 1 0 0 10001 0.05 0.04"
        echo "branch 2 0 0 0 1 0 0 1.000001 1e-6 1e-6"
        awk 'BEGIN { for (i = 0; i < 1500; i++) print "leaf 0 0 0 0.5 0.1 0 0.5 0.05 0.03" }'
    } >"$HOSTILE/short.tree"
    hostile_bad="$hostile_bad_common /no/such/folder/x.tree 12"
}
hostile_files_volume() { # volume directories (src/core/common/field_volume.h)
    for _v in dir empty truncated garbage plain short unreadable huge pattern \
        nan; do
        [ -d "$HOSTILE/$_v" ] && chmod -R u+rwx "$HOSTILE/$_v"
        rm -rf "${HOSTILE:?}/$_v"
        mkdir -p "$HOSTILE/$_v"
    done
    _hdr='aero-volume 1\ndims 8 8 8\nspacing 0.1 0.1 0.1\nrate 1000\nframes 4\nfields density\n'
    : >"$HOSTILE/empty/volume.txt"
    printf 'aero-volume 1\ndims 8 8' >"$HOSTILE/truncated/volume.txt"
    cp "$HOSTILE/garbage.bin" "$HOSTILE/garbage/volume.txt"
    # numbers that are not: nan, inf, hex, negative, overflowing
    printf 'aero-volume 1\ndims 8 8 nan\nspacing inf -1 0x10\nrate 1e400\nframes -3\n' \
        >"$HOSTILE/nan/volume.txt"
    # frames missing or truncated
    printf "$_hdr" >"$HOSTILE/short/volume.txt"
    head -c 2048 /dev/zero >"$HOSTILE/short/frame00000.f32"
    head -c 100 /dev/zero >"$HOSTILE/short/frame00001.f32"
    # the largest header allowed (1024^3 x 1e6 frames) without its data
    printf 'aero-volume 1\ndims 1024 1024 1024\nspacing 0.1 0.1 0.1\nrate 1000\nframes 1000000\nfields density vx vy vz\n' \
        >"$HOSTILE/huge/volume.txt"
    # the good one
    rm -rf "$HOSTILE/burst"
    build/aerotex field-demo --size 12 --spacing 0.1 -q -o "$HOSTILE/burst" >/dev/null
    # the good one with NaN, +Inf, -Inf (float32 0x7fc00000, 0x7f800000,
    # 0xff800000, little-endian) over the first third of each frame
    cp "$HOSTILE"/burst/* "$HOSTILE/plain/"
    printf '\000\000\300\177\000\000\200\177\000\000\200\377' >"$HOSTILE/nan.bin"
    for _k in 1 2 3 4 5 6 7 8; do
        cat "$HOSTILE/nan.bin" "$HOSTILE/nan.bin" >"$HOSTILE/nan2.bin"
        mv "$HOSTILE/nan2.bin" "$HOSTILE/nan.bin"
    done
    for _k in "$HOSTILE"/plain/*.f32; do
        dd if="$HOSTILE/nan.bin" of="$_k" bs=2304 count=1 conv=notrunc 2>/dev/null
    done
    # a printf attack in the file name pattern
    printf 'aero-volume 1\ndims 8 8 8\nspacing 0.1 0.1 0.1\nrate 1000\nframes 4\nfields density\nfiles %%s%%n%%d\n' \
        >"$HOSTILE/pattern/volume.txt"
    cp "$HOSTILE"/burst/* "$HOSTILE/unreadable/"
    chmod 000 "$HOSTILE"/unreadable/*
    hostile_bad="$hostile_bad_common huge pattern nan /no/such/folder/x 12"
}

hostile_blocks="1 2 4 8 16 32 64 128 256 512 1024 2048 4096 8192"
hostile_rates=${HOSTILE_RATES:-22050 44100 48000 96000 192000}
trim() { printf '%s' "$1" | sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//'; }
# message-box text: NAN -> $1, INF -> $2 (the box is fed "NaN Inf"),
# ';' and ',' escaped, '$' escaped for the file format
hostile_box() {
    printf '%s' "$1" | sed -e 's/\bNAN\b/\\$1/g' -e 's/\bINF\b/\\$2/g' \
        -e 's/;/ \\; /g' -e 's/,/ \\, /g'
}

# writing a patch: pd_obj TEXT appends "#X TEXT;" and sets $_last to its
# index; pd_conn A OUTLET B INLET
pd_obj() { echo "#X $1;" >>"$_f"; _last=$_n; _n=$((_n + 1)); }
pd_conn() { echo "#X connect $1 $2 $3 $4;" >>"$_f"; }
# an event at MS ms after load: a message box fed the list "NaN Inf"
pd_event() {
    pd_obj "obj 300 $((100 + _n * 3)) delay $1"; _d=$_last
    pd_obj "obj 300 $((100 + _n * 3)) list append"; _la=$_last
    pd_obj "msg 300 $((100 + _n * 3)) $(hostile_box "; ${2#; }")"
    pd_conn $_d 0 $_la 0; pd_conn $_la 0 $_last 0
    pd_conn "$_start" 0 $_d 0; pd_conn "$_nan" 0 $_la 1
}

# a subpatch NAME with [block~ N] around OBJECT (NOUT signal outlets, or
# NOUT/NIN with NIN = 0 for an object without a signal inlet): fed
# hostile speeds, it counts the non-finite samples on the outlets and the
# samples it ran, and prints "NAME: bad samples" on hostile-report
hostile_sub() {
    _sname=$1 _sblock=$2 _sobj=$3 _snout=${4%%/*} _snin=1
    case "$4" in */*) _snin=${4#*/} ;; esac
    {
        echo "#N canvas 0 0 500 400 $_sname 0;"
        echo "#X obj 10 10 block~ $_sblock;"                            # 0
        echo "#X obj 10 30 r hostile-speed;"                            # 1
        echo "#X obj 10 50 sig~ 10;"                                    # 2
        echo "#X obj 10 70 expr~ if(\\\$v1 == 777 \\, \\\$v1*1e30*1e30 - \\\$v1*1e30*1e30 \\, if(\\\$v1 == 888 \\, \\\$v1*1e30*1e30 \\, \\\$v1));"  # 3
        echo "#X obj 10 90 $_sobj;"                                     # 4
        echo "#X obj 10 110 expr~ if(abs(\\\$v1) < 1e30 \\, 0 \\, 1);"   # 5
        echo "#X obj 150 110 expr~ if(abs(\\\$v1) < 1e30 \\, 0 \\, 1);"  # 6
        echo "#X obj 10 130 rpole~ 1;"                                  # 7
        echo "#X obj 10 150 snapshot~;"                                 # 8
        echo "#X obj 150 130 sig~ 1;"                                   # 9
        echo "#X obj 150 150 rpole~ 1;"                                 # 10
        echo "#X obj 150 170 snapshot~;"                                # 11
        echo "#X obj 10 190 r hostile-report;"                          # 12
        echo "#X obj 10 210 t b b;"                                     # 13
        echo "#X obj 10 230 pack f f;"                                  # 14
        echo "#X obj 10 250 print $_sname;"                             # 15
        echo "#X obj 200 30 r hostile-obj;"                             # 16
        # the hostile speeds into the signal inlet, if it has one
        [ "$_snin" -ge 1 ] && echo "#X connect 3 0 4 0;"
        for _c in "1 0 2 0" "2 0 3 0" "4 0 5 0" "5 0 7 0" \
            "7 0 8 0" "9 0 10 0" "10 0 11 0" "12 0 13 0" "13 1 11 0" \
            "13 0 8 0" "8 0 14 0" "11 0 14 1" "14 0 15 0"; do
            echo "#X connect $_c;"
        done
        # messages only to the object under test
        case "$_sname" in hostile-block*) echo "#X connect 16 0 4 0;" ;; esac
        [ "$_snout" -ge 2 ] && echo "#X connect 4 1 6 0;" && echo "#X connect 6 0 7 0;"
    } >>"$_f"
    pd_obj "restore 200 $((400 + _n * 5)) pd $_sname"
}

# hostile_patch FILE CLASS ARGS NOUT SEL:GOOD NEWARGS MESSAGES
hostile_patch() {
    _f=$1 _cls=$2 _args=$3 _nout=$4 _sel=${5%%:*} _good=${5#*:}
    _good=${_good%%:*}
    _new=$6 _msgs=$7 _n=0
    _abuse="bang; foo 1 2; list a b c; symbol x; 1 2 3; set"
    _files=""
    if [ "$_sel" != "-" ]; then
        for _bad in $hostile_bad; do
            _files="$_files; hostile-obj $_sel $_bad"
        done
        _files="$_files; hostile-obj $_sel"
    fi
    _all=""
    _old_ifs=$IFS
    IFS=';'
    for _m in $_msgs; do
        _m=$(trim "$_m")
        [ -n "$_m" ] && _all="$_all; hostile-obj $_m"
    done
    for _m in $_abuse; do _all="$_all; hostile-obj $(trim "$_m")"; done
    IFS=$_old_ifs
    # dynamic patching into pd-victim: the hostile creation lines, then a
    # working instance
    _create=""
    _y=10
    IFS=','
    for _a in $_new; do
        _create="$_create; pd-victim obj 10 $_y $_cls $(trim "$_a")"
        _y=$((_y + 30))
    done
    IFS=$_old_ifs
    _create="$_create; pd-victim obj 10 $_y $_cls $_args"
    _reload=""
    [ "$_sel" != "-" ] && _reload="; pd dsp 0; hostile-obj $_sel $_good; pd dsp 1; hostile-obj $_sel $_good; pd dsp 0; pd dsp 1; hostile-obj $_sel $_good"
    echo "#N canvas 0 50 900 700 10;" >"$_f"
    pd_obj "obj 10 10 loadbang"; _lb=$_last
    pd_obj "obj 10 30 t b b b"; _t=$_last
    pd_obj "obj 10 50 t b b"; _tn=$_last
    pd_obj "obj 10 70 expr 1e30*1e30 - 1e30*1e30"; _en=$_last
    pd_obj "obj 10 90 expr 1e30*1e30"; _ei=$_last
    pd_obj "obj 10 110 pack f f"; _nan=$_last
    pd_obj "obj 10 130 t b"; _start=$_last
    pd_conn $_lb 0 $_t 0; pd_conn $_t 1 $_tn 0; pd_conn $_t 0 $_start 0
    pd_conn $_tn 1 $_ei 0; pd_conn $_tn 0 $_en 0
    pd_conn $_ei 0 $_nan 1; pd_conn $_en 0 $_nan 0
    # speeds: every 60 ms the next hostile value (777 -> NaN, 888 -> Inf)
    pd_obj "obj 10 200 array define hostile-speeds 9"
    pd_obj "msg 10 220 \\; hostile-speeds 0 10 0 -10 1e+30 777 888 1e-40 100 10"
    pd_conn $_t 2 $_last 0
    pd_obj "obj 10 240 metro 60"; _m0=$_last
    pd_obj "obj 10 260 f"; _m1=$_last
    pd_obj "obj 50 260 + 1"; _m2=$_last
    pd_obj "obj 10 280 mod 9"; _m3=$_last
    pd_obj "obj 10 300 tabread hostile-speeds"; _m4=$_last
    pd_obj "obj 10 320 s hostile-speed"; _m5=$_last
    pd_conn $_start 0 $_m0 0; pd_conn $_m0 0 $_m1 0; pd_conn $_m1 0 $_m2 0
    pd_conn $_m2 0 $_m1 1; pd_conn $_m1 0 $_m3 0; pd_conn $_m3 0 $_m4 0
    pd_conn $_m4 0 $_m5 0
    echo "#N canvas 0 0 300 200 victim 0;" >>"$_f"
    pd_obj "restore 10 400 pd victim"
    # the events
    pd_event 0 "$_all; pd dsp 1"      # before DSP, then DSP on
    pd_event 100 "$_all"              # while it runs
    pd_event 200 "${_files#; }$_reload"
    pd_event 300 "${_create#; }"
    pd_event 450 "pd-victim clear"
    pd_event 550 "${_create#; }"
    pd_event 700 "pd-victim clear; hostile-report bang"
    pd_event 800 "pd quit"
    for _b in $hostile_blocks; do
        hostile_sub "hostile-block$_b" "$_b" "$_cls $_args" "$_nout"
    done
    # negative control: the same counter after an object that does put
    # Inf on its outlet ([expr~] of speed x 1e60) must count it
    hostile_sub hostile-control 64 "expr~ \\\$v1*1e30*1e30" 1
}

# hostile_judge LOG CLASS NMESSAGES: the verdicts of one run
hostile_judge() {
    _log=$1 _cls=$2 _what=$3
    _blocks=$(grep -a -c "^hostile-block[0-9]*: " "$_log")
    _want=$(echo $hostile_blocks | wc -w)
    if [ "$_blocks" -ne "$_want" ]; then
        fail "$_what: Pd did not survive ($_blocks of $_want counters printed)"
        grep -a -v "^hostile-block" "$_log" | tail -15 | sed 's/^/        /'
        return
    fi
    # an object that was never created would pass the rest (its counters
    # run on, fed by nothing)
    if grep -a -q -e "couldn't create" -e "can't load" "$_log"; then
        fail "$_what: $_cls was not created:"
        grep -a -B1 -e "couldn't create" -e "can't load" "$_log" | head -6 | sed 's/^/        /'
        return
    fi
    _bad=$(grep -a "^hostile-block[0-9]*: " "$_log" | awk '$2 != 0' | head -3)
    _idle=$(grep -a "^hostile-block[0-9]*: " "$_log" | awk '!($3 > 0)' | head -3)
    if [ -n "$_bad" ]; then
        fail "$_what: NaN/Inf reached an outlet (block: bad samples, samples): $_bad"
    elif [ -n "$_idle" ]; then
        fail "$_what: an instance never ran: $_idle"
    elif ! grep -a "^hostile-control: " "$_log" | awk '{ exit !($2 > 0) }'; then
        fail "$_what: the negative control (an Inf source) was not counted"
    else
        pass "$_what: survived, outlets finite at block sizes 1..8192 (control: $(grep -a "^hostile-control: " "$_log" | awk '{print $2}') Inf samples counted)"
    fi
    # the object's name: "[aeolian~]" in its own errors, "aeolian~" in
    # Pd's (no method for ...)
    _anon=$(grep -a "^error: " "$_log" | grep -v -F -e "$_cls" | head -5)
    _named=$(grep -a "^error: " "$_log" | grep -c -F -e "$_cls")
    if [ -n "$_anon" ]; then
        fail "$_what: errors that do not name $_cls:"
        echo "$_anon" | sed 's/^/        /'
    elif [ "$_named" -lt "$4" ]; then
        fail "$_what: only $_named errors for $4 bad inputs"
    else
        pass "$_what: all $_named errors name $_cls"
    fi
}

_line_no=0
printf '%s\n' "$hostile_table" | grep -v '^[[:space:]]*$' >"$HOSTILE/table.txt"
while IFS='|' read -r h_cls h_args h_nout h_file h_new h_msgs; do
    _line_no=$((_line_no + 1))
    h_cls=$(trim "$h_cls") h_args=$(trim "$h_args") h_nout=$(trim "$h_nout")
    h_file=$(trim "$h_file")
    h_kind=wav
    case "$h_file" in *:*:*) h_kind=${h_file##*:} ;; esac
    case "$h_cls" in *"${HOSTILE_ONLY:-}"*) ;; *) continue ;; esac
    case "$h_cls" in *"$hostile_only"*) ;; *) continue ;; esac
    # at least one report per hostile message and bad file
    h_min=$(( $(printf '%s' "$h_msgs" | tr -cd ';' | wc -c) + 1 ))
    if [ "$h_file" != "-" ]; then
        "hostile_files_$h_kind"
        h_min=$((h_min + $(echo $hostile_bad | wc -w)))
    fi
    h_jobs=0
    for h_rate in $hostile_rates; do
        h_name="hostile-$_line_no-$h_rate"
        hostile_patch "$HOSTILE/$h_name.pd" "$h_cls" "$h_args" "$h_nout" \
            "$h_file" "$h_new" "$h_msgs"
        # shellcheck disable=SC2086
        (cd "$HOSTILE" && timeout "${HOSTILE_TIMEOUT:-300}" "$PD" $PD_BASE_FLAGS -nrt -r "$h_rate" -path "$ROOT" \
            -open "$h_name.pd" </dev/null >"$h_name.log" 2>&1
            echo $? >"$h_name.status") &
        h_jobs=$((h_jobs + 1))
        [ "$h_jobs" -ge "${HOSTILE_JOBS:-1}" ] && { wait; h_jobs=0; }
    done
    wait
    for h_rate in $hostile_rates; do
        h_name="hostile-$_line_no-$h_rate"
        h_status=$(cat "$HOSTILE/$h_name.status")
        [ "$h_status" -ne 0 ] && { fail "[$h_cls $h_args] at $h_rate Hz: Pd exited $h_status"; tail -5 "$HOSTILE/$h_name.log"; }
        hostile_judge "$HOSTILE/$h_name.log" "$h_cls" "[$h_cls $h_args] at $h_rate Hz" "$h_min"
    done
done <"$HOSTILE/table.txt"
chmod 600 "$HOSTILE"/unreadable.* 2>/dev/null
[ -d "$HOSTILE/unreadable" ] && chmod -R u+rwx "$HOSTILE/unreadable"

# --- the hostile cases of issue 49: each input and the words it must get ---
# One line per case: class | the object (its creation text) | messages at
# load (after "; aero-speed 10" unless they set it) | what the log must
# say ("!text": must not say; "once:text": say exactly once) | the largest
# |sample| allowed, or -, then optionally the lowest level allowed in dB
# SPL (not silent) | optionally, events "MS ; messages" separated by ','.
# Files made here: F.wav is fire.wav with its first 1000 floats 3e38
# (finite, impossible); T1.tree a tree whose second branch ends at
# (1e30, 1e30, 1e30); folder.wav a folder. The Pd runs are short (0.5 s)
# and at one rate. HOSTILE_CASES_ONLY=text narrows them down.
section "hostile cases: physical ceilings and messages that say what happened"
python3 - "$HOSTILE/F.wav" <<'PYEOF'
import struct, sys
d = bytearray(open("textures/fire.wav", "rb").read())
p = 12
while p + 8 <= len(d):
    size = int.from_bytes(d[p + 4:p + 8], "little")
    if d[p:p + 4] == b"data":
        d[p + 8:p + 8 + 4000] = struct.pack("<f", 3e38) * 1000
        break
    p += 8 + size + (size & 1)
open(sys.argv[1], "wb").write(d)
PYEOF
{
    echo "branch 0 -1 0 0 0 0 0 1 0.05 0.04"
    echo "branch 1 0 0 0 1 1e30 1e30 1e30 0.02 0.02"
    echo "branch 2 0 0 0 1 0 1 2 0.02 0.02"
    echo "leaf 2 0 0.5 1.5 0 0.6 1.5 0.05 0.03"
} >"$HOSTILE/T1.tree"
# blade tables ([rotor~] blade): r/R falling, a NaN, a chord of 1e9 m,
# one over 64 KiB, binary data
printf '0.5 0.1 10\n0.2 0.1 10\n' >"$HOSTILE/falling.blade"
printf '0.2 0.1 10\n0.5 nan 10\n' >"$HOSTILE/nan.blade"
printf '0.2 1e9 10\n0.5 0.1 10\n' >"$HOSTILE/absurd.blade"
python3 -c "import sys; sys.stdout.write('# padding\\n' * 8000)" >"$HOSTILE/big.blade"
head -c 3000 /dev/urandom >"$HOSTILE/garbage.blade"
rm -rf "$HOSTILE/folder.wav" && mkdir -p "$HOSTILE/folder.wav"
head -c 1000 textures/cylinder.wav >"$HOSTILE/cut.wav"
# metadata that contradicts itself, same length as the shipped values
sed 's/xfade=320/xfade=9e9/' textures/cylinder.wav >"$HOSTILE/xfade.wav"
H=$ROOT/$HOSTILE
hostile_cases="
vortex~ | vortex~ -texture $H/F.wav -n 8 | ; aero-speed 8 | beyond what a flow of that speed can make | 1
aeolian~ | aeolian~ -texture $H/cut.wav | | !cut.wav: / | -
vortex~ | vortex~ -texture fire -n 8 | ; aero-speed 8; aero-obj texture $H/F.wav | the previous texture stays | -
treebranch~ | treebranch~ $H/T1.tree -listener 0 -5 0.5 | ; aero-speed 10 | farther from the tree's foot than any tree reaches | 101325
aeolian~ | aeolian~ -d 10 -l 1000 -gain 120 -listener 0 0.5 0 | ; aero-speed 100 | output beyond 101325 Pa | 101325
aeolian~ | aeolian~ | ; aero-obj diameter 1e-05; aero-obj length 1e-05 | !out of range | -
cavity~ | cavity~ | ; aero-obj length 0.0001 | !out of range | -
vortex~ | vortex~ -texture fire | ; aero-obj strouhal 0.01 | !out of range | -
leafwave~ | leafwave~ small | ; aero-obj flutter 0.01 | !out of range | -
treebranch~ | treebranch~ small | ; aero-obj wind 1e30 0 0 | wind out of range (0..1029 m/s | -
leafwave~ | leafwave~ small | ; aero-obj tables 128; aero-obj octaves 8 | at most 512 in all (with tables 128: octaves at most 4) | -
body~ | body~ -texture fire | | it is a vortex texture, for [vortex~] | -
treebranch~ | treebranch~ $ROOT/textures/sword.wav | | sword.wav is not a tree file | -
aeolian~ | aeolian~ -texture $H/folder.wav | | is a folder, not a texture file | -
fieldsound~ | fieldsound~ -demo 1000 -sync | | the demo runs at 32 | -
fieldsound~ | fieldsound~ -demo 1000 -sync | | !flag -demo ignored | -
treebranch~ | treebranch~ small | ; aero-obj seed -5 | !out of range | -
body~ | body~ -texture sphere -listener 0 2 0 | ; aero-speed 1e30 | Mach 0.3 | -
treebranch~ | treebranch~ small | ; aero-speed 1e30 | Mach 0.3 | -
aeolian~ | aeolian~ -texture cylinder | ; aero-speed 1e30; aero-obj pose 0 0 -0.1 0 0 0.1; aero-obj wind 5 0 0 | Mach 0.3 | -
body~ | body~ -texture sphere -listener 0 2 0 | ; aero-speed 0 | Mach 0.3 | - | 100 ; aero-obj pose 0 0 0, 110 ; aero-obj pose 10 0 0, 120 ; aero-obj pose 20 0 0, 130 ; aero-obj pose 30 0 0
body~ | body~ | | no texture given | -
aeolian~ | aeolian~ -texture $H/xfade.wav | | xfade=9e+09 frames is not within | -
treebranch~ | treebranch~ | | no tree given | -
fieldsound~ | fieldsound~ -demo 8 -sync | ; aero-obj log 5 | log 5 out of range (0..1 | -
fieldsound~ | fieldsound~ -demo 8 -sync | ; aero-obj velocity 7 | velocity 7 out of range (0..1 | -
fieldsound~ | fieldsound~ -demo 8 -sync | ; aero-obj speed 1e-30 | speed 1e-30 frames/s out of range (0.001.. | -
rotor~ | rotor~ | ; aero-obj blades 0 | blades 0 out of range (1..16 | -
rotor~ | rotor~ | ; aero-obj struts 0 | struts 0 out of range (1..32 | -
rotor~ | rotor~ -struts 2.5 | | struts 2.5 | -
rotor~ | rotor~ | ; aero-obj distortion 1.5 | distortion 1.5 out of range (-1..1 | -
rotor~ | rotor~ -distortion -1.5 | | distortion -1.5 out of range (-1..1 | -
rotor~ | rotor~ | ; aero-obj wake 0 | wake 0 m out of range (0.001..100 m | -
rotor~ | rotor~ -struts 32 -distortion 1 -wake 0.001 -listener 0 0 1 | ; aero-speed 6000 | !error | 10
rotor~ | rotor~ -blade $H/falling.blade | | does not rise from 0.5: the previous blade stays | -
rotor~ | rotor~ -blade $H/nan.blade | | line 2: not three finite numbers | -
rotor~ | rotor~ -blade $H/big.blade | | larger than 65536 bytes | -
rotor~ | rotor~ -blade $H/garbage.blade | | blade: | -
rotor~ | rotor~ | ; aero-obj blade $H/absurd.blade | chord 1e+09 m | -
rotor~ | rotor~ | ; aero-obj blade nosuchfile | can't find 'nosuchfile' | -
rotor~ | rotor~ -radius 47 -blades 3 -blade turbine | ; aero-speed 16 | !blade: | -
rotor~ | rotor~ -listener 0 2 0 | ; aero-speed 1e30 | rpm clamped where the blade tips reach Mach 0.9 | -
rotor~ | rotor~ -listener 0 0 0 | ; aero-speed 6000 | once:listener within 0.24 m of the source: heard as at 0.24 m | - 40
aeolian~ | aeolian~ -listener 0 0 0 | | once:listener within 0.01 m of the source: heard as at 0.01 m | - 40
aeolian~ | aeolian~ -texture cylinder -n 1 -listener 0 0 0 | ; aero-obj pose 0 0 -0.1 0 0 0.1; aero-obj wind 5 0 0 | once:listener within 0.005 m of the source: heard as at 0.005 m | - 60
body~ | body~ -texture sphere -listener 0 0 0 | | once:listener within 0.025 m of the source: heard as at 0.025 m | - 30
cavity~ | cavity~ -listener 0 0 0 | | once:listener within 0.0316228 m of the source: heard as at 0.0316228 m | - 50
cavity~ | cavity~ -texture cavity -listener 0 0 0 | | once:listener within 0.0316228 m of the source: heard as at 0.0316228 m | - 50
vortex~ | vortex~ -texture fire -n 1 -listener 0 0 0 | | once:listener within 0.05 m of the source: heard as at 0.05 m | - 40
treebranch~ | treebranch~ small -listener 0 0 0.6 | | once:listener within 0.1 m of the source: heard as at 0.1 m | - 60
leafwave~ | leafwave~ small -listener 0 0 0.6 | | once:listener within 0.1 m of the source: heard as at 0.1 m | - 60
fieldsound~ | fieldsound~ -demo 8 -sync -listener 0.08 0.08 0.08 | | once:listener within 0.08 m of the source: heard as at 0.08 m | 101325 100 | 0 ; aero-obj play
"
hostile_case_no=0
printf '%s\n' "$hostile_cases" | grep -v '^[[:space:]]*$' >"$HOSTILE/cases.txt"
while IFS='|' read -r c_cls c_obj c_init c_want c_peak c_events; do
    hostile_case_no=$((hostile_case_no + 1))
    c_cls=$(trim "$c_cls") c_obj=$(trim "$c_obj") c_init=$(trim "$c_init")
    c_want=$(trim "$c_want") c_peak=$(trim "$c_peak")
    c_floor=${c_peak#* } c_peak=${c_peak%% *}
    [ "$c_floor" = "$c_peak" ] && c_floor=
    case "$c_cls" in *"$hostile_only"*) ;; *) continue ;; esac
    case "$c_obj $c_init $c_want" in *"${HOSTILE_CASES_ONLY:-}"*) ;; *) continue ;; esac
    case "$c_init" in *aero-speed*) ;; *) c_init="; aero-speed 10$c_init" ;; esac
    c_name="hostile-case-$hostile_case_no"
    set --
    c_old_ifs=$IFS
    IFS=','
    for c_e in $c_events; do
        IFS=$c_old_ifs
        [ -n "$(trim "$c_e")" ] && set -- "$@" "$(trim "$c_e")"
        IFS=','
    done
    IFS=$c_old_ifs
    pd_render "$c_name" "$c_obj" 1 500 "$c_init" 0 "$@"
    c_log="$OUT/$c_name.log"
    if grep -a -q -e "couldn't create" "$c_log"; then
        fail "[$c_obj]: not created"
        continue
    fi
    case "$c_want" in
        !*) if grep -a -q -F -e "${c_want#!}" "$c_log"; then
                fail "[$c_obj] $c_init: says '${c_want#!}':"
                grep -a -F -e "${c_want#!}" "$c_log" | head -3 | sed 's/^/        /'
            else
                pass "[$c_obj] $c_init: does not say '${c_want#!}'"
            fi ;;
        once:*) c_n=$(grep -a -F -e "${c_want#once:}" "$c_log" |
                    grep -a -c -F -e "[$c_cls]")
            if [ "$c_n" -eq 1 ]; then
                pass "[$c_obj] $c_init: says once '${c_want#once:}'"
            else
                fail "[$c_obj] $c_init: says '${c_want#once:}' $c_n times; it says:"
                grep -a -e "error" "$c_log" | head -4 | sed 's/^/        /'
            fi ;;
        *) if grep -a -F -e "$c_want" "$c_log" | grep -a -q -F -e "[$c_cls]"; then
                pass "[$c_obj] $c_init: says '$c_want'"
            else
                fail "[$c_obj] $c_init: does not say '$c_want'; it says:"
                grep -a -e "error" "$c_log" | head -4 | sed 's/^/        /'
            fi ;;
    esac
    [ "$c_peak" != "-" ] && judge $ANALYZE finite "$OUT/$c_name.wav" --max "$c_peak"
    if [ -n "$c_floor" ]; then # not silent, and finite
        [ "$c_peak" = "-" ] && judge $ANALYZE finite "$OUT/$c_name.wav"
        judge $ANALYZE level "$OUT/$c_name.wav" --min "$c_floor"
    fi
done <"$HOSTILE/cases.txt"

# an output in a folder that does not exist: refused before any work, by
# every aerotex command that writes (each names the folder)
case "aerotex" in *"$hostile_only"*)
for c_cmd in "aeolian" "cavity" "object --shape sphere" "vortex" "tree" \
    "field-demo" "auralize /tmp --path /dev/null"; do
    c_out=$(build/aerotex $c_cmd -o /nonexistent/x.wav 2>&1)
    c_rc=$?
    if [ "$c_rc" -ne 0 ] && printf '%s' "$c_out" |
        grep -q -F "the folder '/nonexistent' does not exist"; then
        pass "aerotex $c_cmd -o /nonexistent/x.wav: refused at once (exit $c_rc)"
    else
        fail "aerotex $c_cmd -o /nonexistent/x.wav: exit $c_rc, said: $(printf '%s' "$c_out" | tail -2)"
    fi
done ;;
esac
