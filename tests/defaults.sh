#!/bin/sh
# aero: the ranges and defaults every object states in its table, read
# from the built objects in real Pd, as a user reads them, and the two
# places they are written for users: a line "Defaults (ranges): ..." in
# each help patch's [pd reference], and the table between the
# "defaults: begin/end" marks of docs/objects.md.
#
# Each object is created twice: with a flag that does not exist (its
# error lists the table's flags), then with every one of those flags set
# to 1e30, out of every range, so that each refusal states the message's
# range and default (aero_pd_refused, src/pd/aero_pd.c):
#   [cavity~]: length 1e+30 m out of range (0.0001..100 m; default 0.02 m)...
#
#   sh tests/defaults.sh list    one line per message with a default, in
#                                table order: cavity~|length|0.0001..100|0.02|m
#                                (object|message|range|default|unit)
#   sh tests/defaults.sh check   compares the help patches and
#                                docs/objects.md with it: one line per
#                                place, "ok ..." or "FAIL ...", exit 1 if any
#                                place differs
#   sh tests/defaults.sh write   rewrites those places from it
# Run from the repository root after `make all`; PD and PD_FLAGS as in
# tests/pdtest.sh, DEFAULTS_OUT the folder for the patches and logs.
MODE=${1:-list}
ROOT=${ROOT:-$(pwd)}
DIR=${DEFAULTS_OUT:-build/tests/out/defaults}
PD=${PD:-$(command -v pd || command -v puredata)}
PD_FLAGS=${PD_FLAGS:--batch -nogui -noaudio -noprefs -stderr -nostdpath}
HELP=${DEFAULTS_HELP:-help}          # the negative control checks copies
DOCS=${DEFAULTS_DOCS:-docs/objects.md}
mkdir -p "$DIR"
classes=$(for c in src/pd/*~.c; do basename "$c" .c; done)

run_patch() { # NAME: opens DIR/NAME.pd, logs to DIR/NAME.log
    # shellcheck disable=SC2086
    timeout 60 "$PD" $PD_FLAGS -path "${PD_SEARCH:-$ROOT}" \
        -open "$DIR/$1.pd" -send "pd quit" >"$DIR/$1.log" 2>&1
}

# 1. the flags of each table
{
    echo '#N canvas 0 50 450 300 12;'
    y=10
    for c in $classes; do
        echo "#X obj 10 $y $c -aero-no-such-flag;"
        y=$((y + 30))
    done
} >"$DIR/flags.pd"
run_patch flags

# 2. every flag out of range
{
    echo '#N canvas 0 50 450 300 12;'
    y=10
    for c in $classes; do
        flags=$(sed -n "s/.*\[$c\]: unknown argument '-aero-no-such-flag' ignored (flags: \(.*\))\$/\1/p" \
            "$DIR/flags.log" | head -n 1)
        args=
        for f in $flags; do
            case "$f" in -*) args="$args $f 1e30" ;; esac
        done
        echo "#X obj 10 $y $c$args;"
        y=$((y + 30))
    done
} >"$DIR/refusals.pd"
run_patch refusals

# 3. the refusals that state a default, one line per message
for c in $classes; do
    grep -F "[$c]: " "$DIR/refusals.log" |
        sed -n 's/.*\]: \([^ ]*\) 1e+30 .*out of range (\([^;)]*\); default \([^ ;)]*\) *\([^;)]*\)[;)].*/\1|\2|\3|\4/p' |
        awk -v c="$c" -F'|' '!seen[$1]++ {
            range = $2 # the unit once, after the default
            if ($4 != "" && substr(range, length(range) - length($4)) == " " $4)
                range = substr(range, 1, length(range) - length($4) - 1)
            print c "|" $1 "|" range "|" $3 "|" $4 }'
done >"$DIR/defaults.txt"

if [ "$MODE" = list ]; then
    cat "$DIR/defaults.txt"
    exit 0
fi

# the help patch's line: "length 0.02 m (0.0001..100) / ..."
help_line() { # CLASS
    awk -F'|' -v c="$1" '$1 == c {
        printf "%s%s %s%s (%s)", n++ ? " / " : "", $2, $4, $5 != "" ? " " $5 : "", $3 }' \
        "$DIR/defaults.txt"
}
# docs/objects.md's table
docs_table() {
    echo "| object | message | default | range |"
    echo "|---|---|---|---|"
    awk -F'|' '{ u = $5 != "" ? " " $5 : ""
        printf "| [%s] | `%s` | %s%s | %s%s |\n", $1, $2, $4, u, $3, u }' \
        "$DIR/defaults.txt"
}

status=0
for c in $classes; do
    help=$HELP/$c-help.pd
    want=$(help_line "$c")
    if [ -z "$want" ]; then
        echo "FAIL [$c]: no default read from its refusals (see $DIR/refusals.log)"
        status=1
        continue
    fi
    have=$(sed -n 's/^#X text [0-9]* [0-9]* Defaults (ranges): \(.*\), f [0-9]*;$/\1/p' "$help")
    if [ "$MODE" = write ]; then
        if [ -z "$have" ]; then
            echo "FAIL $help has no line '#X text X Y Defaults (ranges): ..., f 80;' in its [pd reference]: add one"
            status=1
            continue
        fi
        # Pd's file format: "/" and "." need no escape; "," would
        esc=$(printf '%s' "$want" | sed 's/,/ \\,/g')
        awk -v new="$esc" '/^#X text [0-9]* [0-9]* Defaults \(ranges\): / {
            sub(/Defaults \(ranges\): .*, f /, "Defaults (ranges): " new ", f ") } { print }' \
            "$help" >"$DIR/help.tmp" && cat "$DIR/help.tmp" >"$help"
        echo "wrote $help"
    elif [ "$have" = "$want" ]; then
        echo "ok   $help states [$c]'s defaults and ranges"
    else
        echo "FAIL $help: [pd reference] says 'Defaults (ranges): $have'"
        echo "     the table says '$want' (sh tests/defaults.sh write)"
        status=1
    fi
done

docs=$DOCS
docs_table >"$DIR/docs-table.md"
awk '/^<!-- defaults: begin/ { on = 1; next } /^<!-- defaults: end/ { on = 0 } on' \
    "$docs" >"$DIR/docs-have.md"
if [ "$MODE" = write ]; then
    awk -v table="$DIR/docs-table.md" '
        /^<!-- defaults: begin/ { print; while ((getline l < table) > 0) print l; skip = 1; next }
        /^<!-- defaults: end/ { skip = 0 }
        !skip' "$docs" >"$DIR/docs.tmp" && cat "$DIR/docs.tmp" >"$docs"
    echo "wrote $docs"
elif cmp -s "$DIR/docs-table.md" "$DIR/docs-have.md"; then
    echo "ok   $docs states every object's defaults and ranges"
else
    echo "FAIL $docs: its defaults table differs from the tables (sh tests/defaults.sh write):"
    diff "$DIR/docs-have.md" "$DIR/docs-table.md" | head -10 | sed 's/^/     /'
    status=1
fi
exit $status
