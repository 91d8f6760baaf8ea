# aero: helpers for tests that run real Pd in batch mode (sourced by
# tests/run.sh and tests/demo.sh). POSIX sh.
#
# pd_render NAME "OBJ1|OBJ2..." NCH DUR_MS "INIT" [MSGINLET] [EVENTS...]
#   writes $OUT/NAME.pd and renders $OUT/NAME.wav: a [line~] fed by the
#   receiver aero-speed drives the first object's left inlet, the objects
#   are chained outlet 0 -> inlet 0, the receiver aero-obj sends messages to
#   inlet MSGINLET (default 0) of the last one, whose NCH (1 or 2) outlets
#   are recorded at PD_RATE. INIT is a message-box body sent at load, before DSP
#   starts (e.g. "; aero-speed 10; aero-obj diameter 0.02"); each EVENT is
#   "MS ; receiver message..." sent MS ms after recording starts.
#   Recording starts after 200 ms of settling and lasts DUR_MS.
#   PD_EXTRA="OBJ|OBJ..." adds unconnected object boxes (e.g. a pose
#   generator from tests/pd that sends to aero-obj). Object
#   boxes are written as given: escape dollars as \$ (e.g. 'expr~ \$v1*2').
# The Pd log goes to $OUT/NAME.log. Returns Pd's exit status.
#
# PD=/path/to/pd runs another Pd (default: Debian's pd, or puredata);
# PD_RATE (default 44100) is passed to every run as -r: Pd 0.55 and later
# default to 48 kHz, 0.54 and earlier to 44.1 kHz, and the recordings'
# headers must say the rate Pd really ran at.
# PD_SEARCH=/folder makes that folder Pd's only search path (-path) instead
# of the repository (and its abstractions/): a staged package, so that
# every object and file comes from there (tests/platform/run.sh).

: "${OUT:=build/tests/out}"
: "${ROOT:=$(pwd)}"
: "${PD:=$(command -v pd || command -v puredata)}"
: "${PD_RATE:=44100}"
export PD PD_RATE
PD_BASE_FLAGS="-batch -nogui -noaudio -noprefs -stderr -nostdpath"
PD_FLAGS="$PD_BASE_FLAGS -r $PD_RATE"
SETTLE_MS=200
# The render is recorded with [tabwrite~] into arrays and written by
# [soundfiler] (synchronous). [writesf~] was tried first: it opens and
# closes its file in a thread, and batch mode runs logical time so far
# ahead of the clock that the thread missed requests (no file, or a header
# without data) however long the patch waited.

pd_escape() { # Pd message-box text: ';' -> '\;', ',' -> '\,'
    printf '%s' "$1" | sed -e 's/;/ \\; /g' -e 's/,/ \\, /g'
}

