# aerotex over MPI ranks (build/aerotex-mpi, docs/cluster.md): the task
# farm's texture equals the one-process texture byte for byte, at 2 and 3
# ranks (oversubscribed on a small machine), for the section (with its
# calibration circle, broadcast from rank 0), the 3D body and the vortex
# commands; a job whose rank is killed resumes from its checkpoint to the
# same texture, and the checkpoint is what it resumes from (a changed
# sample in it changes the texture). Skipped without Open MPI.
section "aerotex over MPI ranks: task farm and checkpoint (docs/cluster.md)"
if [ ! -x build/aerotex-mpi ] || ! command -v mpirun >/dev/null 2>&1; then
    echo "  skip  no build/aerotex-mpi or no mpirun (Open MPI: make deps)"
else
    mpi_dir="$OUT/mpi"
    rm -rf "$mpi_dir"
    mkdir -p "$mpi_dir"
    # mpirun as root (CI containers) and more ranks than cores
    mpi_run() { # NP DIR ARGS...: aerotex-mpi on NP ranks in DIR
        _np=$1 _dir=$2
        shift 2
        (cd "$_dir" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
            OMPI_MCA_btl=self,vader timeout 300 mpirun --oversubscribe \
            -np "$_np" "$ROOT/build/aerotex-mpi" "$@")
    }
    mpi_same() { # NAME FILE NPS ARGS...: one process, then NPS ranks ("2 3")
        _name=$1 _file=$2 _nps=$3
        shift 3
        for _d in one np2 np3; do mkdir -p "$mpi_dir/$_d"; done
        if ! (cd "$mpi_dir/one" && "$ROOT/build/aerotex" "$@" -q -o "$_file") \
            >"$mpi_dir/$_file.one.log" 2>&1; then
            fail "$_name: the one-process run failed"; cat "$mpi_dir/$_file.one.log"
            return
        fi
        for _np in $_nps; do
            if mpi_run "$_np" "$mpi_dir/np$_np" "$@" -q -o "$_file" \
                >"$mpi_dir/$_file.np$_np.log" 2>&1 &&
                cmp "$mpi_dir/one/$_file" "$mpi_dir/np$_np/$_file"; then
                pass "$_name: $_np ranks write the one-process texture byte for byte"
            else
                fail "$_name: $_np ranks"; tail -5 "$mpi_dir/$_file.np$_np.log"
            fi
        done
    }
    mpi_same "aeolian square, 4 directions, circle-calibrated 2D-to-3D" \
        square.wav "2 3" aeolian --shape square --directions 4 --grid 6 \
        --duration 0.02 --re 400 --settle 5 --span3d circle
    mpi_same "object capsule, 3 directions (3D flow)" capsule.wav "2" \
        object --shape capsule --directions 3 --grid 4 --duration 0.03 --settle 1
    mpi_same "vortex, 3 speeds" vortex.wav "3" \
        vortex --speeds 5,10,20 --grid 8 --duration 0.01

    # the checkpoint: rank 1 killed once rank 0 has kept a task
    ck="$mpi_dir/ckpt"
    mkdir -p "$ck/ref" "$ck/run"
    ck_args="aeolian --shape square --directions 6 --grid 8 --duration 0.03 --re 150 --settle 5 --threads 1 -q -o t.wav"
    # shellcheck disable=SC2086
    (cd "$ck/ref" && "$ROOT/build/aerotex" $ck_args) >"$ck/ref.log" 2>&1
    # shellcheck disable=SC2086
    mpi_run 2 "$ck/run" $ck_args >"$ck/killed.log" 2>&1 &
    ck_pid=$!
    ck_wait=0
    while ! ls "$ck/run/t.wav.ckpt/"task*.bin >/dev/null 2>&1 && [ $ck_wait -lt 1200 ]; do
        sleep 0.05; ck_wait=$((ck_wait + 1))
    done
    # rank 1: the last aerotex-mpi among the job's processes
    mpi_tree() { for _c in $(pgrep -P "$1"); do echo "$_c"; mpi_tree "$_c"; done; }
    ck_rank=
    for _p in $(mpi_tree $ck_pid); do
        [ "$(cat /proc/"$_p"/comm 2>/dev/null)" = aerotex-mpi ] && ck_rank=$_p
    done
    [ -n "$ck_rank" ] && kill -9 "$ck_rank"
    wait $ck_pid
    ck_rc=$?
    ck_kept=0
    for _f in "$ck/run/t.wav.ckpt/"task*.bin; do
        [ -f "$_f" ] && ck_kept=$((ck_kept + 1))
    done
    if [ -n "$ck_rank" ] && [ $ck_rc -ne 0 ] && [ ! -f "$ck/run/t.wav" ] &&
        [ "$ck_kept" -ge 1 ] && [ "$ck_kept" -lt 6 ]; then
        pass "a rank killed mid-run: the job failed with $ck_kept of 6 directions kept"
    else
        fail "the kill: rank pid '${ck_rank}', exit $ck_rc, $ck_kept kept, texture $(ls "$ck/run")"
    fi
    cp -r "$ck/run/t.wav.ckpt" "$ck/saved"
    # shellcheck disable=SC2086
    if mpi_run 2 "$ck/run" $ck_args >"$ck/resumed.log" 2>&1 &&
        cmp "$ck/ref/t.wav" "$ck/run/t.wav" && [ ! -d "$ck/run/t.wav.ckpt" ]; then
        pass "resumed on 2 ranks: the one-process texture byte for byte, checkpoint removed"
    else
        fail "the resumed job"; tail -5 "$ck/resumed.log"
    fi
    # negative control: the resumed job reads the kept directions (one
    # sample in the middle of the first changed changes the texture)
    rm -f "$ck/run/t.wav"
    cp -r "$ck/saved" "$ck/run/t.wav.ckpt"
    for ck_task in "$ck/run/t.wav.ckpt/"task*.bin; do break; done
    ck_size=$(wc -c <"$ck_task")
    printf '\000\000\200\077' | dd of="$ck_task" bs=1 seek=$((ck_size / 8 * 4)) \
        conv=notrunc 2>/dev/null
    # shellcheck disable=SC2086
    (cd "$ck/run" && "$ROOT/build/aerotex-mpi" $ck_args) >"$ck/tampered.log" 2>&1
    if [ -f "$ck/run/t.wav" ] && ! cmp -s "$ck/ref/t.wav" "$ck/run/t.wav"; then
        pass "negative control: a changed checkpoint changes the texture (it is read)"
    else
        fail "negative control: the checkpoint was not what the job resumed from"
    fi

    # the solver's state within a direction (the 3D flow): the rank killed
    # once a state is kept, the job resumed from it
    st="$mpi_dir/state"
    mkdir -p "$st/ref" "$st/run"
    st_args="object --shape sphere --grid 8 --duration 0.1 --settle 0.5 --limiter off --threads 1 --checkpoint 20 -q -o s.wav"
    # shellcheck disable=SC2086
    (cd "$st/ref" && "$ROOT/build/aerotex" $st_args) >"$st/ref.log" 2>&1
    # shellcheck disable=SC2086
    mpi_run 1 "$st/run" $st_args >"$st/killed.log" 2>&1 &
    st_pid=$!
    st_wait=0
    while ! ls "$st/run/s.wav.ckpt/"state*.bin >/dev/null 2>&1 && [ $st_wait -lt 1200 ]; do
        sleep 0.05; st_wait=$((st_wait + 1))
    done
    st_rank=
    for _p in $(mpi_tree $st_pid); do
        [ "$(cat /proc/"$_p"/comm 2>/dev/null)" = aerotex-mpi ] && st_rank=$_p
    done
    [ -n "$st_rank" ] && kill -9 "$st_rank"
    wait $st_pid
    st_rc=$?
    if [ -n "$st_rank" ] && [ $st_rc -ne 0 ] && [ ! -f "$st/run/s.wav" ] &&
        [ -f "$st/run/s.wav.ckpt/state0000.bin" ]; then
        pass "3D flow: the rank killed within its direction, its flow state kept"
    else
        fail "3D flow kill: rank pid '${st_rank}', exit $st_rc, $(ls "$st/run" "$st/run/s.wav.ckpt" 2>&1 | tr '\n' ' ')"
    fi
    cp -r "$st/run/s.wav.ckpt" "$st/saved"
    # shellcheck disable=SC2086
    if mpi_run 1 "$st/run" $st_args >"$st/resumed.log" 2>&1 &&
        cmp "$st/ref/s.wav" "$st/run/s.wav" && [ ! -d "$st/run/s.wav.ckpt" ]; then
        pass "3D flow resumed from its state: the one-process texture byte for byte"
    else
        fail "3D flow resumed"; tail -5 "$st/resumed.log"
    fi
    # negative control: a changed velocity in the kept state changes it
    rm -f "$st/run/s.wav"
    cp -r "$st/saved" "$st/run/s.wav.ckpt"
    st_size=$(wc -c <"$st/run/s.wav.ckpt/state0000.bin")
    # 10 m/s in 64 faces of u in the middle of the box (an eighth into the
    # state: after the forces, the middle layers of u at this grid)
    for _i in $(seq 64); do printf '\000\000\040\101'; done |
        dd of="$st/run/s.wav.ckpt/state0000.bin" bs=1 \
        seek=$((st_size / 32 * 4)) conv=notrunc 2>/dev/null
    # shellcheck disable=SC2086
    (cd "$st/run" && "$ROOT/build/aerotex-mpi" $st_args) >"$st/tampered.log" 2>&1
    if [ -f "$st/run/s.wav" ] && ! cmp -s "$st/ref/s.wav" "$st/run/s.wav"; then
        pass "negative control: a changed flow state changes the texture (it is read)"
    else
        fail "negative control: the flow state was not what the job resumed from"
    fi
