# --- make install, as a user installs: then patches elsewhere find aero ---
section "make install: [declare -path aero] and [declare -lib aero] from the installed folder"

# A user's own externals folder: ~/pd-externals, on Pd's standard path on
# Linux (a -path on the command line would not do: Pd resolves a relative
# [declare -path] only against the saved search path and the standard one)
INST=$OUT/install
INST_HOME=$ROOT/$INST/home
rm -rf "$INST"
mkdir -p "$INST_HOME" "$INST/elsewhere"
if make -s install PDLIBDIR="$INST_HOME/pd-externals" >"$INST/install.log" 2>&1; then
    pass "make install PDLIBDIR=~/pd-externals (HOME=$INST/home)"
else
    fail "make install"; tail -5 "$INST/install.log"
fi
# everything a user needs is there: every external in both float sizes,
# the single binary, help, abstractions, textures, trees, the meta patch
missing=""
for f in $(for c in src/pd/*~.c; do c=$(basename "$c" .c); echo "$c.pd_linux $c.linux-amd64-64.so $c-help.pd"; done) \
    aero.pd_linux aero.linux-amd64-64.so aero-meta.pd LICENSE README.md \
    $(cd abstractions && ls *.pd) $(cd help && ls *-help.pd) \
    $(ls textures/*.wav trees/*.tree); do
    [ -f "$INST_HOME/pd-externals/aero/$f" ] || missing="$missing $f"
done
if [ -z "$missing" ]; then
    pass "installed: $(ls "$INST_HOME/pd-externals/aero" | wc -l) files and folders in aero/ (externals in both float sizes, aero.pd_linux, help, abstractions, textures, trees, aero-meta.pd)"
else
    fail "not installed:$missing"
fi

# A patch outside the repository, Pd with its standard path and nothing
# else: the sword texture and the small tree must come from the installed
# aero/textures and aero/trees (and the abstraction, with -path aero).
# -verbose logs where each object was loaded from.
inst_flags="$(echo "$PD_FLAGS" | sed 's/ -nostdpath//') -verbose"
install_render() { # NAME DECLARE EXTRA-OBJECT: $INST/NAME.wav and .log
    _frames=$((1500 * PD_RATE / 1000))
    cat >"$INST/elsewhere/$1.pd" <<EOP
#N canvas 0 50 600 400 12;
#X declare $2;
#X obj 10 10 declare $2;
#X obj 10 40 loadbang;
#X msg 10 70 \; pd dsp 1;
#X obj 10 100 sig~ 10;
#X obj 10 130 aeolian~ -texture sword;
#X obj 200 100 sig~ 8;
#X obj 200 130 treebranch~ small -listener 0 -12 1.7;
#X obj 10 200 tabwrite~ \\\$0-a;
#X obj 200 200 tabwrite~ \\\$0-b;
#X obj 400 10 array define \\\$0-a $_frames;
#X obj 400 40 array define \\\$0-b $_frames;
#X obj 120 40 delay 200;
#X obj 250 40 delay 1720;
#X msg 250 100 write -bytes 4 -rate $PD_RATE $ROOT/$INST/$1.wav \\\$1-a \\\$1-b;
#X obj 250 130 soundfiler;
#X msg 250 160 \; pd quit;
#X obj 250 70 f \\\$0;
#X obj 400 200 $3;
#X connect 1 0 2 0;
#X connect 1 0 11 0;
#X connect 1 0 12 0;
#X connect 3 0 4 0;
#X connect 4 0 7 0;
#X connect 5 0 6 0;
#X connect 6 0 8 0;
#X connect 11 0 7 0;
#X connect 11 0 8 0;
#X connect 12 0 16 0;
#X connect 16 0 13 0;
#X connect 13 0 14 0;
#X connect 14 0 15 0;
EOP
    rm -f "$INST/$1.wav"
    # shellcheck disable=SC2086
    (cd "$INST/elsewhere" && HOME=$INST_HOME timeout 120 "$PD" $inst_flags \
        -open "$1.pd" >"../$1.log" 2>&1)
}
for use in "uses-path:-path aero:aero.wind~ 5" "uses-lib:-lib aero:vortex~ -texture fire"; do
    name=${use%%:*} rest=${use#*:}
    install_render "$name" "${rest%%:*}" "${rest#*:}"
    log_clean "$INST/$name.log" "[declare ${rest%%:*}] in $INST/elsewhere: the installed aero creates [aeolian~ -texture sword], [treebranch~ small] and [${rest#*:}]"
    # sound from both: the texture and the tree were read (without them
    # [aeolian~] falls back to the model, [treebranch~] is silent)
    judge $ANALYZE level "$INST/$name.wav" --ch 0 --min 20
    judge $ANALYZE level "$INST/$name.wav" --ch 1 --min 20
done
# loaded from the installed folder, not from anywhere else
for f in "uses-path:aero/aeolian~" "uses-path:aero/aero.wind~.pd" "uses-lib:aero/aero"; do
    if grep -q "tried $INST_HOME/pd-externals/${f#*:}[.a-z_0-9-]* and succeeded" "$INST/${f%%:*}.log"; then
        pass "${f%%:*}: ${f#*:} loaded from ~/pd-externals"
    else
        fail "${f%%:*}: ${f#*:} not loaded from ~/pd-externals"; grep "${f#*:}.*succeeded" "$INST/${f%%:*}.log"
    fi
done
if grep -q "aero: aerodynamic sound library loaded" "$INST/uses-lib.log"; then
    pass "[declare -lib aero] loads the installed single binary"
else
    fail "[declare -lib aero] did not load the single binary"; cat "$INST/uses-lib.log"
fi
# negative control: declaring another folder, nothing of aero is found
install_render uses-nothing "-path nowhere" "print"
if grep -q "couldn't create" "$INST/uses-nothing.log"; then
    pass "negative control: with [declare -path nowhere] aero is not found"
else
    fail "negative control: aero was found without declaring it"; cat "$INST/uses-nothing.log"
fi
