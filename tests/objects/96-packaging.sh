# --- packaging: deken archives, the libpd example ---------------------------
section "packaging: make deken, the libpd example"

if make -s deken >"$OUT/deken.log" 2>&1; then
    dek=$(ls build/deken/aero*\(Linux-*\).dek 2>/dev/null | head -n 1)
    listing=$(unzip -l "$dek" 2>/dev/null)
    missing=""
    for f in aero/aeolian~.pd_linux aero/aeolian~-help.pd aero/aero.wind~.pd \
        aero/aero.fire~.pd aero/aero.tree~.pd aero/aero.fire~-help.pd \
        aero/textures/sword.wav aero/LICENSE; do
        echo "$listing" | grep -q -F "$f" || missing="$missing $f"
    done
    if [ -z "$missing" ] && [ -s build/deken/aero*\(Sources\).dek ]; then
        pass "make deken: $(basename "$dek") (externals, help, abstractions, textures) and the Sources package"
    else
        fail "deken package lacks:$missing"
    fi
else
    fail "make deken"; tail -5 "$OUT/deken.log"
fi
# the libpd host must keep compiling against Pd's API with -DPDINSTANCE
if cc -std=c99 -fsyntax-only -Wall -Wextra -Werror -DPDINSTANCE -DPDTHREADS \
    -I/usr/include/pd -Isrc/pd examples/libpd-host.c 2>"$OUT/libpd-example.log"; then
    pass "examples/libpd-host.c compiles with -DPDINSTANCE"
else
    fail "examples/libpd-host.c"; cat "$OUT/libpd-example.log"
fi
