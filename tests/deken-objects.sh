#!/bin/sh
# The object list of a deken package (the .dek.txt): one line per object,
# "NAME<TAB>DESCRIPTION", the description read from the META subpatch of
# help/NAME-help.pd (its "DESCRIPTION ..." comment, as deken reads it).
# A help patch without one gets a generic line and a warning on stderr.
# Usage: sh tests/deken-objects.sh NAME...   (from the repository root)
generic="aero: physically based aerodynamic sound"
for name in "$@"; do
    help="help/$name-help.pd"
    desc=""
    [ -f "$help" ] && desc=$(awk 'BEGIN { RS = ";\n" }
        { gsub(/\n/, " ") }
        /^#X text -?[0-9]+ -?[0-9]+ DESCRIPTION / {
            sub(/^#X text -?[0-9]+ -?[0-9]+ DESCRIPTION /, "")
            sub(/, f [0-9]+$/, "")
            gsub(/ \\,/, ","); gsub(/ \\;/, ";"); gsub(/\\\$/, "$")
            print; exit }' "$help")
    if [ -z "$desc" ]; then
        echo "deken: no META DESCRIPTION in $help: a generic line" >&2
        desc=$generic
    fi
    printf '%s\t%s\n' "$name" "$desc"
done
