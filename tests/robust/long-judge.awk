# Verdict of one long run (tests/robust/long.sh): reads the Pd log lines
# "long: MINUTE CPU_MS NONFINITE", VmRSS samples from the file rssfile.
# Slow-down: the CPU time of the fastest minute among the last 5 must be
# within 10 % of the fastest among minutes 2-6. The fastest minute is the
# one least disturbed by other jobs on the machine (a shared 2-core box
# swings single minutes by +-30 %); a denormal slow-down raises every
# minute, the fastest too, typically several-fold. Means are printed
# beside it. Memory: VmRSS at the end at most 1024 kB above its first
# sample after the first tenth of the minutes (at least minute 1: loading
# is over); rssfile holds "MINUTE_LINES_SO_FAR RSS_KB" per sample (the
# minute-0 line counts one).
/^long: / { m = $2; cpu[m] = $3; bad = $4; n++ }
END {
    if (n < want) { printf "FAIL only %d of %d minutes rendered", n, want; exit 1 }
    a = 0; b = 0; amin = 1e30; bmin = 1e30
    for (i = 2; i <= 6; i++) { a += cpu[i]; if (cpu[i] < amin) amin = cpu[i] }
    for (i = want - 4; i <= want; i++) { b += cpu[i]; if (cpu[i] < bmin) bmin = cpu[i] }
    a /= 5; b /= 5
    tenth = int(want / 10); if (tenth < 1) tenth = 1
    r0 = -1; r1 = -1
    while ((getline line < rssfile) > 0) {
        split(line, f, " ")
        if (r0 < 0 && f[1] - 1 >= tenth) r0 = f[2]
        if (r0 >= 0) r1 = f[2]
    }
    memok = (r0 < 0) || (r1 - r0 <= 1024)
    ok = (bad == 0) && (bmin <= 1.1 * amin) && memok
    mem = r0 < 0 ? sprintf("VmRSS not sampled after minute %d (a run too short or fast: memory not judged)", tenth) \
        : sprintf("VmRSS %d -> %d kB from minute %d", r0, r1, tenth)
    printf "%s %d min, %d non-finite samples, CPU per minute (fastest of 5) %d ms at minutes 2-6 -> %d ms in the last 5: x%.3f (means %.0f -> %.0f ms), %s", \
        ok ? "ok  " : "FAIL", n - 1, bad, amin, bmin, (amin > 0 ? bmin / amin : 0), a, b, mem
    exit !ok
}
