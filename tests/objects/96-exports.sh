# --- only Pd's entry points exported (issue 37) ------------------------
section "externals export only *_setup (tests/robust/exports.sh)"
binaries=$(ls *.pd_linux *-64.so 2>/dev/null)
if [ -z "$binaries" ]; then
    fail "no externals built (make all lib double)"
elif out=$(sh tests/robust/exports.sh $binaries 2>&1); then
    pass "$(echo "$binaries" | wc -w) binaries export only their *_setup"
else
    fail "exported names besides *_setup:"; echo "$out" | sed 's/^/        /'
fi
# negative control: a shared object built without hidden visibility
# exports its helper beside its setup, and must be caught
mkdir -p "$OUT/exports"
printf 'int aero_helper(int a) { return a + 1; }\nvoid x_setup(void) { aero_helper(1); }\n' \
    >"$OUT/exports/leaky.c"
if ${CC:-cc} -shared -fPIC "$OUT/exports/leaky.c" -o "$OUT/exports/leaky.pd_linux" &&
    ! sh tests/robust/exports.sh "$OUT/exports/leaky.pd_linux" >/dev/null 2>&1; then
    pass "negative control: an exported helper is caught"
else
    fail "negative control: exports.sh missed an exported helper"
fi
