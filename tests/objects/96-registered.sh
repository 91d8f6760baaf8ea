# --- every object of AERO_OBJECTS has its own test files, and no such file
# names an unknown object (tests/robust/registered.sh) -----------------------
section "registration: the objects of AERO_OBJECTS and their own test files"
reg_out=$(sh tests/robust/registered.sh 2>&1)
reg_status=$?
printf '%s\n' "$reg_out" | while IFS= read -r reg_line; do
    echo "        $reg_line"
done
if [ "$reg_status" -eq 0 ]; then
    pass "every object has its wrapper, robustness file, multi-instance case, fuzz harness and README line"
else
    fail "registration: $(printf '%s\n' "$reg_out" | grep -c '^FAIL') findings (above)"
fi
# negative controls, on a copy of the files the check reads: a forgotten
# file and a leftover file must each fail it, naming the object
REG=$OUT/registered
rm -rf "$REG"
mkdir -p "$REG/src/pd" "$REG/tests/robust/objects" "$REG/tests/unit" "$REG/fuzz"
cp src/pd/aero.c src/pd/*~.c "$REG/src/pd/"
cp tests/robust/objects/*.txt "$REG/tests/robust/objects/"
cp tests/unit/test_*.c "$REG/tests/unit/"
cp fuzz/fuzz_*.c "$REG/fuzz/"
cp README.md "$REG/"
reg_first=$(sed -n '/^#define AERO_OBJECTS/,/[^\\]$/p' src/pd/aero.c |
    grep -o 'X([A-Za-z0-9_]*)' | head -1 | sed 's/^X(\(.*\))$/\1/')
# reg_control NAME EXPECTED WHAT: the check in the copy must fail, with the
# line EXPECTED
reg_control() {
    if (cd "$REG" && sh "$ROOT/tests/robust/registered.sh") >"$REG/$1.log" 2>&1; then
        fail "negative control: $3 passed the check"
    elif grep -q -F "$2" "$REG/$1.log"; then
        pass "negative control: $3 is caught"
    else
        fail "negative control: $3 not named"; cat "$REG/$1.log"
    fi
}
mv "$REG/tests/robust/objects/$reg_first~.txt" "$REG/lost.txt"
reg_control missing "FAIL [$reg_first~] (AERO_OBJECTS) lacks its robustness file" \
    "[$reg_first~] without its robustness file"
mv "$REG/lost.txt" "$REG/tests/robust/objects/$reg_first~.txt"
cp "$REG/tests/robust/objects/$reg_first~.txt" "$REG/tests/robust/objects/nosuch~.txt"
reg_control stray "FAIL tests/robust/objects/nosuch~.txt is for [nosuch~]" \
    "a robustness file for an unknown object"
