#!/usr/bin/env python3
"""Checks the sizes the house keeps to: no function over MAX_FUNCTION lines and no source file
over MAX_FILE lines, outside the tests (Testing/) and the generated data.

    check_sizes.py [REPO] [--function 200] [--file 900] [--list N]

Functions are found in the C++ sources by their braces (the code is clang-formatted in VTK's
style, so a function's body opens on a line of its own); a function's size counts the lines from
its opening brace to its closing one, lambdas inside it included. Exit 1 and one line per
offender when something is too long; --list N prints the N longest functions.
"""
import argparse
import os
import re
import subprocess
import sys

CONTROL = re.compile(r"^(if|for|while|switch|else|do|try|catch)\b")
TYPE = re.compile(r"^(template\s*<.*>\s*)?(struct|class|union|enum|namespace|extern)\b")
FUNCTION_END = re.compile(
    r"\)\s*(const)?\s*(noexcept)?\s*(override|final)?\s*(->\s*[\w:<>,\s*&]+)?\s*$")
LAMBDA = re.compile(r"\]\s*(\(.*\))?\s*(mutable)?\s*(->\s*[\w:<>,\s*&]+)?\s*$")
SOURCES = (".h", ".cxx", ".cpp", ".hpp", ".py", ".sh", ".cmake", ".txt", ".in", ".xml")


def strip(text):
    """The text with comments, string and character literals blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, lines) of every function defined outside another function."""
    lines = strip(open(path, encoding="utf-8", errors="replace").read()).split("\n")
    # preprocessor lines (with their continuations) hold no code we count
    code, continued = [], False
    for line in lines:
        directive = continued or line.lstrip().startswith("#")
        continued = directive and line.rstrip().endswith("\\")
        code.append("" if directive else line)
    found, stack, header, header_line = [], [], "", 0
    for number, line in enumerate(code, 1):
        for c in line:
            if c == "{":
                h = " ".join(header.split())
                if stack and stack[-1][0] == "function":
                    kind = "inner"
                elif CONTROL.match(h) or TYPE.match(h) or LAMBDA.search(h) or "=" in h.split("(")[0]:
                    kind = "other"
                elif FUNCTION_END.search(h) and "(" in h:
                    kind = "function"
                else:
                    kind = "other"
                name = h.split("(")[0].split()[-1] if kind == "function" and h.split("(")[0].split() else ""
                stack.append((kind, number, name))
                header = ""
            elif c == "}":
                if stack:
                    kind, start, name = stack.pop()
                    if kind == "function":
                        found.append((name, start, number - start + 1))
                header = ""
            elif c == ";":
                header = ""
            else:
                if not header.strip():
                    header_line = number
                header += c
        header += " "
    return found


def tracked(repo):
    try:
        names = subprocess.run(["git", "-C", repo, "ls-files"], capture_output=True, text=True,
                               check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        names = [os.path.relpath(os.path.join(d, f), repo) for d, _, fs in os.walk(repo) for f in fs]
    return [n for n in names if not n.startswith(("Testing/", "build")) and n.endswith(SOURCES)
            and not n.startswith("Data/") or n.startswith("Data/") and n.endswith(".cxx")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("repo", nargs="?", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--function", type=int, default=200)
    parser.add_argument("--file", type=int, default=900)
    parser.add_argument("--list", type=int, default=0)
    args = parser.parse_args()
    bad, every = [], []
    for name in tracked(args.repo):
        path = os.path.join(args.repo, name)
        if not os.path.isfile(path):
            continue
        count = sum(1 for _ in open(path, encoding="utf-8", errors="replace"))
        if count > args.file:
            bad.append("%s: %d lines (at most %d)" % (name, count, args.file))
        if name.endswith((".h", ".cxx", ".cpp", ".hpp")):
            for function, start, length in functions(path):
                every.append((length, name, start, function))
                if length > args.function:
                    bad.append("%s:%d: %s is %d lines (at most %d)" % (
                        name, start, function, length, args.function))
    for length, name, start, function in sorted(every, reverse=True)[:args.list]:
        print("%5d  %s:%d %s" % (length, name, start, function))
    for line in bad:
        print(line)
    print("check_sizes: %d functions in %d files; %s" % (
        len(every), len({e[1] for e in every}), "too long: %d" % len(bad) if bad else "all within bounds"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