fi

# One 3D flow in z slabs over the ranks (src/tools/flow3d_slab.c,
# docs/cluster.md): build/tests/flow3d-slab makes a random field and a
# block body of two regions on a 16 x 16 x 24 grid, and compares with the
# one-process solver (aero_flow3d_project, aero_flow3d_step) what its
# slabs give at 1, 2 and 4 ranks: the projection alone, and 10 whole steps
# (MacCormack, confinement, viscosity, sponge, body forcing, projection)
# with 6 halo planes. Tolerance 1e-12 of the largest value: the velocity
# is expected bit for bit (a float differs by 6e-8 at least; the windows
# sample departure points at the whole grid's heights, so they round as
# the one process does), the region forces to the rounding of their
# double sums, added in another order over the ranks. A halo of 4 planes,
# narrower than a step reads, gives 6e-5 at 4 ranks; no halo exchange
# makes the flow blow up (negative controls). Then aerotex-mpi object
# --slabs: its samples at 2 and 4 ranks, and after a rank is killed and
# the job resumed from the ranks' window states, are the one-process
# samples byte for byte.
section "one 3D flow in z slabs over MPI ranks (docs/cluster.md)"
if [ ! -x build/tests/flow3d-slab ] || [ ! -x build/aerotex-mpi ] ||
    ! command -v mpirun >/dev/null 2>&1; then
    echo "  skip  no build/tests/flow3d-slab, build/aerotex-mpi or mpirun (Open MPI: make deps)"
