"""Reads the /*TEST ... TEST*/ blocks of an example source (PETSc style).

    /*TEST
      args: -physics dem ...      shared by every test (continuation lines are indented further)
      rtol: 1e-8                  shared tolerance (atol likewise)
      test:
        suffix: 1
        nsize: 1
        args: -more               appended to the shared args
        output_file: output/ex01_name_1.out   (default: output/<example>_<suffix>.out)
        requires: hdf5            features that must be present; otherwise the test is skipped
        timeout: 300
    TEST*/
"""
import os
import re

KEYS = {"suffix", "nsize", "args", "output_file", "requires", "rtol", "atol", "timeout"}


class Test:
    def __init__(self, example, source, fields):
        self.example = example
        self.source = source
        self.suffix = fields.get("suffix", "0")
        self.nsize = int(fields.get("nsize", "1"))
        self.args = fields.get("args", "").split()
        self.output_file = fields.get("output_file", "output/%s_%s.out" % (example, self.suffix))
        self.requires = fields.get("requires", "").split()
        self.rtol = float(fields.get("rtol", "1e-8"))
        self.atol = float(fields.get("atol", "1e-12"))
        self.timeout = int(fields.get("timeout", "600"))

    @property
    def name(self):
        return "%s_%s" % (self.example, self.suffix)


def _parse_fields(lines, where):
    fields, last = {}, None
    for indent, text, lineno in lines:
        m = re.match(r"([a-z_]+):\s*(.*)$", text)
        if m and m.group(1) in KEYS:
            last = m.group(1)
            fields[last] = m.group(2).strip()
        elif m:
            raise ValueError("%s:%d: unknown TEST key '%s'" % (where, lineno, m.group(1)))
        elif last == "args":
            fields["args"] += " " + text.strip()
        else:
            raise ValueError("%s:%d: cannot read '%s'" % (where, lineno, text.strip()))
    return fields


def parse(path):
    """Returns the list of Test objects of one example file."""
    with open(path) as f:
        src = f.read()
    m = re.search(r"/\*TEST\n(.*?)TEST\*/", src, re.S)
    if not m:
        return []
    first_line = src[: m.start()].count("\n") + 2
    example = os.path.splitext(os.path.basename(path))[0]
    shared, blocks, current = [], [], None
    for i, raw in enumerate(m.group(1).splitlines()):
        if not raw.strip() or raw.strip().startswith("#"):
            continue
        indent = len(raw) - len(raw.lstrip())
        text = raw.strip()
        if text == "test:":
            current = (indent, [])
            blocks.append(current)
        elif current is not None and indent > current[0]:
            current[1].append((indent, text, first_line + i))
        else:
            current = None
            shared.append((indent, text, first_line + i))
    base = _parse_fields(shared, path)
    tests = []
    for _, lines in blocks or [(0, [])]:
        fields = dict(base)
        own = _parse_fields(lines, path)
        if "args" in own and "args" in base:
            own["args"] = base["args"] + " " + own["args"]
        fields.update(own)
        tests.append(Test(example, path, fields))
    names = [t.name for t in tests]
    if len(set(names)) != len(names):
        raise ValueError("%s: duplicate test suffixes %s" % (path, names))
    return tests
