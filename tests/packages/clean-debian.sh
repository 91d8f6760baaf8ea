#!/bin/sh
# The Linux deken packages on a Linux with nothing but Pd: a minimal
# Debian 12 (debootstrap --variant=minbase) with only puredata-core
# installed, so no libsndfile, no FFTW, no compiler. The package is
# unzipped into ~/pd-externals as a user would; in a chroot Debian's Pd
# 0.53 (batch mode) loads every object and abstraction with
# [declare -path aero] (and the single binary with [declare -lib aero])
# and renders each; the WAV is copied out and judged by the native
# build/aero-analyze: sounding and finite. The double-precision package is
# played by Pd 0.56-5 built with PD_FLOATSIZE=64 (build/pd056/double, as
# make check-pd056 builds it, ~1 min), copied into the same root: it needs
# nothing but glibc. A negative control unpacks the externals of
# `make install` (linked to the system's libsndfile and FFTW) into the same
# root: they must fail to load ("libsndfile.so.1: cannot open shared
# object file"), which shows the root lacks what the packages carry.
#
# The bootstrapped root is cached as a tarball outside the clone,
# ${AERO_CACHE:-$HOME/.cache/aero}/debian12-minbase-KEY.tar.gz, KEY a
# hash of the suite, variant and package list; build/clean-debian/root is
# unpacked from it on every run. Needs root (debootstrap, chroot) and
# Debian's archive (DEBIAN_MIRROR, default http://deb.debian.org/debian)
# the first time.
#
# Usage (repository root, after `make deken` and `make all lib`):
#   sh tests/packages/clean-debian.sh [DEKEN_DIR]   (default build/deken)
# Ends with `N passed, N failed`.
ROOT=$(pwd)
DEKEN_DIR=${1:-build/deken}
case "$DEKEN_DIR" in /*) ;; *) DEKEN_DIR=$ROOT/$DEKEN_DIR ;; esac
CACHE=${AERO_CACHE:-$HOME/.cache/aero}
MIRROR=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
SUITE=bookworm
VARIANT=minbase
PACKAGES=puredata-core
ANALYZE=$ROOT/build/aero-analyze
WORK=$ROOT/build/clean-debian
R=$WORK/root
OUT=$WORK/out
RATE=44100
PD056_ARCHIVE=${PD056_ARCHIVE:-$ROOT/../shared/vendor/pure-data-0.56-5.tar.gz}
PD64=$ROOT/build/pd056/double

. "$ROOT/tests/judge.sh" # pass, fail, judge
finish() {
    echo
    echo "clean Debian: $(($(date +%s) - start)) s"
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
    exit
}
start=$(date +%s)
echo "== the Linux packages in a minimal Debian 12 with only $PACKAGES"

if [ "$(id -u)" -ne 0 ]; then
    fail "needs root (debootstrap, chroot)"; finish
fi
version=$(sed -n 's/^#X text [0-9]* [0-9]* VERSION \([0-9][0-9.]*\).*/\1/p' \
    help/aero-meta.pd | head -n 1)
dek32="$DEKEN_DIR/aero[v$version](Linux-amd64-32).dek"
dek64="$DEKEN_DIR/aero[v$version](Linux-amd64-64).dek"
[ -f "$dek32" ] || { fail "no $dek32 (make deken first)"; finish; }

