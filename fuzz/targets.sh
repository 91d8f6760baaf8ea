# aero: the fuzz targets, found by their harness files (sourced by
# fuzz/run.sh and tests/objects/95-fuzz-replay.sh). Every fuzz/fuzz_NAME.c
# is the harness of target NAME; a new one joins with its file alone. What
# a harness needs beyond src/core/*/*.c it states in lines of its own, each
# a comment `/* aero-fuzz: KEY VALUES */` before its first #include:
#   sources FILE...   more sources to build with (src/tools/...)
#   seeds GLOB...     shipped files it starts from (textures/?*.wav: `?*`
#                     because a C comment cannot hold a slash and a star)
#   object CLASS      the Pd object whose messages it fuzzes (a harness
#                     fuzz/fuzz_OBJECT_args.c; tests/robust/registered.sh
#                     requires one for every object of AERO_OBJECTS)
# fuzz/seeds/NAME/* are its seeds too, and fuzz/regress/NAME/* the inputs
# that once broke it (replayed by `make check`). No seed at all: every byte
# string is a valid input (a program of messages).

# fuzz_targets: the names, one a line
fuzz_targets() {
    for _h in fuzz/fuzz_*.c; do
        [ -f "$_h" ] || continue
        _h=${_h#fuzz/fuzz_}
        echo "${_h%.c}"
    done
}

# fuzz_key NAME KEY: the values of the harness's `aero-fuzz: KEY` lines
fuzz_key() {
    sed -n "s|^/\\* aero-fuzz: $2 \\(.*\\) \\*/\$|\\1|p" "fuzz/fuzz_$1.c" |
        tr '\n' ' '
}

# fuzz_seeds NAME: its seed files (shipped and fuzz/seeds/NAME/*), one a line
fuzz_seeds() {
    # shellcheck disable=SC2046
    for _s in $(fuzz_key "$1" seeds) fuzz/seeds/"$1"/*; do
        [ -f "$_s" ] && echo "$_s"
    done
}