pd_render() {
    _name=$1 _chain=$2 _nch=$3 _dur=$4 _init=$5
    _msginlet=${6:-0}
    shift 5
    [ $# -gt 0 ] && shift
    mkdir -p "$OUT"
    _patch="$OUT/$_name.pd"
    _wav="$ROOT/$OUT/$_name.wav"
    rm -f "$_wav"
    [ -n "$_init" ] || _init="; aero-nothing bang"
    _frames=$((_dur * PD_RATE / 1000))
    _arrays="aero-out0"
    [ "$_nch" -ge 2 ] && _arrays="aero-out0 aero-out1"
    {
        echo "#N canvas 0 50 700 500 10;"
        echo "#X obj 10 10 loadbang;"                              # 0
        echo "#X obj 10 30 t b b;"                                 # 1
        echo "#X msg 200 30 $(pd_escape "$_init");"                # 2
        echo "#X msg 10 50 \\; pd dsp 1;"                          # 3
        echo "#X obj 10 80 r aero-speed;"                          # 4
        echo "#X obj 10 100 line~;"                                # 5
        echo "#X obj 200 80 r aero-obj;"                           # 6
        echo "#X obj 400 80 array define aero-out0 $_frames;"      # 7
        echo "#X obj 400 100 array define aero-out1 $_frames;"     # 8
        echo "#X obj 400 10 r aero-nothing;"                       # 9
        echo "#X obj 10 400 delay $SETTLE_MS;"                     # 10
        echo "#X obj 10 300 tabwrite~ aero-out0;"                  # 11
        echo "#X obj 100 300 tabwrite~ aero-out1;"                 # 12
        echo "#X obj 200 400 delay $((SETTLE_MS + _dur + 10));"    # 13
        echo "#X msg 200 420 write -bytes 4 -rate $PD_RATE $_wav $_arrays;"
        echo "#X obj 200 440 soundfiler;"                          # 15
        echo "#X msg 200 460 \\; pd quit;"                         # 16
        echo "#X obj 10 420 s aero-recording;"                     # 17
        echo "#X obj 300 10 r aero-recording;"                     # 18
        # [tabwrite~] zeroes NaN and Inf: mark them as 1e9 before it, so
        # the analyser sees them (checked by a negative control in run.sh)
        echo "#X obj 10 250 expr~ if(abs(\\\$v1) < 1e30 \\, \\\$v1 \\, 1e9);" # 19
        echo "#X obj 100 250 expr~ if(abs(\\\$v1) < 1e30 \\, \\\$v1 \\, 1e9);" # 20
        _first=21 _k=21 _y=150
        _old_ifs=$IFS
        IFS='|'
        for _obj in $_chain; do
            echo "#X obj 10 $_y $_obj;"
            _k=$((_k + 1)) _y=$((_y + 30))
        done
        IFS=$_old_ifs
        _last=$((_k - 1))
        _ev=$_k
        for _event in "$@"; do
            echo "#X obj 500 $_y delay $((SETTLE_MS + ${_event%% *}));"
            echo "#X msg 500 $((_y + 20)) $(pd_escape "${_event#* }");"
            _y=$((_y + 40))
        done
 if [ -n "${PD_EXTRA:-}" ]; then
            IFS='|'
            for _obj in $PD_EXTRA; do
                echo "#X obj 300 $_y $_obj;"
                _y=$((_y + 30))
            done
            IFS=$_old_ifs
        fi
        for _c in "0 0 1 0" "1 1 2 0" "1 0 3 0" "1 0 10 0" "1 0 13 0" \
            "10 0 11 0" "10 0 12 0" "10 0 17 0" "13 0 14 0" "14 0 15 0" \
            "15 0 16 0" "4 0 5 0" "5 0 $_first 0" "6 0 $_last $_msginlet"; do
            echo "#X connect $_c;"
        done
        _j=$_first
        while [ $_j -lt $_last ]; do
            echo "#X connect $_j 0 $((_j + 1)) 0;"
            _j=$((_j + 1))
        done
        _c=0
        while [ $_c -lt "$_nch" ]; do
            echo "#X connect $_last $_c $((19 + _c)) 0;"
            echo "#X connect $((19 + _c)) 0 $((11 + _c)) 0;"
            _c=$((_c + 1))
        done
        for _event in "$@"; do
            echo "#X connect 1 0 $_ev 0;"
            echo "#X connect $_ev 0 $((_ev + 1)) 0;"
            _ev=$((_ev + 2))
        done
    } >"$_patch"
    # shellcheck disable=SC2086
    timeout 300 "$PD" $PD_FLAGS -path "${PD_SEARCH:-$ROOT}" \
        -open "$_patch" >"$OUT/$_name.log" 2>&1
}

# pd_open_log PATCH LOG: open a patch (help or abstraction) for 1 s of
# logical time with DSP on, then quit; the log goes to LOG.
pd_open_log() {
    # shellcheck disable=SC2086
    # (with PD_SEARCH, that folder twice: Pd ignores the repeat)
    timeout 120 "$PD" $PD_FLAGS -path "${PD_SEARCH:-$ROOT}" \
        -path "${PD_SEARCH:-$ROOT/abstractions}" \
        -open "$1" -open "$ROOT/tests/pd/run-1s-and-quit.pd" >"$2" 2>&1
}

# pd_render_sr RATE NAME ...: pd_render at another sample rate
pd_render_sr() {
    _saved_rate=$PD_RATE
    PD_FLAGS="$PD_BASE_FLAGS -r $1" PD_RATE=$1
    shift
    pd_render "$@"
    _status=$?
    PD_FLAGS="$PD_BASE_FLAGS -r $_saved_rate" PD_RATE=$_saved_rate
    return $_status
}