# --- the root: from the cache, or bootstrapped once ------------------------
key=$(printf '%s\n' "$SUITE" "$VARIANT" "$PACKAGES" | sha256sum | cut -c 1-16)
tarball=$CACHE/debian12-$VARIANT-$key.tar.gz
if [ ! -s "$tarball" ]; then
    echo "-- bootstrapping $SUITE ($VARIANT + $PACKAGES) from $MIRROR"
    t0=$(date +%s)
    rm -rf "$WORK/bootstrap"
    mkdir -p "$CACHE" "$WORK"
    if nice -n 10 debootstrap --variant="$VARIANT" --include="$PACKAGES" \
        "$SUITE" "$WORK/bootstrap" "$MIRROR" >"$WORK/debootstrap.log" 2>&1; then
        # what apt downloaded is not part of the system
        rm -rf "$WORK/bootstrap/var/cache/apt/archives/"*.deb \
            "$WORK/bootstrap/var/lib/apt/lists/"*
        tar -C "$WORK/bootstrap" -czf "$tarball.tmp" . && mv "$tarball.tmp" "$tarball"
        rm -rf "$WORK/bootstrap"
        pass "debootstrap $SUITE $VARIANT + $PACKAGES: $(du -h "$tarball" | cut -f 1) cached as $tarball ($(($(date +%s) - t0)) s)"
    else
        fail "debootstrap (log: $WORK/debootstrap.log)"; tail -5 "$WORK/debootstrap.log"
        rm -rf "$WORK/bootstrap"
        finish
    fi
fi
rm -rf "$R" "$OUT"
mkdir -p "$R" "$OUT"
tar -C "$R" -xzf "$tarball" || { fail "unpacking $tarball"; finish; }

# nothing of what aero links is there (so the test can tell)
found=$(cd "$R" && ls usr/lib/*/libsndfile* usr/lib/*/libfftw3* \
    usr/lib/*/libFLAC* usr/lib/*/libvorbis* 2>/dev/null)
pdver=$(chroot "$R" pd -version 2>&1 | head -n 1)
if [ -z "$found" ] && [ -n "$pdver" ]; then
    pass "the root has $pdver and no libsndfile, FFTW, FLAC or Vorbis ($(chroot "$R" dpkg-query -W | wc -l) Debian packages)"
else
    fail "the root is not as it should be: ${pdver:-no pd}, has: $found"
fi

# --- one render per object ------------------------------------------------
# NAME|DECLARE|OBJECT|SPEED (a [sig~] into inlet 0, - for none)|MESSAGE
# (sent to inlet 0 when the recording starts, - for none)|CHANNELS
renders="aeolian|-path aero|aeolian~ -d 0.01 -l 0.5|10|-|1
aeolian-sword|-path aero|aeolian~ -texture sword -stereo|10|-|2
cavity|-path aero|cavity~ -L 0.02 -D 0.01 -W 0.05|10|-|1
cavity-texture|-path aero|cavity~ -texture cavity|10|-|1
vortex|-path aero|vortex~ -texture fire -listener 0 2 0|8|-|1
body|-path aero|body~ -texture sphere -listener 0 1 0|20|-|1
rotor|-path aero|rotor~ -listener 0 1 0|3000|-|1
treebranch|-path aero|treebranch~ small -listener 0 -12 1.7|8|-|1
leafwave|-path aero|leafwave~ small|8|-|1
fieldsound|-path aero|fieldsound~ -demo 8 -sync -listener 4 0 0|-|play|1
lib|-lib aero|aeolian~ -d 0.01|10|-|1
wind|-path aero|aero.wind~|-|-|1
draft|-path aero|aero.draft~|-|-|2
fence|-path aero|aero.fence~|10|-|2
fire|-path aero|aero.fire~|-|-|2
swing|-path aero|aero.swing~|-|bang|2
throw|-path aero|aero.throw~|-|bang|2
whirl|-path aero|aero.whirl~|-|rate 4 \\, whirl 1|2
tree|-path aero|aero.tree~ small|-|-|2
fan|-path aero|aero.fan~|-|fan 1|2
drone|-path aero|aero.drone~|-|thrust 1|2
propeller|-path aero|aero.propeller~|-|-|2
turbine|-path aero|aero.turbine~|-|-|2"

