# --- the help patches as a Pd user sees them ----------------------
# tests/gui/check-help.sh opens each help patch in the real Pd GUI under
# Xvfb; its plugin measures every window and subpatch window (overlapping
# boxes, cords through text, content outside the window) and saves a
# screenshot of each under build/gui/ for a person to look at.
section "help patches drawn by the Pd GUI (tests/gui/check-help.sh, screenshots in build/gui/)"

# the check must be able to fail: a patch with an overlap, a cord through a
# comment, a box outside the window and an overlap in its subpatch
control=$(GUI_OUT=$OUT/gui sh tests/gui/check-help.sh tests/gui/bad-layout.pd 2>&1)
status=$?
if [ "$status" -eq 1 ] &&
    echo "$control" | grep -q '^FAIL bad-layout .*overlap: .*crosses "a cord runs through me".*does not fit' &&
    echo "$control" | grep -q '^FAIL bad-layout/inner .*overlap: \[osc~ 440\] / \[\*~ 0.1\]'; then
    pass "negative control: the GUI check flags tests/gui/bad-layout.pd (overlaps, a cord through a comment, a box outside the window, a subpatch)"
else
    fail "negative control: the GUI check missed a flaw of tests/gui/bad-layout.pd (exit $status)"
    echo "$control" | sed 's/^/        /'
fi
# ... and to pass: a clean patch with a slider, cords and a subpatch
control=$(GUI_OUT=$OUT/gui sh tests/gui/check-help.sh tests/gui/good-layout.pd 2>&1)
status=$?
if [ "$status" -eq 0 ] && [ "$(echo "$control" | grep -c '^ok ')" -eq 2 ]; then
    pass "positive control: tests/gui/good-layout.pd and its subpatch pass the GUI check"
else
    fail "positive control: tests/gui/good-layout.pd (exit $status)"
    echo "$control" | sed 's/^/        /'
fi

# a help patch without its parts (reference, META, version) must fail too
control=$(GUI_OUT=$OUT/gui sh tests/gui/check-help.sh tests/gui/bare-help.pd 2>&1)
status=$?
if [ "$status" -eq 1 ] && echo "$control" | grep -q '^ok   bare-help (' &&
    echo "$control" | grep -q '^FAIL bare-help parts: no \[pd reference\] | no \[pd META\] | no see also | no updated for aero.* | 1 comments wider than 80'; then
    pass "negative control: the GUI check flags a help patch without [pd reference], [pd META], see also and version, with a comment 90 characters wide (tests/gui/bare-help.pd)"
else
    fail "negative control: tests/gui/bare-help.pd (exit $status)"
    echo "$control" | sed 's/^/        /'
fi

# every window of every help patch: one pass or fail each
sh tests/gui/check-help.sh >"$OUT/gui-help.txt" 2>&1
while IFS= read -r line; do
    case "$line" in
        ok*) pass "${line#ok   }" ;;
        note*) echo "        $line" ;;
        *) fail "${line#FAIL }" ;;
    esac
done <"$OUT/gui-help.txt"
