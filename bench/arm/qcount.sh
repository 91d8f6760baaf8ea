#!/bin/sh
# bench/arm/qcount.sh QEMU [QEMU-OPTIONS] PROGRAM [ARGS]: the number of guest
# instructions PROGRAM executes under QEMU's user-mode emulator, counted by
# QEMU's own log: every translation block (TB) is listed once as it is
# translated (-d in_asm: one line per guest instruction, the first one
# giving the block's address) and once more each time it runs (-d exec,
# with nochain so that chained blocks are logged too). The count is the sum,
# over executions, of the executed block's instruction count. The log is
# read through a pipe, never stored. The program's own output goes to
# stderr; the count is the only line on stdout.
# Checked by bench/arm/count.sh on a loop of known length on each
# architecture (exactly 4 instructions per iteration), and against one
# instruction per block (-singlestep) on the benchmark itself.
set -e
fifo=$(mktemp -u "${TMPDIR:-/tmp}/qcount.XXXXXX")
mkfifo "$fifo"
trap 'rm -f "$fifo"' EXIT
qemu=$1
shift
awk '
    /^IN:/ { inblock = 1; pc = ""; n = 0; next }
    inblock && /^0x[0-9a-f]+:/ {
        if (pc == "") { pc = substr($1, 3, length($1) - 3); sub(/^0+/, "", pc) }
        # an x86 instruction longer than 8 bytes continues its byte dump
        # on a line of its own (only 2-digit bytes): not an instruction
        for (i = 2; i <= NF; i++) if ($i !~ /^[0-9a-f][0-9a-f]$/) { n++; break }
        next }
    inblock && /^$/ { if (pc != "") size[pc] = n; inblock = 0; next }
    /^Trace / {
        split($0, f, "/"); p = f[2]; sub(/^0+/, "", p)
        if (p in size) total += size[p]; else missing++
    }
    END {
        if (missing) printf "qcount: %d executions of untranslated blocks\n", missing > "/dev/stderr"
        printf "%.0f\n", total }' "$fifo" &
reader=$!
"$qemu" -d in_asm,exec,nochain -D "$fifo" "$@" >&2
wait "$reader"
