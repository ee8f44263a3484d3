#!/usr/bin/python3
"""The lengths of the functions in src/, against the project's limit (a function does one job,
under MAX_LINES lines).

A function's length is its lines from the one with its name to the one with its closing brace
(a `template <...>` line above it is not counted). Lambdas count to the function they are in.

  function_lengths.py [--top N]       the N longest functions (default 25)
  function_lengths.py --check         fails (exit 1) when a function over MAX_LINES is not in
                                      the exceptions file, or is longer than it says there, or
                                      when the file lists one that is gone or now short enough
  function_lengths.py --update        rewrites the exceptions file with today's lengths of the
                                      functions it lists that are still over MAX_LINES: it only
                                      removes and shortens, never adds

The exceptions file (tests/data/function-length-exceptions.txt) holds the functions that were
over the limit when the check came, one a line, `PATH NAME LENGTH`; it may only shrink. An entry
matches a function by its name (PATH says where it was last, --update refreshes it), so that a
function moved to another file keeps its entry.
"""

import argparse
import pathlib
import re
import sys

MAX_LINES = 80

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXCEPTIONS = ROOT / "tests" / "data" / "function-length-exceptions.txt"

CONTAINER = re.compile(r"\b(namespace|class|struct|union|enum)\b")
IDENTIFIER = re.compile(r"[A-Za-z_~][A-Za-z0-9_]*(?:\s*::\s*~?[A-Za-z_][A-Za-z0-9_]*)*$")
OPERATOR = re.compile(r"\boperator\s*(\(\)|\[\]|[^\s(]+)\s*$")


