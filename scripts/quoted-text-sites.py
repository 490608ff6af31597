#!/usr/bin/env python3
"""Messages that quote user text by hand: a fmt::format or fmt::print whose format string
puts an argument between quotes ('{}' or \\"{}\\") instead of passing it through quoted()
(framework/util/quoted_text.h), which escapes control bytes, a NUL and invalid UTF-8 in the
message text itself.

    scripts/quoted-text-sites.py DIR...            list the sites (file:line: argument)
    scripts/quoted-text-sites.py --fix DIR...      rewrite them: '{}' -> {} and X -> quoted(X)
    scripts/quoted-text-sites.py --check DIR...    exit 1 when any site is left (ctest)

Text quoted outside fmt (\"'\" + name + \"'\") is listed too, for fixing by hand.
"""
import re
import sys
from pathlib import Path

# quoted() qualified: std::quoted (<iomanip>) would be found by ADL for a std::string argument.
QUALIFIED = {"quoted": "subdiv::quoted", "escaped": "escaped"}
CALL = re.compile(r"\bfmt::(format|print)\(")
QUOTES = {"'": "'", '\\"': '\\"'}


def skip_literal(text, i):
    """Index after the string or char literal starting at text[i]."""
    if text.startswith('R"', i):
        m = re.match(r'R"([^(]*)\(', text[i:])
        end = text.index(")" + m.group(1) + '"', i + m.end())
        return end + len(m.group(1)) + 2
    quote = text[i]
    i += 1
    while text[i] != quote:
        i += 2 if text[i] == "\\" else 1
    return i + 1


def split_arguments(text, start):
    """The arguments of the call whose '(' is at text[start - 1]: [(begin, end)], and the
    index after the closing ')'."""
    args, depth, i, begin = [], 0, start, start
    while True:
        c = text[i]
        if c in "\"'" or text.startswith('R"', i):
            if c == "'" and i > 0 and (text[i - 1].isalnum()):  # digit separator 1'000
                i += 1
                continue
            i = skip_literal(text, i)
            continue
        if text.startswith("//", i):
            i = text.index("\n", i)
            continue
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                args.append((begin, i))
                return args, i + 1
            depth -= 1
        elif c == "," and depth == 0:
            args.append((begin, i))
            begin = i + 1
        i += 1


def literal_pieces(text, begin, end):
    """The plain string literals (begin, end) making up the argument text[begin:end], or None
    when it is not only adjacent literals."""
    pieces, i = [], begin
    while i < end:
        if text[i].isspace():
            i += 1
        elif text.startswith("//", i):
            i = text.index("\n", i)
        elif text[i] == '"':
            j = skip_literal(text, i)
            pieces.append((i + 1, j - 1))
            i = j
        else:
            return None
    return pieces


def fields(text, pieces):
    """Replacement fields of the format string: (start, end) of each '{...}' in the source,
    in argument order (automatic numbering), with the quote around it if any:
    [(open_quote_start, field_start, field_end, close_quote_end or None)]."""
    out = []
    for (b, e) in pieces:
        i = b
        while i < e:
            if text.startswith("{{", i) or text.startswith("}}", i):
                i += 2
                continue
            if text[i] == "{":
                j = text.index("}", i) + 1
                quote = None
                for q in QUOTES:
                    if text[i - len(q):i] == q and text[j:j + len(q)] == q and i - len(q) >= b:
                        quote = q
                out.append((i, j, quote))
                i = j
                continue
            i += 2 if text[i] == "\\" else 1
    return out


def sites(text):
    """[(call start, format fields, argument spans)] for every call quoting an argument."""
    found = []
    for m in CALL.finditer(text):
        args, _ = split_arguments(text, m.end())
        first = 0
        pieces = literal_pieces(text, *args[0])
        if pieces is None and len(args) > 1:  # fmt::print(stderr, "...")
            first, pieces = 1, literal_pieces(text, *args[1])
        if not pieces:
            continue
        fs = fields(text, pieces)
        quoted_fields = [(k, f) for k, f in enumerate(fs) if f[2]]
        if quoted_fields:
            found.append((m.start(), quoted_fields, args[first + 1:]))
    return found