else
    for _np in 1 2 4; do
        if _line=$(OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
            OMPI_MCA_btl=self,vader timeout 120 mpirun --oversubscribe \
            -np "$_np" "$ROOT/build/tests/flow3d-slab" 16 16 24 1e-12 2>&1); then
            pass "projection in $_np slabs: $(echo "$_line" | grep '^flow3d-slab' | sed 's/^flow3d-slab //')"
        else
            fail "projection in $_np slabs"; echo "$_line" | tail -3
        fi
        if _line=$(OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
            OMPI_MCA_btl=self,vader timeout 120 mpirun --oversubscribe \
            -np "$_np" "$ROOT/build/tests/flow3d-slab" 16 16 24 1e-12 halo 10 6 2>&1); then
            pass "10 steps in $_np slabs: $(echo "$_line" | grep '^flow3d-slab' | sed 's/^flow3d-slab //')"
        else
            fail "10 steps in $_np slabs"; echo "$_line" | tail -3
        fi
    done
    # aerotex-mpi object --slabs: a sphere's texture with each flow over
    # 2 and 4 ranks in slabs; its samples (the data chunk, the WAV's last:
    # the metadata holds the command line) equal the one-process run's
    slab_dir="$OUT/mpi-slabs"
    rm -rf "$slab_dir"
    mkdir -p "$slab_dir/one" "$slab_dir/np2" "$slab_dir/np4"
    slab_args="object --shape sphere --grid 8 --duration 0.1 --settle 0.5 --limiter off --threads 1 -q -o s.wav"
    # shellcheck disable=SC2086
    (cd "$slab_dir/one" && "$ROOT/build/aerotex" $slab_args) >"$slab_dir/one.log" 2>&1
    slab_samples() { # FILE: the bytes of its data chunk
        python3 -c 'import struct, sys
b = open(sys.argv[1], "rb").read(); i = 12
while i + 8 <= len(b):
    n = struct.unpack("<I", b[i + 4:i + 8])[0]
    if b[i:i + 4] == b"data":
        sys.stdout.buffer.write(b[i + 8:i + 8 + n])
    i += 8 + n + (n & 1)' "$1"
    }
    for _np in 2 4; do
        # shellcheck disable=SC2086
        if (cd "$slab_dir/np$_np" && OMPI_ALLOW_RUN_AS_ROOT=1 \
            OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader \
            timeout 300 mpirun --oversubscribe -np "$_np" \
            "$ROOT/build/aerotex-mpi" $slab_args --slabs) \
            >"$slab_dir/np$_np.log" 2>&1 && [ -f "$slab_dir/one/s.wav" ] &&
            [ "$(slab_samples "$slab_dir/one/s.wav" | od -An -tx1 | md5sum)" = \
              "$(slab_samples "$slab_dir/np$_np/s.wav" | od -An -tx1 | md5sum)" ] &&
            [ -n "$(slab_samples "$slab_dir/one/s.wav" | head -c 8)" ]; then
            pass "object --slabs on $_np ranks: the one-process samples byte for byte"
        else
            fail "object --slabs on $_np ranks"; tail -5 "$slab_dir/np$_np.log"
        fi
    done
    # a slab-split flow killed once its ranks kept their window states
    # (--checkpoint 20), resumed on 2 ranks: the one-process samples; a
    # changed velocity in rank 0's state changes them (it is read)
    sk="$slab_dir/ckpt"
    mkdir -p "$sk"
    sk_args="$slab_args --checkpoint 20 --slabs"
    # shellcheck disable=SC2086
    (cd "$sk" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        OMPI_MCA_btl=self,vader timeout 300 mpirun --oversubscribe -np 2 \
        "$ROOT/build/aerotex-mpi" $sk_args) >"$slab_dir/killed.log" 2>&1 &
    sk_pid=$!
    sk_wait=0
    while [ ! -f "$sk/s.wav.ckpt/state0000.001of002.bin" ] && [ $sk_wait -lt 1200 ]; do
        sleep 0.05; sk_wait=$((sk_wait + 1))
    done
    sk_rank=
    for _p in $(mpi_tree $sk_pid); do
        [ "$(cat /proc/"$_p"/comm 2>/dev/null)" = aerotex-mpi ] && sk_rank=$_p
    done
    [ -n "$sk_rank" ] && kill -9 "$sk_rank"
    wait $sk_pid
    sk_rc=$?
    cp -r "$sk/s.wav.ckpt" "$slab_dir/saved" 2>/dev/null
    # shellcheck disable=SC2086
    if [ -n "$sk_rank" ] && [ $sk_rc -ne 0 ] && [ ! -f "$sk/s.wav" ] &&
        (cd "$sk" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
            OMPI_MCA_btl=self,vader timeout 300 mpirun --oversubscribe -np 2 \
            "$ROOT/build/aerotex-mpi" $sk_args) >"$slab_dir/resumed.log" 2>&1 &&
        [ "$(slab_samples "$slab_dir/one/s.wav" | od -An -tx1 | md5sum)" = \
          "$(slab_samples "$sk/s.wav" | od -An -tx1 | md5sum)" ] &&
        [ ! -d "$sk/s.wav.ckpt" ]; then
        pass "object --slabs: a rank killed, resumed from the ranks' states to the one-process samples"
    else
        fail "object --slabs resumed: rank '$sk_rank', exit $sk_rc"; tail -3 "$slab_dir/resumed.log"
    fi
    rm -f "$sk/s.wav"
    cp -r "$slab_dir/saved" "$sk/s.wav.ckpt"
    sk_size=$(wc -c <"$sk/s.wav.ckpt/state0000.000of002.bin")
    # 10 m/s in 64 faces of u in rank 0's own planes (an eighth into it)
    for _i in $(seq 64); do printf '\000\000\040\101'; done |
        dd of="$sk/s.wav.ckpt/state0000.000of002.bin" bs=1 \
        seek=$((sk_size / 8)) conv=notrunc 2>/dev/null
    # shellcheck disable=SC2086
    (cd "$sk" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        OMPI_MCA_btl=self,vader timeout 300 mpirun --oversubscribe -np 2 \
        "$ROOT/build/aerotex-mpi" $sk_args) >"$slab_dir/tampered.log" 2>&1
    if [ -f "$sk/s.wav" ] && [ "$(slab_samples "$slab_dir/one/s.wav" | od -An -tx1 | md5sum)" != \
        "$(slab_samples "$sk/s.wav" | od -An -tx1 | md5sum)" ]; then
        pass "negative control: a changed window state changes the samples (it is read)"
    else
        fail "negative control: the window state was not what the job resumed from"
    fi
    for _neg in "halo 10 4" "nohalo 10 6"; do
        # shellcheck disable=SC2086
        if _line=$(OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
            OMPI_MCA_btl=self,vader timeout 120 mpirun --oversubscribe \
            -np 4 "$ROOT/build/tests/flow3d-slab" 16 16 24 1e-12 $_neg 2>&1); then
            fail "negative control ($_neg): 4 slabs passed"
        else
            pass "negative control ($_neg): $(echo "$_line" | grep '^flow3d-slab' | sed 's/^flow3d-slab //')"
        fi
    done
fi
