# --- multi-instance safety: no writable globals in src/ ---------
section "no writable globals in src/ (tests/robust/globals.sh)"
if out=$(sh tests/robust/globals.sh 2>&1); then
    pass "$out"
else
    fail "writable globals (two instances would share them):"; echo "$out" | sed 's/^/        /'
fi
# negative control: an object file with a global counter must be caught
mkdir -p "$OUT/globals"
printf 'int aero_counter;\nint aero_next(void) { return ++aero_counter; }\n' \
    >"$OUT/globals/shared.c"
if ${CC:-cc} -c -fPIC "$OUT/globals/shared.c" -o "$OUT/globals/shared.o" &&
    ! sh tests/robust/globals.sh "$OUT/globals/shared.o" >/dev/null 2>&1; then
    pass "negative control: a writable global counter is caught"
else
    fail "negative control: globals.sh missed a writable global"
fi
