# --- packaging: deken archives, the libpd example ---------------------------
# DEKEN_PLATFORMS (default linux-amd64, what `make check` builds; make
# check-packages: every platform) chooses the packages made and checked
section "packaging: make deken (${DEKEN_PLATFORMS:-linux-amd64}, sources), the libpd example"

version=$(sed -n 's/^#X text [0-9]* [0-9]* VERSION \([0-9][0-9.]*\).*/\1/p' help/aero-meta.pd | head -n 1)
platforms=${DEKEN_PLATFORMS:-linux-amd64}
D=$OUT/deken # not build/deken: two runs (make check, check-pd056) may overlap
if make -s deken DEKEN_DIR="$D" DEKEN_PLATFORMS="$platforms" >"$OUT/deken.log" 2>&1; then
    pass "make deken for $platforms (version $version from help/aero-meta.pd)"
else
    fail "make deken"; tail -5 "$OUT/deken.log"
fi
classes=$(for c in src/pd/*~.c; do basename "$c" .c; done)
abstractions=$(cd abstractions && ls *.pd | sed 's/\.pd$//')
# PACKAGE:EXTENSION:FORMAT:CPU:FLOATSIZE; FORMAT/CPU as binutils name them
# (objdump -f's file format for Windows, readelf -h's class and machine),
# for macOS Mach-O and the architectures llvm-lipo names (PACKAGE is what
# goes between the name's outer parentheses: several (ARCH) for a
# universal package)
packages=""
for p in $platforms; do
    case "$p" in
        linux-amd64) packages="$packages
Linux-amd64-32:pd_linux:ELF64:X86-64:32
Linux-amd64-64:linux-amd64-64.so:ELF64:X86-64:64" ;;
        linux-arm64) packages="$packages
Linux-arm64-32:pd_linux:ELF64:AArch64:32" ;;
        linux-armv7) packages="$packages
Linux-armv7-32:pd_linux:ELF32:ARM:32" ;;
        windows-amd64) packages="$packages
Windows-amd64-32:windows-amd64-32.dll:pei-x86-64:-:32
Windows-amd64-64:windows-amd64-64.dll:pei-x86-64:-:64" ;;
        darwin) packages="$packages
Darwin-arm64-32)(Darwin-amd64-32:d_fat:Mach-O:arm64+x86_64:32
Darwin-arm64-64)(Darwin-amd64-64:darwin-fat-64.so:Mach-O:arm64+x86_64:64" ;;
        *) fail "unknown platform $p in DEKEN_PLATFORMS" ;;
    esac
done
binary_re='\.(pd_linux|so|dll|exe|dylib|pd_darwin|l_[a-z0-9]+|m_[a-z0-9]+|d_[a-z0-9]+)$'
# the libraries a binary loads beyond the system's C library and Pd
# (ELF: its NEEDED entries; PE: the DLLs it imports from)
foreign_libs() { # BINARY FORMAT
    if [ "$2" = pei-x86-64 ]; then
        objdump -p "$1" 2>/dev/null | awk '/DLL Name:/ { print $3 }' |
            grep -v -i -x -e kernel32.dll -e msvcrt.dll -e pd.dll
    elif [ "$2" = Mach-O ]; then
        # every slice's libraries; the first line of each is its own name
        llvm-otool-14 -L -arch all "$1" 2>/dev/null | grep '^[[:space:]]' |
            awk '{ print $1 }' | grep -v -x -e "$(basename "$1")" \
                -e /usr/lib/libSystem.B.dylib | sort -u
    else
        readelf -d "$1" 2>/dev/null | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' |
            grep -v -x -e libc.so.6 -e libm.so.6 -e libpthread.so.0 -e libdl.so.2 \
                -e 'ld-linux.*'
    fi
}
# negative control: the native build (make), linked to the system's
# shared libsndfile and FFTW, fails the same check
if [ -f aeolian~.pd_linux ]; then
    libs=$(foreign_libs aeolian~.pd_linux ELF64 | tr '\n' ' ')
    case "$libs" in
        *libsndfile*) pass "negative control: the native aeolian~.pd_linux needs $libs" ;;
        *) fail "negative control: the native aeolian~.pd_linux needs no libsndfile (${libs:-nothing})" ;;
    esac
fi
glibc_max=""
for pkg in $packages Sources; do
    fs=${pkg%%:*}
    dek="$D/aero[v$version]($fs).dek"
    if [ ! -s "$dek" ]; then
        fail "no $dek"; continue
    fi
    if (cd "$D" && sha256sum -c --quiet "$(basename "$dek").sha256" >/dev/null 2>&1); then
        pass "$(basename "$dek").sha256 matches"
    else
        fail "$(basename "$dek").sha256 does not match"
    fi
    # the object list: every object, with its help patch's description
    missing=""
    for o in $classes $abstractions; do
        grep -q "^$o	." "$dek.txt" 2>/dev/null || missing="$missing $o"
    done
    if [ -z "$missing" ]; then
        pass "$(basename "$dek").txt lists the $(wc -l <"$dek.txt") objects"
    else
        fail "$(basename "$dek").txt lacks:$missing"
    fi
    listing=$(unzip -Z1 "$dek" 2>/dev/null)
    if [ "$fs" = Sources ]; then
        missing=""
        for f in aero/Makefile aero/README.md aero/LICENSE aero/src/pd/aero.c \
            aero/help/aero-meta.pd aero/textures/sword.wav aero/trees/small.tree; do
            echo "$listing" | grep -q -x -F "$f" || missing="$missing $f"
        done
        if [ -z "$missing" ]; then
            pass "$(basename "$dek"): the sources ($(echo "$listing" | wc -l) entries)"
        else
            fail "$(basename "$dek") lacks:$missing"
        fi
        continue
    fi
    # a binary package: its own platform's and float size's binaries, none
    # other, and everything else of the library
    rest=${pkg#*:}
    ext=${rest%%:*} rest=${rest#*:}
    format=${rest%%:*} rest=${rest#*:}
    cpu=${rest%%:*} bits=${rest#*:}
    missing=""
    for f in $(for c in $classes aero; do echo "aero/$c.$ext"; done) \
        $(for c in $classes $abstractions; do echo "aero/$c-help.pd"; done) \
        $(for a in $abstractions; do echo "aero/$a.pd"; done) \
        $(ls textures/*.wav trees/*.tree | sed 's|^|aero/|') \
        $(ls docs/*.md docs/img/*.png | sed 's|^|aero/|') \
        aero/textures/README.md aero/trees/README.md \
        aero/aero-meta.pd aero/LICENSE aero/README.md; do
        echo "$listing" | grep -q -x -F "$f" || missing="$missing $f"
    done
    foreign=$(echo "$listing" | grep -E "$binary_re" | grep -v -F ".$ext" | head -3)
    if [ -z "$missing" ] && [ -z "$foreign" ]; then
        pass "$(basename "$dek"): *.$ext, help, abstractions, textures, trees, meta, license, the README's documents, no other binary"
    else
        fail "$(basename "$dek") lacks:$missing$(echo "$foreign" | sed 's/^/ has /')"
    fi
    # each binary is of the package's platform (file format, CPU) and
    # float size (a double-precision external calls class_new64, m_pd.h's
    # name for class_new with PD_FLOATSIZE=64), exports only its Pd entry
    # point, and needs no newer glibc than Debian 12's (2.36)
    x=$OUT/deken-x/$fs
    rm -rf "$x"
    mkdir -p "$x"
    unzip -q "$dek" -d "$x" 2>/dev/null
    wrong=""
    for b in "$x"/aero/*."$ext"; do
        [ -f "$b" ] || continue
        n=$(basename "$b")
        if [ "$format" = Mach-O ]; then
            # a universal binary holding exactly the package's CPUs;
            # symbols without Mach-O's leading underscore, both slices
            a=$(llvm-lipo-14 -archs "$b" 2>/dev/null | tr ' ' '\n' | grep . | LC_ALL=C sort | tr '\n' '+')
            [ "$a" = "$(echo "$cpu" | tr '+' '\n' | LC_ALL=C sort | tr '\n' '+')" ] ||
                wrong="$wrong $n:archs-$a"
            imports=$(llvm-nm-14 -u -j "$b" 2>/dev/null | grep -v -e ':$' -e '^$' |
                sed 's/^_//' | sort -u)
            exports=$(llvm-nm-14 -g --defined-only -j "$b" 2>/dev/null |
                grep -v -e ':$' -e '^$' | sed 's/^_//' | sort -u)
        elif [ "$format" = pei-x86-64 ]; then
            objdump -f "$b" 2>/dev/null | grep -q "file format $format" ||
                wrong="$wrong $n:not-$format"
            info=$(objdump -p "$b" 2>/dev/null)
            imports=$(echo "$info" | sed -n '/Import Tables/,/Export Address/p')
            exports=$(echo "$info" | sed -n '/Ordinal\/Name Pointer/,/^$/p' |
                awk '/Ordinal/ { next } NF >= 2 && $1 ~ /^\[/ { print $NF }')
        else
            h=$(readelf -h "$b" 2>/dev/null)
            echo "$h" | grep -q "Class: *$format" && echo "$h" | grep -q "Machine:.*$cpu" ||
                wrong="$wrong $n:not-$format-$cpu"
            if [ "$cpu" = ARM ]; then # armhf: the hard-float ABI
                echo "$h" | grep -q "hard-float" || wrong="$wrong $n:not-hard-float"
            fi
            imports=$(readelf --dyn-syms -W "$b" 2>/dev/null | awk '$7 == "UND" { print $8 }')
            exports=$(readelf --dyn-syms -W "$b" 2>/dev/null |
                awk '$7 != "UND" && $5 != "LOCAL" && NR > 3 && $8 != "" { print $8 }' |
                grep -v -x -e _init -e _fini)
            g=$(readelf -V -W "$b" 2>/dev/null | grep -o 'GLIBC_[0-9.]*' | sed 's/GLIBC_//' |
                sort -t . -k 1,1n -k 2,2n -k 3,3n | tail -n 1)
            glibc_max=$(printf '%s\n%s\n' "$glibc_max" "$g" | grep . |
                sort -t . -k 1,1n -k 2,2n -k 3,3n | tail -n 1)
            [ -n "$g" ] && [ "$(printf '%s\n2.36\n' "$g" |
                sort -t . -k 1,1n -k 2,2n | tail -n 1)" = 2.36 ] ||
                wrong="$wrong $n:glibc-$g"
        fi
        if [ "$bits" = 64 ]; then
            echo "$imports" | grep -q -w class_new64 || wrong="$wrong $n:no-class_new64"
        else
            echo "$imports" | grep -q -w class_new && ! echo "$imports" | grep -q -w class_new64 ||
                wrong="$wrong $n:not-32-bit-floats"
        fi
        libs=$(foreign_libs "$b" "$format" | tr '\n' ' ')
        [ -z "$libs" ] || wrong="$wrong $n:needs:$libs"
        other=$(echo "$exports" | grep . | grep -v '_setup$' | head -3 | tr '\n' ' ')
        [ -z "$other" ] || wrong="$wrong $n:exports:$other"
    done
    if [ -z "$wrong" ]; then
        what=$format
        [ "$cpu" = - ] || what="$format $cpu"
        pass "$(basename "$dek"): every binary is $what with $bits-bit floats, loads nothing but the C library and Pd, exports only *_setup"
    else
        fail "$(basename "$dek"):$wrong"
    fi
done
if [ -n "$glibc_max" ]; then
    pass "the Linux packages need glibc >= $glibc_max (Debian 12 has 2.36)"
fi
# the descriptions: once a help patch has a META DESCRIPTION, every one must
# (until then, the packages carry a generic line for each object)
with=0 without=""
for o in $classes $abstractions; do
    if grep -q "^#X text [0-9-]* [0-9-]* DESCRIPTION " "help/$o-help.pd"; then
        with=$((with + 1))
    else
        without="$without $o"
    fi
done
if [ "$with" -eq 0 ]; then
    pass "no help patch has a META DESCRIPTION yet: the .dek.txt carries a generic line"
elif [ -z "$without" ]; then
    if ! grep -q -F "aero: physically based aerodynamic sound" "$D/aero[v$version](Sources).dek.txt"; then
        pass "every object's .dek.txt line is its help patch's META DESCRIPTION"
    else
        fail "a generic line in the .dek.txt although every help patch has a DESCRIPTION"
    fi
else
    fail "help patches without a META DESCRIPTION:$without"
fi

# the package of this Pd's float size, unpacked into a fresh folder as
# deken does: every help patch opens from there, with nothing else on the
# path (externals, abstractions, textures and trees from the package)
# (when the Linux amd64 packages are among those made)
fs=${PD_FLOATSIZE:-32}
unpacked=$OUT/deken-$fs
rm -rf "$unpacked"
mkdir -p "$unpacked"
if ! echo " $platforms " | grep -q " linux-amd64 "; then
    :
elif unzip -q "$D/aero[v$version](Linux-amd64-$fs).dek" -d "$unpacked" 2>"$OUT/deken-unzip.log"; then
    for p in "$unpacked"/aero/*-help.pd; do
        [ -f "$p" ] || continue
        log="$OUT/deken-$fs-$(basename "$p" .pd).log"
        # shellcheck disable=SC2086
        timeout 120 "$PD" $PD_FLAGS -open "$ROOT/$p" \
            -open "$ROOT/tests/pd/run-1s-and-quit.pd" >"$log" 2>&1
        log_clean "$log" "from the unpacked (Linux-amd64-$fs) package: $(basename "$p") opens cleanly"
    done
else
    fail "unzip of the (Linux-amd64-$fs) package"; cat "$OUT/deken-unzip.log"
fi
# the libpd host must keep compiling against Pd's API with -DPDINSTANCE
if cc -std=c99 -fsyntax-only -Wall -Wextra -Werror -DPDINSTANCE -DPDTHREADS \
    -I/usr/include/pd -Isrc/pd examples/libpd-host.c 2>"$OUT/libpd-example.log"; then
    pass "examples/libpd-host.c compiles with -DPDINSTANCE"
else
    fail "examples/libpd-host.c"; cat "$OUT/libpd-example.log"
fi
