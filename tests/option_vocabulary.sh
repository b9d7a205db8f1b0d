#!/usr/bin/env bash
# One vocabulary per option (issue 26, item 2): every name of a library enum lives in one table in
# lib/ (core/vocabulary.h's NamedValue rows, `{Enum::Value, "name"}`); the CLI and Python parse
# through that table (parse_X, X_names()). This test fails when code outside lib/shadetool (cli/,
# lib/python/) parses one of those names itself: compares text with a vocabulary name (== "name",
# "name" ==, != ...), lists names for CLI11 (IsMember({..."name"...})), or maps a name to an enum
# value ({"name", Enum::Value}). Defaults and help text may still spell a name; comments and
# Python docstrings are not read. The Python stub's Literal[...] types must each list one enum's
# names exactly (a name added to a table and not to the stub fails here).
# The detector checks itself first on planted lines (it must flag each second parser and pass the
# spellings that are not parsers), so a pattern that silently stops matching fails the test.
set -uo pipefail
src=$2
python3 - "$src" <<'PY'
import pathlib, re, sys

src = pathlib.Path(sys.argv[1])
ROW = re.compile(r'\{\s*(\w+)::(\w+)\s*,\s*"([^"]+)"\s*\}')

# 1. The vocabularies: every NamedValue table row in lib/shadetool.
vocab = {}  # name -> set of enums
for path in sorted((src / "lib" / "shadetool").rglob("*")):
    if path.suffix not in (".h", ".cpp"):
        continue
    text = path.read_text(errors="replace")
    for table in re.finditer(r'NamedValue<(\w+)>\s+\w+\[\]\s*=\s*\{(.*?)\};', text, re.S):
        for enum, _value, name in ROW.findall(table.group(2)):
            vocab.setdefault(name, set()).add(enum)
enums = set().union(*vocab.values()) if vocab else set()
expected = {"ShadingModel", "ShadingSpace", "ShadingFrequency", "RenderShading", "Weighting", "Precision",
            "NormalsPolicy", "ValuePrecision"}
missing = expected - enums
if missing:
    print("FAIL: no vocabulary table found in lib/shadetool for: " + ", ".join(sorted(missing)))
    sys.exit(1)

def strip(text):
    """The code without comments and raw-string docstrings (line numbers kept)."""
    text = re.sub(r'R"(\w*)\((.*?)\)\1"', lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r'/\*.*?\*/', lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r'//[^\n]*', '', text)

def second_parsers(text):
    """(line, name, how) for every place the code parses a vocabulary name itself."""
    code = strip(text)
    hits = []
    def add(pos, name, how):
        hits.append((code.count("\n", 0, pos) + 1, name, how))
    for m in re.finditer(r'(?:[=!]=\s*"([^"\n]+)")|(?:"([^"\n]+)"\s*[=!]=)', code):
        name = m.group(1) or m.group(2)
        if name in vocab: add(m.start(), name, "compared with text")
    for m in re.finditer(r'(?:compare|strcmp|starts_with|rfind)\s*\([^()\n]*"([^"\n]+)"', code):
        if m.group(1) in vocab: add(m.start(), m.group(1), "compared with text")
    for m in re.finditer(r'IsMember\s*\(\s*\{([^}]*)\}', code):
        for name in re.findall(r'"([^"\n]+)"', m.group(1)):
            if name in vocab: add(m.start(), name, "a hand-written CLI11 list")
    for m in re.finditer(r'"([^"\n]+)"\s*,\s*(?:shadetool::)?(\w+)::\w+', code):
        if m.group(1) in vocab and m.group(2) in vocab[m.group(1)]: add(m.start(), m.group(1), "mapped to an enum value")
    return hits

# 2. The detector on planted lines: each second parser flagged, each plain spelling not.
planted_bad = [
    'if (s == "lambert") return shadetool::ShadingModel::Lambert;',
    'x = "face" != opt.per;',
    '->check(CLI::IsMember({"flat", "gouraud"}));',
    '{"area", shadetool::Weighting::Area},',
    'if (s.compare("world") == 0) {}',
]
planted_ok = [
    'std::string shading = "phong";  // == "phong" in a comment',
    'py::arg("per") = "vertex",',
    'R"doc(space "auto" == "world")doc"',
    '->check(CLI::IsMember(shadetool::render_shading_names()));',
]
for line in planted_bad:
    if not second_parsers(line):
        print("FAIL: the detector misses a second parser: " + line); sys.exit(1)
for line in planted_ok:
    if second_parsers(line):
        print("FAIL: the detector flags a line that parses nothing: " + line); sys.exit(1)

# 3. Outside lib/shadetool: the CLI and the Python module.
found = []
for folder in (src / "cli", src / "lib" / "python"):
    for path in sorted(folder.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        for line, name, how in second_parsers(path.read_text(errors="replace")):
            found.append(f"{path.relative_to(src)}:{line}: '{name}' ({'/'.join(sorted(vocab[name]))}) {how}")
# 4. The Python stub (lib/python/shadetool.pyi) spells the vocabularies as Literal[...] types: each
# that names a vocabulary name must list exactly one enum's names (in step with the table).
by_enum = {}
for name, owners in vocab.items():
    for e in owners:
        by_enum.setdefault(e, set()).add(name)

def stale_literals(text):
    bad = []
    for m in re.finditer(r'Literal\[([^\]]*)\]', text):
        names = re.findall(r'"([^"]+)"', m.group(1))
        if any(n in vocab for n in names) and not any(set(names) == v for v in by_enum.values()):
            bad.append((text.count("\n", 0, m.start()) + 1, ", ".join(names)))
    return bad

if not stale_literals('x: Literal["flat", "phong"]') or stale_literals('x: Literal["flat", "gouraud", "phong"]'):
    print("FAIL: the stub check misjudges a planted Literal"); sys.exit(1)
stub = src / "lib" / "python" / "shadetool.pyi"
for line, names in stale_literals(stub.read_text()):
    found.append(f"{stub.relative_to(src)}:{line}: Literal[{names}] is not the full vocabulary of one enum")

for f in found:
    print("FAIL: " + f)
print(f"{len(vocab)} names of {len(enums)} enums; {len(found)} second parsers or stale stub types outside lib/shadetool")
if found:
    print("parse with the library's parse_X(text, what), list with X_names() (lib/shadetool/core/vocabulary.h), and keep shadetool.pyi's Literal types in step")
    sys.exit(1)
PY
