# --- the defaults users read are the ones the objects start with ----------
# tests/defaults.sh reads every object's ranges and defaults from its
# refusals in real Pd (the table's rules, from the cores' constants, which
# the cores' inits start from) and compares each help patch's "Defaults
# (ranges)" line and docs/objects.md's table with them. The negative
# control checks a copy of the help patches with one default changed.
section "defaults and ranges: the help patches and docs/objects.md against the tables"
DEFAULTS_OUT=$OUT/defaults sh tests/defaults.sh check >"$OUT/defaults.txt" 2>&1
while IFS= read -r line; do
    case "$line" in
        "ok   "*) pass "${line#ok   }" ;;
        "FAIL "*) fail "${line#FAIL }" ;;
        *) echo "        $line" ;;
    esac
done <"$OUT/defaults.txt"
grep -q . "$OUT/defaults.txt" || fail "tests/defaults.sh printed nothing"

rm -rf "$OUT/defaults-control"
mkdir -p "$OUT/defaults-control"
cp help/*~-help.pd "$OUT/defaults-control/"
sed -i 's/\(Defaults (ranges): length\) 0.02 m/\1 0.03 m/' \
    "$OUT/defaults-control/cavity~-help.pd"
if DEFAULTS_OUT=$OUT/defaults DEFAULTS_HELP=$OUT/defaults-control \
    sh tests/defaults.sh check >"$OUT/defaults-control.txt" 2>&1; then
    fail "negative control: a help patch stating length 0.03 m for [cavity~] passed"
elif grep -q "^FAIL .*cavity~-help.pd" "$OUT/defaults-control.txt"; then
    pass "negative control: a help patch with a wrong default fails"
else
    fail "negative control ended otherwise:"; cat "$OUT/defaults-control.txt"
fi