DUR=2000
write_patch() { # FILE DECLARE OBJECT SPEED MESSAGE WAV
    frames=$((DUR * RATE / 1000))
    {
        echo "#N canvas 0 50 600 400 10;"
        echo "#X declare $2;"
        echo "#X obj 10 10 loadbang;"                                  # 0
        echo "#X msg 10 30 \\; pd dsp 1;"                              # 1
        echo "#X obj 10 60 sig~ ${4#-};"                               # 2
        echo "#X obj 10 90 $3;"                                        # 3
        # [tabwrite~] zeroes NaN and Inf: they are marked as 1e9 before
        echo "#X obj 10 150 expr~ if(abs(\\\$v1) < 1e30 \\, \\\$v1 \\, 1e9);" # 4
        echo "#X obj 200 150 expr~ if(abs(\\\$v1) < 1e30 \\, \\\$v1 \\, 1e9);" # 5
        echo "#X obj 10 180 tabwrite~ out0;"                           # 6
        echo "#X obj 200 180 tabwrite~ out1;"                          # 7
        echo "#X obj 400 10 array define out0 $frames;"                # 8
        echo "#X obj 400 30 array define out1 $frames;"                # 9
        echo "#X obj 100 10 delay 200;"                                # 10
        echo "#X obj 200 220 delay $((200 + DUR + 10));"               # 11
        echo "#X msg 200 240 write -bytes 4 -rate $RATE $6 out0 out1;" # 12
        echo "#X obj 200 260 soundfiler;"                              # 13
        echo "#X msg 200 280 \\; pd quit;"                             # 14
        echo "#X msg 300 60 ${5#-};"                                   # 15
        echo "#X obj 10 250 declare $2;"                               # 16
        for c in "0 0 1 0" "0 0 10 0" "0 0 11 0" "3 0 4 0" "4 0 6 0" \
            "10 0 6 0" "10 0 7 0" "11 0 12 0" "12 0 13 0" "13 0 14 0"; do
            echo "#X connect $c;"
        done
        [ "$4" = - ] || echo "#X connect 2 0 3 0;"
        [ "$5" = - ] || { echo "#X connect 10 0 15 0;"; echo "#X connect 15 0 3 0;"; }
        echo "#X connect 3 1 5 0;"
        echo "#X connect 5 0 7 0;"
    } >"$1"
}
# the object's second outlet is connected only when it has two signal
# outlets: a patch naming a missing outlet logs "connection failed"

# render_all LABEL PD-IN-ROOT FLOATSIZE-EXT: every render in the root
render_all() {
    label=$1 pd=$2 ext=$3
    mkdir -p "$R/root/renders-$label"
    echo "$renders" | while IFS='|' read -r name declare object speed message nch; do
        # not NAME.pd: Pd looks for textures (fire, cavity) in the
        # patch's folder first, where an earlier render's WAV would be
        patch=/root/renders-$label/render-$name.pd
        wav=/root/renders-$label/render-$name.wav
        write_patch "$R$patch" "$declare" "$object" "$speed" "$message" "$wav"
        [ "$nch" -ge 2 ] || sed -i '/^#X connect 3 1 5 0;$/d; /^#X connect 5 0 7 0;$/d' "$R$patch"
        rm -f "$R$wav"
        chroot "$R" /usr/bin/env -i HOME=/root PATH=/usr/bin:/bin \
            timeout 120 "$pd" -batch -nogui -noaudio -noprefs -stderr -verbose \
            -r "$RATE" -open "$patch" >"$OUT/$label-$name.log" 2>&1
        log="$OUT/$label-$name.log"
        if grep -q -i -e "couldn't create" -e "error" -e "connection failed" \
            -e "cannot open" "$log" || [ ! -s "$R$wav" ]; then
            echo "FAIL $label $name: [$object] did not load or render"
            grep -i -e "couldn't" -e "error" -e "cannot" "$log" | head -5 | sed 's/^/        /'
            continue
        fi
        cp "$R$wav" "$OUT/$label-$name.wav"
        # loaded from the unpacked package (Pd's -verbose names the file)
        case "$object" in
            aero.*) file=${object%% *}.pd ;;
            *) file=${object%% *}.$ext ;;
        esac
        [ "$name" = lib ] && file=aero.$ext
        if grep -q "tried /root/pd-externals/aero/$file and succeeded" "$log"; then
            echo "ok $label $name: [$object] loaded from ~/pd-externals/aero/$file"
        else
            echo "FAIL $label $name: $file not loaded from ~/pd-externals/aero"
        fi
        ch=0
        while [ "$ch" -lt "$nch" ]; do
            "$ANALYZE" finite "$OUT/$label-$name.wav" --ch "$ch" --max 1e4
            "$ANALYZE" level "$OUT/$label-$name.wav" --ch "$ch" --min 20
            ch=$((ch + 1))
        done
    done >"$OUT/$label.results" 2>&1
    while IFS= read -r line; do
        case "$line" in
            ok*) pass "${line#ok }" ;;
            FAIL*) fail "${line#FAIL }" ;;
            *) echo "$line" ;;
        esac
    done <"$OUT/$label.results"
}