def wrap(arg, helper="quoted"):
    stripped = arg.strip()
    lead = arg[: len(arg) - len(arg.lstrip())]
    m = re.fullmatch(r"(?:subdiv::)?(escaped|quoted)\((.*)\)", stripped, re.S)
    if m and split_ok(m.group(2)):
        if m.group(1) == helper:
            return arg
        stripped = m.group(2)
    m = re.fullmatch(r'fmt::format\("\{\}", (.*)\)', stripped, re.S)
    if m and split_ok(m.group(1)):
        stripped = m.group(1)
    return f"{lead}{QUALIFIED[helper]}({stripped})"


def split_ok(inner):
    depth = 0
    for c in inner:
        depth += c == "("
        depth -= c == ")"
        if depth < 0:
            return False
    return depth == 0


def fix(text):
    edits = []  # (start, end, replacement), applied from the end
    for _, quoted_fields, args in sites(text):
        for k, (fb, fe, q) in quoted_fields:
            if k >= len(args):
                continue
            ab, ae = args[k]
            if q == "'":  # 'X' -> quoted(X), which adds the quotes
                edits.append((fb - len(q), fb, ""))
                edits.append((fe, fe + len(q), ""))
                edits.append((ab, ae, wrap(text[ab:ae])))
            else:  # "X" (JSON keys and strings) keeps its quotes: escaped(X)
                edits.append((fb, fb, ""))
                edits.append((fe, fe, ""))
                edits.append((ab, ae, wrap(text[ab:ae], "escaped")))
    for b, e, r in sorted(set(edits), reverse=True):
        text = text[:b] + r + text[e:]
    return text, len(edits) // 3


def add_include(text, path):
    include = '#include "framework/util/quoted_text.h"'
    if include in text or "quoted_text.h" in path.name:
        return text
    lines = text.split("\n")
    last = max((i for i, l in enumerate(lines) if l.startswith('#include "')), default=None)
    if last is None:
        last = max(i for i, l in enumerate(lines) if l.startswith("#include"))
    lines.insert(last + 1, include)
    return "\n".join(lines)


CONCAT = re.compile(r"\"[^\"\n]*'\"\s*\+|\+\s*\"'[^\"\n]*\"")


def main():
    mode = sys.argv[1] if sys.argv[1].startswith("--") else "--list"
    dirs = [a for a in sys.argv[1:] if not a.startswith("--")]
    total = 0
    for d in dirs:
        for path in sorted(p for p in Path(d).rglob("*") if p.suffix in (".cpp", ".h", ".cxx")):
            text = path.read_text()
            if mode == "--fix":
                new, n = fix(text)
                if n:
                    path.write_text(add_include(new, path))
                    total += n
                continue
            for start, quoted_fields, args in sites(text):
                line = text.count("\n", 0, start) + 1
                for k, (_, _, q) in quoted_fields:
                    arg = text[slice(*args[k])].strip() if k < len(args) else "?"
                    if q == '\\"' and re.match(r"(?:subdiv::)?(escaped|quoted)\(", arg):
                        continue  # a JSON string: escaped inside its own quotes
                    print(f"{path}:{line}: {' '.join(arg.split())}")
                    total += 1
            if path.name.startswith("quoted_text"):
                continue  # the helper itself
            for m in CONCAT.finditer(text):
                print(f"{path}:{text.count(chr(10), 0, m.start()) + 1}: quoted by concatenation")
                total += 1
    print(f"{total} site(s)" + (" fixed" if mode == "--fix" else ""), file=sys.stderr)
    return 1 if mode == "--check" and total else 0


if __name__ == "__main__":
    sys.exit(main())
