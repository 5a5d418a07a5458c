#!/usr/bin/python3
"""Read and write OpenFOAM ASCII lagrangian fields (IOField<label|scalar|vector>).

A small helper for the tutorial scripts: no OpenFOAM Python bindings are
needed. Handles the three ASCII list forms OpenFOAM writes:
    N{value}                  (uniform)
    N(v0 v1 ...)              (one line)
    N\n(\nv0\nv1\n...\n)      (one entry per line)
with vector entries written as (x y z); and the per-parcel lists of the
contact histories (IOField<labelField>, IOField<vectorField>: contactKeys,
contactXi), a list of such lists, by read_nested_field and
write_nested_field.
"""
import os
import re

import numpy as np

_HEADER_END = re.compile(r"^// \* \*.*$", re.M)


def split_header(text):
    """(header incl. the '// * *' line, body) of an OpenFOAM file."""
    m = _HEADER_END.search(text)
    if not m:
        raise ValueError("no '// * * *' header separator")
    return text[:m.end()], text[m.end():]


def _parse_body(body):
    body = re.sub(r"//.*", "", body)             # trailing comments
    m = re.match(r"\s*(\d+)\s*([({])", body)
    if not m:
        raise ValueError("no list in field body")
    n = int(m.group(1))
    rest = body[m.end(1):].strip()
    if rest.startswith("{"):                      # uniform
        inner = rest[1:rest.index("}")].strip()
        if inner.startswith("("):
            v = [float(x) for x in inner.strip("()").split()]
            return np.tile(np.array(v), (n, 1))
        return np.full(n, float(inner))
    # outer list: from the first '(' to its matching ')'
    depth = 0
    for k, ch in enumerate(rest):
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth == 0:
                break
    inner = rest[1:k]
    if "(" in inner:                               # vectors
        vals = re.findall(r"\(([^()]*)\)", inner)
        arr = np.array([[float(x) for x in v.split()] for v in vals])
    else:
        arr = np.array([float(x) for x in inner.split()])
    if len(arr) != n:
        raise ValueError("list size %d but %d entries" % (n, len(arr)))
    return arr


def read_field(path):
    """The values of a lagrangian IOField as a numpy array ((n,) or (n, 3))."""
    with open(path) as f:
        _, body = split_header(f.read())
    return _parse_body(body)


def _rewrite_list(path, lines):
    """Replace the body of an OpenFOAM file by the list lines (from its
    size to its closing ')'), keeping its header."""
    with open(path) as f:
        header, _ = split_header(f.read())
    with open(path, "w") as f:
        f.write(header + "\n".join(["", ""] + lines
                                   + ["", "", "// " + "*"*73 + " //", ""]))


def _vector_text(v):
    # 17 significant digits: the double read back is the one written
    return "(%.17g %.17g %.17g)" % tuple(v)


def write_vector_field(path, values):
    """Rewrite the list of a vector IOField, keeping its header."""
    values = np.atleast_2d(values)
    _rewrite_list(path, ["%d" % len(values), "("]
                  + [_vector_text(v) for v in values] + [")"])


# a nested list's tokens: a uniform list 'n{...}', a parenthesis, a word
_TOKEN = re.compile(r"\d+\s*\{[^}]*\}|\(|\)|[^\s()]+")


def _nested_list(tokens, k, item):
    """Parse 'n ( items )' or 'n{v}' from tokens[k]: (values, next k)."""
    t = tokens[k]
    if "{" in t:
        # OpenFOAM writes an empty list of a nested field as 0{}
        if int(t[:t.index("{")]) != 0:
            raise ValueError("a uniform nested list: %s" % t)
        return [], k + 1
    n = int(t)
    if tokens[k + 1] != "(":
        raise ValueError("expected '(' after %d" % n)
    k += 2
    out = []
    while tokens[k] != ")":
        v, k = item(tokens, k)
        out.append(v)
    if len(out) != n:
        raise ValueError("list size %d but %d entries" % (n, len(out)))
    return out, k + 1


def _label_item(tokens, k):
    return int(tokens[k]), k + 1


def _vector_item(tokens, k):
    if tokens[k] != "(" or tokens[k + 4] != ")":
        raise ValueError("expected a vector at token %d" % k)
    return tuple(float(x) for x in tokens[k + 1:k + 4]), k + 5


def read_nested_field(path, vectors=False):
    """The rows of an IOField<labelField> (vectors=False) or
    IOField<vectorField> (vectors=True): a list per parcel, of ints or of
    (x, y, z) tuples."""
    with open(path) as f:
        _, body = split_header(f.read())
    tokens = _TOKEN.findall(re.sub(r"//.*", "", body))
    item = _vector_item if vectors else _label_item
    rows, _ = _nested_list(tokens, 0, lambda t, k: _nested_list(t, k, item))
    return rows


def write_nested_field(path, rows, vectors=False):
    """Rewrite the rows of a nested IOField (read_nested_field's form),
    keeping its header."""
    text = _vector_text if vectors else str
    lines = [str(len(rows)), "("]
    for r in rows:
        if r:
            lines += ["%d" % len(r), "("] + [text(v) for v in r] + [")"]
        else:
            lines.append("0()")
    _rewrite_list(path, lines + [")"])


def read_internal_field(path):
    """The internalField of an ASCII volField (a gas field written by the
    solver, or the cell centres C of postProcess -func writeCellCentres) as
    a numpy array ((nCells,) or (nCells, 3)); None for a uniform field,
    which carries no cell count."""
    with open(path) as f:
        _, body = split_header(f.read())
    m = re.search(r"internalField\s+(uniform|nonuniform)", body)
    if not m:
        raise ValueError("%s: no internalField" % path)
    if m.group(1) == "uniform":
        return None
    rest = re.sub(r"^\s*List<\w+>", "", body[m.end():])
    return _parse_body(rest)


def cloud_dir(case, time, cloud="dpiCloud"):
    return os.path.join(case, time, "lagrangian", cloud)


def read_cloud(case, time, cloud="dpiCloud",
               fields=("xDEM", "U", "d", "typeId", "nParticle", "globalId",
                       "agglomerateId")):
    """Dictionary of the cloud's fields at a time, sorted by globalId."""
    d = cloud_dir(case, time, cloud)
    out = {name: read_field(os.path.join(d, name)) for name in fields}
    if "globalId" in out:
        order = np.argsort(out["globalId"])
        out = {k: v[order] for k, v in out.items()}
    return out


def times(case):
    """Written time directories of a case (numeric names, sorted, '0' too)."""
    ts = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, name)):
            ts.append((t, name))
    return [name for _, name in sorted(ts)]
