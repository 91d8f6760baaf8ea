#!/usr/bin/env python3
"""aero: the names Pd's API headers declare, one per line, as Mach-O
symbols (with their leading underscore): usage pd-api.py [HEADER...]
(default /usr/include/pd/m_pd.h, g_canvas.h and s_stuff.h, the headers
the wrappers are compiled against: aero_pd.c takes canvas_realizedollar
from g_canvas.h, fieldsound~.c audio_isopen from s_stuff.h). Every EXTERN declaration counts, functions and variables
(s_float, sys_idlehook...), whatever #if it is under (class_new64 is the
double build's class_new)."""
import re
import sys

headers = sys.argv[1:] or ["/usr/include/pd/m_pd.h", "/usr/include/pd/g_canvas.h",
                           "/usr/include/pd/s_stuff.h"]
text = "\n".join(open(h).read() for h in headers)
text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
text = re.sub(r"//[^\n]*", " ", text)
# preprocessor lines are not declarations
text = "\n".join(l for l in text.split("\n") if not l.lstrip().startswith("#"))
names = set()
for stmt in text.split(";"):
    s = " ".join(stmt.split())
    m = re.search(r"\bEXTERN\s+(.*)$", s)
    if not m or "EXTERN_STRUCT" in s:
        continue
    decl = m.group(1)
    fp = re.search(r"\(\s*\*\s*(\w+)\s*\)", decl)  # a pointer to function
    fn = re.search(r"(\w+)\s*\(", decl)
    if fp and (not fn or decl.index(fp.group(0)) < decl.index(fn.group(0))):
        names.add(fp.group(1))
    elif fn:
        names.add(fn.group(1))
    else:
        for part in decl.split(","):  # EXTERN t_symbol s_a, s_b
            v = re.findall(r"(\w+)\s*(?:\[[^\]]*\])?\s*$", part.strip())
            if v:
                names.add(v[0])
for n in sorted(names):
    print("_" + n)
