#!/usr/bin/env python3
"""reorderTypes.py FILE: reverse the order of the entries of dem/types in a
dpiCloudProperties file, text only (foamDictionary would rewrite every
number to 6 digits and change the physics)."""
import re
import sys

path = sys.argv[1]
text = open(path).read()
start = re.search(r"\n    types\s*\n    \{", text)
if not start:
    sys.exit("no dem/types block in " + path)
i = start.end()                     # just after the opening brace
depth, j = 1, i
while depth:
    depth += {"{": 1, "}": -1}.get(text[j], 0)
    j += 1
body = text[i:j - 1]                # between the braces of types

# the entries: a name line followed by a brace block
entries, k = [], 0
for m in re.finditer(r"\n\s*([A-Za-z_][A-Za-z0-9_]*)[^\n{]*\n?\s*\{", body):
    if m.start() < k:
        continue
    depth, e = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(body[e], 0)
        e += 1
    entries.append(body[m.start():e])
    k = e
if len(entries) < 2:
    sys.exit("fewer than two types in " + path)
new = "".join(reversed(entries)) + "\n    "
open(path, "w").write(text[:i] + new + text[j - 1:])
print("types now:", [re.search(r"[A-Za-z_]\w*", e).group(0) for e in reversed(entries)])