def blank_out(text):
    """The text with comments, string and character literals and preprocessor lines replaced by
    spaces, keeping every newline where it was, so that braces in them do not count."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":  # a preprocessor line, with its continuations
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        raw = re.match(r'R"([^(\s]*)\(', text[i:i + 20]) if c == "R" else None
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            close = ")" + raw.group(1) + '"'
            end = text.find(close, i + raw.end())
            end = n if end < 0 else end + len(close)
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        if c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator: 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (j + 1 - i))
            i = j + 1
            continue
        out.append(c)
        line_start = c == "\n" or (line_start and c in " \t")
        i += 1
    return "".join(out)


def without_templates(header):
    """The header without its `template <...>` parameter lists (they hold `class` and `=`)."""
    while True:
        m = re.search(r"\btemplate\s*<", header)
        if not m:
            return header
        depth, j = 1, m.end()
        while j < len(header) and depth:
            depth += {"<": 1, ">": -1}.get(header[j], 0)
            j += 1
        header = header[: m.start()] + " " + header[j:]


def function_name(header):
    """The name of the function whose definition `header` (the text before its body's brace)
    begins, or None when the brace opens something else (a class, an initialiser)."""
    header = re.sub(r"^\s*(public|private|protected)\s*:(?!:)", " ", without_templates(header))
    if not header.strip() or CONTAINER.search(header.split("(")[0]) or "extern" in header:
        return None
    depth = 0
    for j, c in enumerate(header):  # an `=` outside brackets: a variable's initialiser
        if c in "([<":
            depth += 1
        elif c in ")]>":
            depth -= 1
        elif c == "=" and depth == 0 and not re.search(r"operator\s*\S*$", header[:j]):
            return None
    before = header[: header.find("(")] if "(" in header else None
    if before is None:
        return None
    op = re.search(r"\boperator\s*$", before)
    if op:  # operator()(...): the first parentheses are the name's
        return "operator()"
    m = OPERATOR.search(before) or IDENTIFIER.search(before.rstrip())
    if not m:
        return None
    return re.sub(r"\s+", "", m.group(0))


def functions_in(path):
    """(name, first line, last line) of every function defined in the file."""
    text = blank_out(path.read_text())
    found = []
    # Scopes: ("container", class name or None), ("function", name, first line) or ("block",).
    scopes = []
    header_start = 0
    line = 1
    in_function = lambda: any(s[0] in ("function", "block") for s in scopes)
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        elif c == "{":
            if in_function():
                scopes.append(("block",))
            else:
                header = text[header_start:i]
                name = function_name(header)
                colon = re.search(r"\)[^()]*?(?<!:):(?!:)", header)
                if name and colon and re.search(r"[A-Za-z0-9_>]\s*$", header):
                    # a brace initialiser of a constructor's member: x_{a} in `) : x_{a} {`
                    scopes.append(("init",))
                    continue
                if name:
                    name_at = header.rfind(name.split("::")[-1].replace("operator()", "operator"))
                    first = line - header[name_at if name_at >= 0 else 0:].count("\n")
                    classes = [s[1] for s in scopes if s[0] == "container" and s[1]]
                    scopes.append(("function", "::".join(classes + [name]), first))
                elif CONTAINER.search(without_templates(header).split("(")[0]) or "extern" in header:
                    m = re.search(r"\b(?:class|struct|union)\s+([A-Za-z_][A-Za-z0-9_]*)", header)
                    scopes.append(("container", m.group(1) if m else None))
                else:
                    scopes.append(("block",))  # an initialiser: nothing in it is a function
            header_start = i + 1
        elif c == "}":
            scope = scopes.pop() if scopes else ("container", None)
            if scope[0] == "function":
                found.append((scope[1], scope[2], line))
            if scope[0] != "init":
                header_start = i + 1
        elif c == ";" and not in_function() and not (scopes and scopes[-1][0] == "init"):
            header_start = i + 1
    return found


def measure(root):
    """Every function in root/src: (path relative to root, name, length), longest first."""
    rows = []
    for path in sorted((root / "src").rglob("*")):
        if path.suffix in (".cpp", ".hpp", ".h", ".cc"):
            rel = path.relative_to(root).as_posix()
            rows += [(rel, name, last - first + 1) for name, first, last in functions_in(path)]
    return sorted(rows, key=lambda r: (-r[2], r[0], r[1]))


def read_exceptions(path):
    entries = []
    for number, text in enumerate(path.read_text().splitlines(), 1):
        text = text.split("#")[0].strip()
        if not text:
            continue
        parts = text.split()
        if len(parts) != 3 or not parts[2].isdigit():
            sys.exit(f"{path}:{number}: expected `PATH NAME LENGTH`, got `{text}`")
        entries.append((parts[0], parts[1], int(parts[2])))
    return entries


def pair_up(rows, entries):
    """Each function over the limit with its entry: (path, name, length now or None when it is gone
    or within the limit, length listed or None when not listed). Entries match by name, not by
    path, so that moving a function to another file keeps its entry; functions of one name pair
    with the entries of that name longest with longest."""
    over = [r for r in rows if r[2] > MAX_LINES]
    pairs = []
    for name in sorted({r[1] for r in over} | {e[1] for e in entries}):
        now = sorted((r for r in over if r[1] == name), key=lambda r: -r[2])
        listed = sorted((e for e in entries if e[1] == name), key=lambda e: -e[2])
        for k in range(max(len(now), len(listed))):
            path = now[k][0] if k < len(now) else listed[k][0]
            pairs.append((path, name, now[k][2] if k < len(now) else None,
                          listed[k][2] if k < len(listed) else None))
    return pairs


def write_exceptions(path, entries):
    head = [line for line in path.read_text().splitlines() if line.startswith("#")]
    body = [f"{p} {n} {length}" for p, n, length in sorted(entries, key=lambda e: (-e[2], e[0]))]
    path.write_text("\n".join(head + body) + "\n")


def check(rows, exceptions_path, update):
    pairs = pair_up(rows, read_exceptions(exceptions_path))
    failed = False
    for p, n, now, listed in pairs:
        if listed is None:
            print(f"{p}: {n} is {now} lines, over {MAX_LINES}: split it")
            failed = True
        elif now is not None and now > listed:
            print(f"{p}: {n} grew to {now} lines (listed at {listed} in {exceptions_path.name})")
            failed = True
    if update:  # only removes and shortens: what is not listed, or grew, fails as before
        kept = [(p, n, min(now, listed)) for p, n, now, listed in pairs if now and listed]
        write_exceptions(exceptions_path, kept)
        print(f"{exceptions_path}: {len(kept)} exceptions kept")
        return 1 if failed else 0
    for p, n, now, listed in pairs:
        if listed is not None and now is None:
            print(f"{exceptions_path.name}: remove `{p} {n} {listed}`: it is gone or within "
                  f"{MAX_LINES} lines now (scripts/function_lengths.py --update removes it)")
            failed = True
        elif listed is not None and now < listed:
            print(f"{exceptions_path.name}: `{p} {n} {listed}` can be lowered to {now}")
    over = sum(1 for r in rows if r[2] > MAX_LINES)
    listed = sum(1 for pair in pairs if pair[3] is not None)
    print(f"{len(rows)} functions in src/, {over} over {MAX_LINES} lines, {listed} listed as "
          f"exceptions: {'FAILED' if failed else 'ok'}")
    return 1 if failed else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=pathlib.Path, default=ROOT)
    parser.add_argument("--top", type=int, default=25)
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--update", action="store_true")
    parser.add_argument("--exceptions", type=pathlib.Path, default=None)
    args = parser.parse_args()
    rows = measure(args.root)
    if args.check or args.update:
        path = args.exceptions or args.root / EXCEPTIONS.relative_to(ROOT)
        return check(rows, path, args.update)
    for p, n, length in rows[: args.top]:
        print(f"{length:5d}  {p}  {n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
