#!/usr/bin/env python3
"""Checks the project's rule that no function is longer than 150 lines.

Usage: check_function_length.py [--max N] [--list] [--allow FILE] DIR_OR_FILE...

A function's length is counted from the line of its opening brace to the
line of its closing brace, both included (lambdas and local classes count
towards the function around them). Comments, string literals and
preprocessor lines are masked first, so braces in them do not count. The
scan is lexical, not a C++ parser: a brace block at namespace or class
scope is a function body when the text before it ends with a parameter
list (with qualifiers, a trailing return type or a constructor's member
initializers). Exit status 1 when a function is longer than the maximum.

--allow FILE names functions that may stay longer for now, one a line:
`PATH FIRST-LINE-OF-ITS-HEAD-TEXT # reason` is too brittle, so a line is
`PATH NAME reason...`, where NAME is the function's name as written before
its parameter list (Class::name or name). Each entry must still match a
long function: an entry that matches none fails the check, so the list
only shrinks.
"""
import argparse
import os
import re
import sys

SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc", ".inc")


def mask(text):
    """Blanks comments, string and character literals, keeping newlines."""
    out = []
    i, n = 0, len(text)

    def blank(segment):
        return "".join(ch if ch == "\n" else " " for ch in segment)

    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(blank(text[i:j]))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(blank(text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = ")" + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            out.append(blank(text[i:j]))
            i = j
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum() and text[i + 1:i + 2].isalnum())):
            # A ' between two alphanumerics is a digit separator (1'000).
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(blank(text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    masked = "".join(out)
    # Preprocessor lines (with continuations) hold no function bodies.
    return re.sub(r"(?m)^[ \t]*#.*(?:\\\n.*)*$", lambda m: blank(m.group(0)), masked)


# Text before a '{' that makes the block a function body: a parameter list,
# then qualifiers, a trailing return type, or member initializers.
FUNCTION_HEAD = re.compile(
    r"\)\s*(?:const|volatile|noexcept(?:\s*\([^()]*\))?|override|final|mutable|&&?|"
    r"->\s*[\w:<>,\s\*&]+|\s)*$")
INITIALIZER_HEAD = re.compile(r"\)\s*:\s*[^;{}]*$")
TYPE_HEAD = re.compile(r"\b(?:namespace|class|struct|enum|union)\b[^;{}()]*$")


NAME_BEFORE_PARAMS = re.compile(r"([\w:~]+)\s*\($")


def function_name(masked, brace):
    """The name before the parameter list that ends before `brace`."""
    depth = 0
    i = brace - 1
    while i >= 0:
        c = masked[i]
        if c == ")":
            depth += 1
        elif c == "(":
            depth -= 1
            if depth == 0:
                m = NAME_BEFORE_PARAMS.search(masked[max(0, i - 200):i + 1])
                if m:
                    return m.group(1)
                # A member initializer list: keep looking further back.
        elif depth == 0 and c in ";}":
            break
        i -= 1
    return "?"


def functions(text):
    """Yields (first line, last line, name) of each function body."""
    masked = mask(text)
    stack = []  # (is_function, line, name)
    line = 1
    for i, c in enumerate(masked):
        if c == "\n":
            line += 1
        elif c == "{":
            is_function = False
            if not any(f for f, _, _ in stack):
                head = re.sub(r"\s+", " ", masked[max(0, i - 600):i]).rstrip()
                if (FUNCTION_HEAD.search(head) or INITIALIZER_HEAD.search(head)) and not TYPE_HEAD.search(head):
                    is_function = True
            stack.append((is_function, line, function_name(masked, i) if is_function else ""))
        elif c == "}" and stack:
            is_function, first, name = stack.pop()
            if is_function:
                yield first, line, name


def source_files(paths):
    for path in paths:
        if os.path.isfile(path):
            yield path
            continue
        for root, _, names in os.walk(path):
            for name in sorted(names):
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.join(root, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max", type=int, default=150)
    parser.add_argument("--list", action="store_true", help="print every function's length")
    parser.add_argument("--allow", help="allow-list file (see above)")
    parser.add_argument("paths", nargs="+")
    args = parser.parse_args()
    allowed = {}  # (path suffix, name) -> used
    if args.allow:
        with open(args.allow, encoding="utf-8") as f:
            for line in f:
                fields = line.split()
                if fields and not fields[0].startswith("#"):
                    if len(fields) < 3:
                        print(f"{args.allow}: an entry needs a path, a name and a reason: {line.strip()}")
                        return 1
                    allowed[(fields[0], fields[1])] = False
    too_long = 0
    for path in sorted(source_files(args.paths)):
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        for first, last, name in functions(text):
            length = last - first + 1
            if args.list:
                print(f"{path}:{first}: {length} {name}")
            if length <= args.max:
                continue
            key = next((k for k in allowed if path.endswith("/" + k[0]) and k[1] == name), None)
            if key:
                allowed[key] = True
                print(f"{path}:{first}: {name}: {length} lines, allowed for now ({args.allow})")
                continue
            too_long += 1
            print(f"{path}:{first}: {name}: function body of {length} lines (at most {args.max})")
    stale = [k for k, used in allowed.items() if not used]
    for path, name in stale:
        print(f"{args.allow}: {path} {name} is no longer over {args.max} lines: remove its entry")
    if too_long:
        print(f"{too_long} function(s) longer than {args.max} lines", file=sys.stderr)
    return 1 if too_long or stale else 0


if __name__ == "__main__":
    sys.exit(main())
