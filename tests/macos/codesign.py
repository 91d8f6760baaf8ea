#!/usr/bin/env python3
"""aero: checks the code signature of a Mach-O file's arm64 code, as far as
it can be without Apple's tools: usage codesign.py FILE [ARCH] (ARCH arm64
by default; FILE thin or universal). Finds LC_CODE_SIGNATURE, reads the
SuperBlob it points to (Apple's blob format, big-endian: magic 0xfade0cc0
with an index of blobs), takes its CodeDirectory (magic 0xfade0c02) and
recomputes every code slot: the hash of each page of the file (from the
slice's start up to codeLimit, pages of 2^pageSize bytes) must be the one
stored. Prints one line; exit 0 when every slot matches and the directory
is ad hoc (flag 0x2: signed without a certificate, what a Mac requires of
arm64 code at the least), 1 otherwise, 2 when the file is not readable as
Mach-O."""
import hashlib
import struct
import sys

FAT_MAGIC = 0xCAFEBABE
MH_MAGIC_64 = 0xFEEDFACF
CPU_ARM64 = 0x0100000C
CPU_X86_64 = 0x01000007
LC_CODE_SIGNATURE = 0x1D
CSMAGIC_EMBEDDED_SIGNATURE = 0xFADE0CC0
CSMAGIC_CODEDIRECTORY = 0xFADE0C02
CS_ADHOC = 0x2
HASHES = {1: hashlib.sha1, 2: hashlib.sha256}


def slice_of(data, cpu):
    """(offset, size) of the slice for cpu in a thin or universal file"""
    if struct.unpack(">I", data[:4])[0] == FAT_MAGIC:
        n = struct.unpack(">I", data[4:8])[0]
        for i in range(n):
            c, _, off, size, _ = struct.unpack(">iiIII", data[8 + 20 * i:28 + 20 * i])
            if c & 0xFFFFFFFF == cpu:
                return off, size
        return None
    magic, c = struct.unpack("<Ii", data[:8])
    if magic == MH_MAGIC_64 and c & 0xFFFFFFFF == cpu:
        return 0, len(data)
    return None


def check(path, arch):
    data = open(path, "rb").read()
    where = slice_of(data, {"arm64": CPU_ARM64, "x86_64": CPU_X86_64}[arch])
    if where is None:
        return 2, "%s: no %s Mach-O slice" % (path, arch)
    off, size = where
    m = data[off:off + size]
    magic, _, _, _, ncmds = struct.unpack("<IiiII", m[:20])
    if magic != MH_MAGIC_64:
        return 2, "%s: not a 64-bit Mach-O" % path
    p = 32
    sig = None
    for _ in range(ncmds):
        cmd, cmdsize = struct.unpack("<II", m[p:p + 8])
        if cmd == LC_CODE_SIGNATURE:
            sig = struct.unpack("<II", m[p + 8:p + 16])
        p += cmdsize
    if sig is None:
        return 1, "%s (%s): no LC_CODE_SIGNATURE" % (path, arch)
    dataoff, datasize = sig
    blob = m[dataoff:dataoff + datasize]
    bmagic, _, count = struct.unpack(">III", blob[:12])
    if bmagic != CSMAGIC_EMBEDDED_SIGNATURE:
        return 1, "%s (%s): the signature is not an embedded SuperBlob" % (path, arch)
    cd = None
    for i in range(count):
        _, boff = struct.unpack(">II", blob[12 + 8 * i:20 + 8 * i])
        if struct.unpack(">I", blob[boff:boff + 4])[0] == CSMAGIC_CODEDIRECTORY:
            cd = blob[boff:]
            break
    if cd is None:
        return 1, "%s (%s): no CodeDirectory" % (path, arch)
    (_, _, _, flags, hash_off, _, _, ncode, code_limit, hash_size, hash_type,
     _, page_log) = struct.unpack(">IIIIIIIIIBBBB", cd[:40])
    if hash_type not in HASHES:
        return 1, "%s (%s): unknown hash type %d" % (path, arch, hash_type)
    page = 1 << page_log
    if code_limit != dataoff or ncode != (code_limit + page - 1) // page:
        return 1, "%s (%s): the CodeDirectory covers %d bytes in %d slots, the code is %d" % (
            path, arch, code_limit, ncode, dataoff)
    bad = 0
    for i in range(ncode):
        h = HASHES[hash_type](m[i * page:min((i + 1) * page, code_limit)]).digest()
        if h[:hash_size] != cd[hash_off + i * hash_size:hash_off + (i + 1) * hash_size]:
            bad += 1
    if bad:
        return 1, "%s (%s): %d of %d page hashes do not match" % (path, arch, bad, ncode)
    if not flags & CS_ADHOC:
        return 1, "%s (%s): the signature is not ad hoc (flags 0x%x)" % (path, arch, flags)
    return 0, "%s (%s): ad-hoc signature, %d page hashes (%s) match" % (
        path, arch, ncode, HASHES[hash_type]().name)


if __name__ == "__main__":
    try:
        status, line = check(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "arm64")
    except (OSError, struct.error, IndexError) as e:
        status, line = 2, "%s: %s" % (sys.argv[1] if len(sys.argv) > 1 else "?", e)
    print(line)
    sys.exit(status)
