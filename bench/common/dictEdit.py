#!/usr/bin/env python3
"""Edit one entry of an OpenFOAM dictionary file in place, leaving the rest
of the text as it is (comments, #include, $:scope.key references).

    dictEdit.py FILE ENTRY VALUE       set a/b/c to VALUE (made if missing;
                                       its parent dictionaries must exist)
    dictEdit.py FILE ENTRY --remove    remove a/b/c
    dictEdit.py FILE ENTRY             print a/b/c's text as written

Why not foamDictionary -set: it writes the whole file back expanded, so an
#include of system/setup (the inhaler's) becomes the included values, and a
list included from another file is written inline with 6 digits. A VALUE
starting with '{' replaces a sub-dictionary whole. dpiFoam refuses a key
given twice, so appending an override is not an option either.
"""
import sys


def skip(s, i):
    """Index of the next character that is not blank or in a comment."""
    while i < len(s):
        if s[i].isspace():
            i += 1
        elif s.startswith("//", i):
            j = s.find("\n", i)
            i = len(s) if j < 0 else j + 1
        elif s.startswith("/*", i):
            j = s.find("*/", i + 2)
            if j < 0:
                raise SystemExit("dictEdit: unterminated /* comment")
            i = j + 2
        else:
            return i
    return i


def token(s, i):
    """End of the token at i: a quoted string or a run of non-blank,
    non-delimiter characters."""
    if s[i] == '"':
        j = s.find('"', i + 1)
        if j < 0:
            raise SystemExit("dictEdit: unterminated string")
        return j + 1
    j = i
    while j < len(s) and not s[j].isspace() and s[j] not in "{};":
        j += 1
    return j


def valueEnd(s, i):
    """End (exclusive) of the value starting at i: a block { } or the text
    up to the ';' outside brackets, strings and comments."""
    depth = 0
    while i < len(s):
        i2 = skip(s, i)
        if i2 != i:
            i = i2
            continue
        c = s[i]
        if c == '"':
            i = token(s, i)
            continue
        if c in "({[":
            depth += 1
        elif c in ")}]":
            depth -= 1
            if depth == 0 and c == "}":
                return i + 1
        elif c == ";" and depth == 0:
            return i + 1
        i += 1
    raise SystemExit("dictEdit: a value runs to the end of the file")


def entries(s, i, end):
    """(key, start, end) of each entry between i and end, directives
    (#include "f", #remove k) with their one argument."""
    out = []
    while True:
        i = skip(s, i)
        if i >= end or s[i] == "}":
            return out
        k = token(s, i)
        key = s[i:k]
        if key.startswith("#"):
            j = token(s, skip(s, k))
        else:
            j = valueEnd(s, skip(s, k))
        out.append((key, i, j))
        i = j


def find(s, path):
    """(start, end, bodyStart, bodyEnd) of path's parent body and the entry,
    or None for the entry where it is missing."""
    lo, hi = 0, len(s)
    found = None
    for n, key in enumerate(path):
        match = [e for e in entries(s, lo, hi) if e[0] == key]
        if not match:
            if n < len(path) - 1:
                raise SystemExit(
                    "dictEdit: no dictionary %s" % "/".join(path[:n + 1]))
            return lo, hi, None
        found = match[-1]
        if n < len(path) - 1:
            b = skip(s, token(s, found[1]))
            if s[b] != "{":
                raise SystemExit(
                    "dictEdit: %s is not a dictionary" % "/".join(path[:n + 1]))
            lo, hi = b + 1, found[2] - 1
    return lo, hi, found


def main(argv):
    if len(argv) not in (3, 4):
        raise SystemExit(__doc__)
    name, path = argv[1], argv[2].split("/")
    s = open(name).read()
    lo, hi, e = find(s, path)
    if len(argv) == 3:
        if e is None:
            raise SystemExit("dictEdit: no entry %s in %s" % (argv[2], name))
        print(s[e[1]:e[2]])
        return
    value = argv[3]
    if value == "--remove":
        if e is None:
            raise SystemExit("dictEdit: no entry %s in %s" % (argv[2], name))
        s = s[:e[1]] + s[e[2]:]
    else:
        text = path[-1] + " " + value + ("" if value.lstrip().startswith("{") else ";")
        if e is not None:
            s = s[:e[1]] + text + s[e[2]:]
        elif hi == len(s):
            s = s.rstrip("\n") + "\n" + text + "\n"
        else:
            line = s.rfind("\n", 0, hi) + 1
            at = line if s[line:hi].strip() == "" else hi
            s = s[:at] + "    " + text + "\n" + s[at:]
    open(name, "w").write(s)


if __name__ == "__main__":
    main(sys.argv)
