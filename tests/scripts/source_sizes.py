#!/usr/bin/env python3
"""Sizes of the sources against the house limits (DEVELOPERS.md, issue 38).

A source file (.cc) may have at most 800 lines, a header (.h) 400, and a
function body at most 100 lines (from the line of its opening brace to the
line of its closing one, as clang-tidy's readability-function-size counts).
Offenders listed in the allow-list may stay while they do not grow; an entry
that no longer offends must be removed, so that the list only shrinks.

    source_sizes.py ROOT [ALLOW_LIST]    check (exit status 1 on a violation)
    source_sizes.py ROOT --list          print every offender in list format
    source_sizes.py ROOT --top N         the N longest functions

Functions are found with a brace scanner over the code without comments and
literals: a block at namespace or class scope whose opening brace follows a
parameter list (and qualifiers such as const, override or a constructor's
initializer list) is a function; lambdas and blocks inside a function belong
to it.
"""
import os
import re
import sys

LIMITS = {".cc": 800, ".h": 400}
FUNCTION_LIMIT = 100


def strip_code(text):
    """The text with comments, string and character literals blanked, the
    line structure kept."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i)
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isdigit():
                out.append(" ")  # digit separator 1'000
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(re.sub(r"[^\n]", " ", text[i:j + 1]))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


QUALIFIER = re.compile(
    r"\)\s*(const|override|final|noexcept(\s*\([^()]*\))?|mutable|&|&&|\s)*"
    r"(->\s*[\w:<>,\s*&]+)?\s*$")


def is_function_head(head):
    """Whether the text before an opening brace at namespace or class scope
    is a function's signature."""
    head = re.sub(r"\s+", " ", head).strip()
    if not head or "(" not in head:
        return False
    if re.match(r"^(template\s*<.*>\s*)?(class|struct|union|enum|namespace)\b", head):
        return False
    if QUALIFIER.search(head):
        return "=" not in head.split("(")[0] or "operator" in head
    # a constructor's initializer list: ") : member(value), other(value)"
    return bool(re.search(r"\)\s*:\s*[\w:]+\s*[({]", head)) and head.rstrip().endswith(")")


def function_name(head):
    head = re.sub(r"\s+", " ", head)
    m = re.search(r"([\w:~]+(?:<[^<>()]*>)?(?:::[\w~]+)?|operator\s*\S+)\s*\(", head)
    return m.group(1) if m else "?"


def functions(text):
    """(name, first line, number of lines) of every function body."""
    code = strip_code(text)
    result = []
    stack = []  # kinds of the open blocks: 'scope', 'function', 'other'
    head_start = 0
    line = 1
    open_at = []
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            head = code[head_start:i]
            inside_function = "function" in stack
            if inside_function:
                kind = "other"
            elif re.search(r"\b(namespace|class|struct|union|enum)\b[^()]*$", re.sub(r"\s+", " ", head)):
                kind = "scope"
            elif is_function_head(head):
                kind = "function"
            else:
                kind = "other"
            stack.append(kind)
            open_at.append((line, head))
            head_start = i + 1
        elif c == "}":
            if stack:
                kind = stack.pop()
                start, head = open_at.pop()
                if kind == "function":
                    result.append((function_name(head), start, line - start + 1))
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
    return result


def offenders(root):
    found = {}
    for folder in ("include", "source"):
        for dirpath, _, files in os.walk(os.path.join(root, folder)):
            for f in sorted(files):
                ext = os.path.splitext(f)[1]
                if ext not in LIMITS:
                    continue
                path = os.path.join(dirpath, f)
                rel = os.path.relpath(path, root)
                text = open(path, encoding="utf-8", errors="replace").read()
                n_lines = text.count("\n")
                if n_lines > LIMITS[ext]:
                    found["file %s" % rel] = n_lines
                for name, start, length in functions(text):
                    if length > FUNCTION_LIMIT:
                        key = "function %s %s" % (rel, name)
                        found[key] = max(found.get(key, 0), length)
    return found


def all_functions(root):
    out = []
    for folder in ("include", "source"):
        for dirpath, _, files in os.walk(os.path.join(root, folder)):
            for f in files:
                if os.path.splitext(f)[1] in LIMITS:
                    path = os.path.join(dirpath, f)
                    text = open(path, encoding="utf-8", errors="replace").read()
                    for name, start, length in functions(text):
                        out.append((length, "%s:%d %s" % (os.path.relpath(path, root), start, name)))
    return sorted(out, reverse=True)


def read_allow_list(path):
    allowed = {}
    if not path or not os.path.exists(path):
        return allowed
    for raw in open(path):
        entry = raw.split("#")[0].strip()
        if entry:
            key, _, size = entry.rpartition(" ")
            allowed[key] = int(size)
    return allowed


def main(argv):
    root = argv[1]
    if len(argv) > 2 and argv[2] == "--list":
        for key, size in sorted(offenders(root).items()):
            print("%s %d" % (key, size))
        return 0
    if len(argv) > 3 and argv[2] == "--top":
        for length, where in all_functions(root)[:int(argv[3])]:
            print("%5d  %s" % (length, where))
        return 0
    allowed = read_allow_list(argv[2] if len(argv) > 2 else None)
    found = offenders(root)
    errors = []
    for key, size in sorted(found.items()):
        limit = FUNCTION_LIMIT if key.startswith("function") else LIMITS[os.path.splitext(key.split()[1])[1]]
        if key not in allowed:
            errors.append("%s: %d lines, the limit is %d" % (key, size, limit))
        elif size > allowed[key]:
            errors.append("%s: %d lines, grown beyond the %d the allow-list keeps" % (key, size, allowed[key]))
    for key in sorted(set(allowed) - set(found)):
        errors.append("%s: within the limit now; remove it from the allow-list" % key)
    for e in errors:
        print(e)
    print("%d offenders, %d on the allow-list: %s" % (len(found), len(allowed), "size check failed" if errors else "size check passed"))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
