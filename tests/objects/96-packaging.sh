# --- packaging: deken archives, the libpd example ---------------------------
section "packaging: make deken (single, double, sources), the libpd example"

version=$(sed -n 's/^#X text [0-9]* [0-9]* VERSION \([0-9][0-9.]*\).*/\1/p' help/aero-meta.pd | head -n 1)
arch="$(uname -s)-$(uname -m | sed 's/x86_64/amd64/; s/aarch64/arm64/')"
D=$OUT/deken # not build/deken: two runs (make check, check-pd056) may overlap
if make -s deken DEKEN_DIR="$D" >"$OUT/deken.log" 2>&1; then
    pass "make deken (version $version from help/aero-meta.pd)"
else
    fail "make deken"; tail -5 "$OUT/deken.log"
fi
classes=$(for c in src/pd/*~.c; do basename "$c" .c; done)
abstractions=$(cd abstractions && ls *.pd | sed 's/\.pd$//')
for pkg in "$arch-32:pd_linux:linux-amd64-64.so" "$arch-64:linux-amd64-64.so:pd_linux" Sources; do
    fs=${pkg%%:*}
    dek="$D/aero[v$version]($fs).dek"
    if [ ! -s "$dek" ]; then
        fail "no $dek"; continue
    fi
    if (cd "$D" && sha256sum -c --quiet "$(basename "$dek").sha256" >/dev/null 2>&1); then
        pass "$(basename "$dek").sha256 matches"
    else
        fail "$(basename "$dek").sha256 does not match"
    fi
    # the object list: every object, with its help patch's description
    missing=""
    for o in $classes $abstractions; do
        grep -q "^$o	." "$dek.txt" 2>/dev/null || missing="$missing $o"
    done
    if [ -z "$missing" ]; then
        pass "$(basename "$dek").txt lists the $(wc -l <"$dek.txt") objects"
    else
        fail "$(basename "$dek").txt lacks:$missing"
    fi
    listing=$(unzip -Z1 "$dek" 2>/dev/null)
    if [ "$fs" = Sources ]; then
        missing=""
        for f in aero/Makefile aero/README.md aero/LICENSE aero/src/pd/aero.c \
            aero/help/aero-meta.pd aero/textures/sword.wav aero/trees/small.tree; do
            echo "$listing" | grep -q -x -F "$f" || missing="$missing $f"
        done
        if [ -z "$missing" ]; then
            pass "$(basename "$dek"): the sources ($(echo "$listing" | wc -l) entries)"
        else
            fail "$(basename "$dek") lacks:$missing"
        fi
        continue
    fi
    # a binary package: its own float size's externals, none of the other
    ext=${pkg#*:} ext=${ext%%:*} other=${pkg##*:}
    missing=""
    for f in $(for c in $classes aero; do echo "aero/$c.$ext"; done) \
        $(for c in $classes $abstractions; do echo "aero/$c-help.pd"; done) \
        $(for a in $abstractions; do echo "aero/$a.pd"; done) \
        $(ls textures/*.wav trees/*.tree | sed 's|^|aero/|') \
        aero/aero-meta.pd aero/LICENSE aero/README.md; do
        echo "$listing" | grep -q -x -F "$f" || missing="$missing $f"
    done
    if [ -z "$missing" ] && ! echo "$listing" | grep -q -F ".$other"; then
        pass "$(basename "$dek"): *.$ext, help, abstractions, textures, trees, meta, license"
    else
        fail "$(basename "$dek") lacks:$missing$(echo "$listing" | grep -F ".$other" | head -3 | sed 's/^/ has /')"
    fi
done
# the descriptions: once a help patch has a META DESCRIPTION, every one must
# (until then, the packages carry a generic line for each object)
with=0 without=""
for o in $classes $abstractions; do
    if grep -q "^#X text [0-9-]* [0-9-]* DESCRIPTION " "help/$o-help.pd"; then
        with=$((with + 1))
    else
        without="$without $o"
    fi
done
if [ "$with" -eq 0 ]; then
    pass "no help patch has a META DESCRIPTION yet: the .dek.txt carries a generic line"
elif [ -z "$without" ]; then
    if ! grep -q -F "aero: physically based aerodynamic sound" "$D/aero[v$version]($arch-32).dek.txt"; then
        pass "every object's .dek.txt line is its help patch's META DESCRIPTION"
    else
        fail "a generic line in the .dek.txt although every help patch has a DESCRIPTION"
    fi
else
    fail "help patches without a META DESCRIPTION:$without"
fi

# the package of this Pd's float size, unpacked into a fresh folder as
# deken does: every help patch opens from there, with nothing else on the
# path (externals, abstractions, textures and trees from the package)
fs=${PD_FLOATSIZE:-32}
unpacked=$OUT/deken-$fs
rm -rf "$unpacked"
mkdir -p "$unpacked"
if unzip -q "$D/aero[v$version]($arch-$fs).dek" -d "$unpacked" 2>"$OUT/deken-unzip.log"; then
    for p in "$unpacked"/aero/*-help.pd; do
        [ -f "$p" ] || continue
        log="$OUT/deken-$fs-$(basename "$p" .pd).log"
        # shellcheck disable=SC2086
        timeout 120 "$PD" $PD_FLAGS -open "$ROOT/$p" \
            -open "$ROOT/tests/pd/run-1s-and-quit.pd" >"$log" 2>&1
        log_clean "$log" "from the unpacked ($arch-$fs) package: $(basename "$p") opens cleanly"
    done
else
    fail "unzip of the ($arch-$fs) package"; cat "$OUT/deken-unzip.log"
fi
# the libpd host must keep compiling against Pd's API with -DPDINSTANCE
if cc -std=c99 -fsyntax-only -Wall -Wextra -Werror -DPDINSTANCE -DPDTHREADS \
    -I/usr/include/pd -Isrc/pd examples/libpd-host.c 2>"$OUT/libpd-example.log"; then
    pass "examples/libpd-host.c compiles with -DPDINSTANCE"
else
    fail "examples/libpd-host.c"; cat "$OUT/libpd-example.log"
fi