unpack() { # DEK: ~/pd-externals/aero in the root holds the package only
    rm -rf "$R/root/pd-externals"
    mkdir -p "$R/root/pd-externals"
    unzip -q "$1" -d "$R/root/pd-externals"
}

echo "-- (Linux-amd64-32) in Debian's $pdver"
if unpack "$dek32"; then
    render_all single32 /usr/bin/pd pd_linux
else
    fail "unzip $dek32"
fi

# --- double precision: Pd 0.56-5 with 64-bit floats, copied in ------------
echo "-- (Linux-amd64-64) in Pd 0.56-5 (PD_FLOATSIZE=64)"
if [ ! -x "$PD64/bin/pd" ] && [ -f "$PD056_ARCHIVE" ]; then
    rm -rf "$PD64"
    mkdir -p "$PD64"
    tar xzf "$PD056_ARCHIVE" -C "$PD64" --strip-components=1 &&
        nice -n 10 make -j2 -C "$PD64/src" -f makefile.gnu ALSA=false OSS=false \
            MORECFLAGS=-DPD_FLOATSIZE=64 bin >"$PD64.log" 2>&1
fi
if [ ! -f "$dek64" ]; then
    fail "no $dek64"
elif [ ! -x "$PD64/bin/pd" ]; then
    fail "no double-precision Pd 0.56 ($PD64/bin/pd; vendored archive: $PD056_ARCHIVE)"
else
    mkdir -p "$R/opt/pd64"
    cp -r "$PD64/bin" "$R/opt/pd64/"
    if unpack "$dek64"; then
        render_all double64 /opt/pd64/bin/pd linux-amd64-64.so
    else
        fail "unzip $dek64"
    fi
fi

# --- negative control: the externals of `make install` --------------------
# (linked to the system's shared libsndfile and FFTW) do not load there
echo "-- negative control: make install's externals (shared libsndfile, FFTW)"
rm -rf "$R/root/pd-externals"
if make -s install PDLIBDIR="$R/root/pd-externals" >"$OUT/neg-install.log" 2>&1; then
    mkdir -p "$R/root/renders-neg"
    write_patch "$R/root/renders-neg/aeolian.pd" "-path aero" "aeolian~ -d 0.01" 10 - \
        /root/renders-neg/aeolian.wav
    chroot "$R" /usr/bin/env -i HOME=/root PATH=/usr/bin:/bin \
        timeout 120 pd -batch -nogui -noaudio -noprefs -stderr -verbose \
        -r "$RATE" -open /root/renders-neg/aeolian.pd >"$OUT/neg.log" 2>&1
    if grep -q "libsndfile.so.1: cannot open shared object file" "$OUT/neg.log" &&
        grep -q "couldn't create" "$OUT/neg.log"; then
        pass "negative control fails as it must: $(grep -o '[^ /]*: cannot open shared object file' "$OUT/neg.log" | head -n 1), [aeolian~] couldn't create"
    else
        fail "negative control: make install's [aeolian~] did not fail on a missing libsndfile"
        sed 's/^/        /' "$OUT/neg.log" | head -10
    fi
else
    fail "make install (negative control)"; tail -5 "$OUT/neg-install.log"
fi
finish
