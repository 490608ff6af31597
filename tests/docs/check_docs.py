#!/usr/bin/env python3
"""Runs the command blocks of the docs that are marked runnable and compares what they
print with what the docs say, so that a change of output fails until the docs follow.

A runnable block is a fenced code block right after the line `<!-- doc-test -->`. In it,
a line starting with `$ ` is a command (run by bash in a scratch folder holding links to
the checkout's examples/ and schemes/, with `subdiv` on the PATH); the lines after it, up
to the next command, are what it prints (stdout and stderr together). `[exit N]` states a
non-zero exit code; `...` on a line of its own stands for any number of lines, and within a
line for any text (a list of names that grows). Before the
comparison, timings (`1.25 s`, `30 ms`), the scratch folder and the checkout's path are
masked and trailing spaces dropped.

    check_docs.py --subdiv build/tools/subdiv/subdiv --root . README.md docs/*.md
    check_docs.py --subdiv build/tools/subdiv/subdiv --root . --all   (and the README's
                                                     built-in schemes table against `subdiv schemes`)
    check_docs.py --self-test          (the checker's own test, on tests/docs/fixtures)
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

MARKER = "<!-- doc-test -->"
TIMING = re.compile(r"\b\d+(\.\d+)?(e[-+]?\d+)? ?(s|ms|us|µs|min)\b")
EXIT = re.compile(r"^\[exit (\d+)\]$")


def runnable_blocks(text):
    """(line number of the block, [lines]) for each block after the marker."""
    lines = text.splitlines()
    blocks, i = [], 0
    while i < len(lines):
        if lines[i].strip() == MARKER and i + 1 < len(lines) and lines[i + 1].startswith("```"):
            start, body, i = i + 2, [], i + 2
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            blocks.append((start, body))
        i += 1
    return blocks


def commands(block):
    """(command, expected lines, expected exit code) for each `$ ` line of a block."""
    out = []
    for line in block:
        if line.startswith("$ "):
            out.append([line[2:], [], 0])
        elif out:
            m = EXIT.match(line.strip())
            if m:
                out[-1][2] = int(m.group(1))
            elif line.strip() or out[-1][1]:
                out[-1][1].append(line)
    for c in out:
        while c[1] and not c[1][-1].strip():
            c[1].pop()
    return out


def masked(line, replacements):
    for path, name in replacements:
        line = line.replace(path, name)
    return TIMING.sub("<time>", line).rstrip()


def matches(expected, actual):
    """Line-by-line equality where an expected `...` line matches any run of lines."""
    if not expected:
        return not actual
    if expected[0] == "...":
        return any(matches(expected[1:], actual[k:]) for k in range(len(actual) + 1))
    return bool(actual) and same_line(expected[0], actual[0]) and matches(expected[1:], actual[1:])


def same_line(expected, actual):
    """Equal, where `...` inside an expected line stands for any text (a list that grows)."""
    if "..." not in expected:
        return expected == actual
    pattern = ".*".join(re.escape(part) for part in expected.split("..."))
    return re.fullmatch(pattern, actual) is not None


def scratch(root):
    folder = Path(tempfile.mkdtemp(prefix="subdivkit-docs-"))
    for name in ("examples", "schemes"):
        if (root / name).exists():
            (folder / name).symlink_to(root / name)
    return folder


def run(command, cwd, env):
    done = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=120)
    return done.returncode, done.stdout.splitlines()


def check_file(page, root, env, label=None):
    """The failures of one page, as messages."""
    failures = []
    folder = scratch(root)
    replacements = [(str(folder) + "/", ""), (str(folder), "."), (str(root) + "/", ""), (str(root), ".")]
    for start, block in runnable_blocks(page.read_text()):
        for command, expected, code in commands(block):
            got_code, got = run(command, folder, env)
            want = [masked(l, replacements) for l in expected]
            have = [masked(l, replacements) for l in got]
            if got_code != code or not matches(want, have):
                failures.append(f"{label or page}:{start}: `$ {command}` printed (exit {got_code}):\n"
                                + "\n".join("    " + l for l in have)
                                + f"\n  the docs say (exit {code}):\n" + "\n".join("    " + l for l in want))
    return failures


def scheme_table_failures(readme, env):
    """The README's built-in schemes table names every scheme `subdiv schemes` lists as
    built-in, and no other."""
    text = readme.read_text()
    start = text.find("## Built-in schemes")
    if start < 0:
        return [f"{readme}: no '## Built-in schemes' section"]
    end = text.find("\n## ", start + 1)
    table = set(re.findall(r"^\| `([a-z0-9-]+)` \|", text[start:end if end > 0 else None], re.M))
    listed = subprocess.run(["bash", "-c", "subdiv schemes"], env=env, capture_output=True, text=True).stdout
    built_in = set(re.findall(r"^  (\S+)\s+\[built-in\]", listed, re.M))
    failures = []
    if not built_in:
        failures.append("`subdiv schemes` lists no built-in scheme")
    if built_in - table:
        failures.append(f"{readme}: the built-in schemes table lacks {', '.join(sorted(built_in - table))}")
    if table - built_in:
        failures.append(f"{readme}: the built-in schemes table lists {', '.join(sorted(table - built_in))}, "
                        "which `subdiv schemes` does not")
    return failures


def environment(subdiv):
    env = dict(os.environ)
    if subdiv:
        env["PATH"] = str(Path(subdiv).resolve().parent) + os.pathsep + env.get("PATH", "")
    env["COLUMNS"] = "200"
    return env


def self_test(here):
    """The checker passes the fixture, and fails it when one output line or the exit code changes."""
    fixture = here / "fixtures" / "runnable.md"
    env = environment(None)
    problems = []
    if check_file(fixture, here, env):
        problems.append("the unchanged fixture fails: " + "\n".join(check_file(fixture, here, env)))
    text = fixture.read_text()
    with tempfile.TemporaryDirectory() as tmp:
        for what, changed in [("an output line", text.replace("\nsecond line\n", "\n2nd line\n")),
                              ("the exit code", text.replace("[exit 3]", "[exit 4]")),
                              ("a line too many", text.replace("first line\n", "first line\nextra line\n", 1))]:
            assert changed != text, what
            mutated = Path(tmp) / "mutated.md"
            mutated.write_text(changed)
            if not check_file(mutated, here, env):
                problems.append(f"a fixture with {what} changed passes")
    unmarked = len(runnable_blocks(text)), text.count("```") // 2
    if unmarked[0] >= unmarked[1]:
        problems.append("blocks without the marker were counted as runnable")
    for p in problems:
        print("self-test:", p)
    return 1 if problems else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pages", nargs="*", type=Path)
    parser.add_argument("--subdiv", help="the subdiv tool to put on the PATH")
    parser.add_argument("--root", type=Path, default=Path("."), help="the checkout (examples/, schemes/)")
    parser.add_argument("--self-test", action="store_true")
    parser.add_argument("--all", action="store_true", help="README.md and docs/*.md of --root")
    args = parser.parse_args()
    if args.self_test:
        return self_test(Path(__file__).resolve().parent)
    root, env = args.root.resolve(), environment(args.subdiv)
    if args.all:
        args.pages += [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    schemes_table = scheme_table_failures(root / "README.md", env) if args.all else []
    failures, blocks = [], 0
    for page in args.pages:
        blocks += len(runnable_blocks(page.read_text()))
        failures += check_file(page, root, env, label=os.path.relpath(page, root) if page.is_absolute() else None)
    failures += schemes_table
    for f in failures:
        print(f, end="\n\n")
    print(f"{len(args.pages)} pages, {blocks} runnable blocks, {len(failures)} differ from the program")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
