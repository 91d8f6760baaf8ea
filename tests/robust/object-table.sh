#!/bin/sh
# aero: one table of test configurations, gathered from every object's own
# file tests/robust/objects/CLASS.txt (tests/robust/objects/README.md), in
# the layout its runner reads, one configuration a line:
#   hostile   class | creation args | outlets | file | hostile creation
#             args | hostile messages        (tests/objects/90-hostile.sh)
#   long      name | object box | message at load [| message per speed]
#                                            (tests/robust/long.sh)
# Usage, from the repository root: sh tests/robust/object-table.sh KIND
case "${1:-}" in
hostile | long) ;;
*) echo "usage: $0 hostile|long" >&2; exit 2 ;;
esac
for f in tests/robust/objects/*~.txt; do
    [ -f "$f" ] || continue
    cls=$(basename "$f" .txt)
    if [ "$1" = hostile ]; then # the class from the file's name
        sed -n "s/^hostile[[:space:]]*|/$cls |/p" "$f"
    else # the box: the class, then the line's arguments
        sed -n "s/^long[[:space:]]*|\([^|]*\)|[[:space:]]*/\1| $cls /p" "$f"
    fi
done
