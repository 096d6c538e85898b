#!/usr/bin/env python3
"""Fails when two different English labels get the same translation (once
the probing feed and the measuring feed were both 测量进给率). Labels are the
short texts: at most five words, whatever their context. Pairs that are one
word in a language (listed in ALLOWED) are allowed.
usage: check_terms.py TS_FILE..."""
import sys
import xml.etree.ElementTree as ET

# English labels that may share a translation: the same thing said two ways.
ALLOWED = {
    frozenset({"Measuring feedrate", "measuring feed"}),
    frozenset({"line %1", "lines %1"}),  # Chinese has no plural
    frozenset({"Touch", "Touches"}),
}


def labels(path):
    out = {}
    for ctx in ET.parse(path).getroot().findall("context"):
        for m in ctx.findall("message"):
            src = m.findtext("source") or ""
            tr = m.find("translation")
            if tr is None or not tr.text or tr.get("type") in ("unfinished", "vanished", "obsolete"):
                continue
            if len(src.split()) > 5 or m.get("numerus") == "yes":
                continue
            out.setdefault(tr.text.strip(), set()).add(src.strip().rstrip(":").replace("&", ""))
    return out


status = 0
for path in sys.argv[1:]:
    for translation, sources in sorted(labels(path).items()):
        folded = {s.lower() for s in sources}
        if len(folded) > 1 and frozenset(sources) not in ALLOWED:
            print(f"{path}: '{translation}' translates {sorted(sources)}")
            status = 1
if status == 0:
    print("terms distinct: no two English labels share a translation")
sys.exit(status)
