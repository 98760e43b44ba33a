#!/usr/bin/env python3
"""Fails when a function in the given source folders is longer than the limit (60 lines).

Usage: check_function_length.py --root REPO [--max 60] [--exclude GLOB ...] [--verbose] FOLDER ...

Scans every .cpp file under REPO/FOLDER (a folder that does not exist is skipped, so a layer may be
checked before it is created). A function is a body at namespace scope: a free function, a member
function defined out of its class (`Foo::bar(...) {`), a constructor with its initializer list, or a
lambda assigned to a namespace-scope variable. Lambdas and local classes inside a function count
towards it. Member functions defined inside a class body are not scanned.

A function's length is the number of lines from the first line of its definition (return type,
qualifiers, name) to its closing brace, both included.

Layout builders are allowed to be longer: their job is to create widgets and lay them out, which
reads best in one place. They are recognised by name only (LAYOUT_BUILDER below): build<Something>,
make<Something>Layout, layOut<Something>.

--exclude GLOB (matched against the path relative to REPO, fnmatch rules, `*` crosses folders) lists
files still being rewritten: their long functions are printed as notes and do not fail the check.

Prints file:line, name and length of each offender; exits 1 when one is outside the excluded files.
"""
import argparse
import fnmatch
import os
import re
import sys

LAYOUT_BUILDER = re.compile(r"^(build[A-Z]\w*|make\w*Layout|layOut[A-Z]\w*)$")
IDENT = re.compile(r"[A-Za-z_]\w*")
MACRO_CALL = re.compile(r"\s*[A-Z][A-Z0-9_]*[A-Z0-9]\s*\(")
QUALIFIED_NAME = re.compile(
    r"((?:~?[A-Za-z_]\w*(?:\s*<[^<>()]*>)?\s*::\s*)*(?:operator\s*(?:\(\s*\)|[^\s\w(]+|\s[\w:<>* &]+)|~?[A-Za-z_]\w*))\s*$")
TYPE_KEYWORDS = {"class", "struct", "union", "enum"}


def blank(text):
    """The source with comments, string and character literals and preprocessor lines replaced by
    spaces (newlines kept, so offsets map to the same lines)."""
    out = list(text)
    i, n = 0, len(text)
    at_line_start = True

    def wipe(a, b):
        for k in range(a, b):
            if out[k] != "\n":
                out[k] = " "

    while i < n:
        c = text[i]
        if c == "\n":
            at_line_start = True
            i += 1
            continue
        if at_line_start and c in " \t":
            i += 1
            continue
        if at_line_start and c == "#":  # a preprocessor line, with its continuations
            j = i
            while j < n and not (text[j] == "\n" and text[j - 1] != "\\"):
                j += 1
            wipe(i, j)
            i = j
            continue
        at_line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            wipe(i, j)
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            wipe(i, j)
            i = j
        elif c == '"':
            raw = re.search(r"(?:u8|u|U|L)?R$", text[max(0, i - 3):i])
            if raw and (i - len(raw.group(0)) == 0 or not (text[i - len(raw.group(0)) - 1].isalnum()
                                                            or text[i - len(raw.group(0)) - 1] == "_")):
                delim_end = text.find("(", i)
                closing = ")" + text[i + 1:delim_end] + '"'
                j = text.find(closing, delim_end)
                j = n if j < 0 else j + len(closing)
            else:
                j = i + 1
                while j < n and text[j] != '"':
                    j += 2 if text[j] == "\\" else 1
                j += 1
            wipe(i + 1, j - 1)
            i = j
        elif c == "'":
            k = i
            while k > 0 and (text[k - 1].isalnum() or text[k - 1] in "_."):
                k -= 1
            if k < i and text[k].isdigit():  # a digit separator (1'000'000)
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != "'":
                j += 2 if text[j] == "\\" else 1
            j += 1
            wipe(i + 1, j - 1)
            i = j
        else:
            i += 1
    return "".join(out)


def matching(text, i):
    """Index of the bracket closing the one at i ((, [, { or <-free))."""
    pairs = {"(": ")", "[": "]", "{": "}"}
    stack = [pairs[text[i]]]
    j = i + 1
    while j < len(text) and stack:
        c = text[j]
        if c in pairs:
            stack.append(pairs[c])
        elif c in ")]}":
            if c == stack[-1]:
                stack.pop()
            else:  # unbalanced source: stop at the end of this bracket kind
                stack.pop()
        j += 1
    return j - 1


def strip_macro_calls(head):
    """The head without leading MACRO(...) calls (Q_LOGGING_CATEGORY(...) has no semicolon)."""
    offset = 0
    while True:
        m = MACRO_CALL.match(head, offset)
        if not m:
            return head[offset:], offset
        close = matching(head, m.end() - 1)
        offset = close + 1


def depth0(head):
    """Yields (index, char) of the head outside (), [], {} and <>."""
    depth = angle = 0
    for k, c in enumerate(head):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif depth == 0 and c == "<":
            angle += 1
        elif depth == 0 and c == ">" and angle > 0 and head[k - 1] != "-":
            angle -= 1
        elif depth == 0 and angle == 0:
            yield k, c


def first_paren(head):
    """Index of the first ( at depth 0 (the parameter list), skipping `operator()`'s own."""
    depth = angle = 0
    k = 0
    while k < len(head):
        c = head[k]
        if c == "(" and depth == 0:
            if re.search(r"\boperator\s*$", head[:k]) and re.match(r"\(\s*\)", head[k:]):
                k = head.index(")", k) + 1
                continue
            return k
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif depth == 0 and c == "<":
            angle += 1
        elif depth == 0 and c == ">" and angle > 0:
            angle -= 1
        k += 1
    return -1


def assignment(head, limit):
    """Index of an `=` at depth 0 before `limit` that starts an initializer (not operator=, ==, ...)."""
    for k, c in depth0(head[:limit]):
        if c != "=":
            continue
        before, after = head[k - 1] if k else " ", head[k + 1] if k + 1 < len(head) else " "
        if before in "=!<>+-*/%&|^" or after == "=":
            continue
        if re.search(r"\boperator\s*$", head[:k]):
            continue
        return k
    return -1


class Function:
    def __init__(self, path, line, name, length):
        self.path, self.line, self.name, self.length = path, line, name, length

    def short_name(self):
        return re.split(r"::", self.name)[-1].strip()


def scan(text, path):
    """The functions defined at namespace scope in `text` (already blanked)."""
    functions = []
    line_of = []
    line = 1
    for c in text:
        line_of.append(line)
        if c == "\n":
            line += 1
    line_of.append(line)

    def record(head_start, head, open_brace, name):
        close = matching(text, open_brace)
        start = head_start + len(head) - len(head.lstrip())
        functions.append(Function(path, line_of[start], name, line_of[close] - line_of[start] + 1))
        return close

    def scope(i):
        """Scans declarations from i to the } closing this namespace; returns the index after it."""
        head_start = i
        while i < len(text):
            c = text[i]
            if c == ";":
                head_start = i + 1
            elif c == "}":
                return i + 1
            elif c in "([":  # a group inside a head (parameters, attributes)
                i = matching(text, i)
            elif c == "{":
                raw = text[head_start:i]
                head, cut = strip_macro_calls(raw)
                words = IDENT.findall(head)
                start = head_start + cut
                if words[:1] == ["namespace"] or words[:2] == ["inline", "namespace"] or words == ["extern"]:
                    i = scope(i + 1)
                    head_start = i
                    continue
                paren = first_paren(head)
                before_paren = head if paren < 0 else head[:paren]
                if TYPE_KEYWORDS & set(IDENT.findall("".join(ch for _, ch in depth0(before_paren)))):
                    i = matching(text, i)  # a class body: its inline members are not scanned
                elif (eq := assignment(head, paren if paren >= 0 else len(head))) >= 0:
                    if head[eq + 1:].lstrip().startswith("["):  # a lambda held by a variable
                        name = IDENT.findall(head[:eq])[-1]
                        i = record(start, head, i, name)
                        head_start = i + 1
                    else:
                        i = matching(text, i)  # an initializer
                elif paren >= 0:
                    after = head[matching(head, paren) + 1:]
                    initializers = re.search(r"(?<!:):(?!:)", after) is not None
                    if initializers and re.search(r"[\w>]\s*$", head):  # member{...} in the initializer list
                        i = matching(text, i)
                    else:
                        m = QUALIFIED_NAME.search(head[:paren])
                        name = re.sub(r"\s+", "", m.group(1)) if m else "?"
                        i = record(start, head, i, name)
                        head_start = i + 1
                else:
                    i = matching(text, i)  # a brace initializer: Foo x{...}
            i += 1
        return i

    scope(0)
    return functions


def relative(path, root):
    return os.path.relpath(path, root).replace(os.sep, "/")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True)
    parser.add_argument("--max", type=int, default=60)
    parser.add_argument("--exclude", action="append", default=[])
    parser.add_argument("--verbose", action="store_true")
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args(argv)

    offenders, excluded, builders, scanned, files = [], [], [], 0, 0
    for folder in args.folders:
        base = os.path.join(args.root, folder)
        if not os.path.isdir(base):
            print(f"{folder}/: does not exist, skipped")
            continue
        for dirpath, _, names in sorted(os.walk(base)):
            for name in sorted(names):
                if not name.endswith(".cpp"):
                    continue
                path = os.path.join(dirpath, name)
                rel = relative(path, args.root)
                with open(path, encoding="utf-8") as f:
                    functions = scan(blank(f.read()), rel)
                files += 1
                scanned += len(functions)
                for fn in functions:
                    if fn.length <= args.max:
                        continue
                    if LAYOUT_BUILDER.match(fn.short_name()):
                        builders.append(fn)
                    elif any(fnmatch.fnmatch(rel, pattern) for pattern in args.exclude):
                        excluded.append(fn)
                    else:
                        offenders.append(fn)

    def show(fn):
        return f"  {fn.path}:{fn.line}: {fn.name} is {fn.length} lines"

    if args.verbose and builders:
        print(f"Layout builders over {args.max} lines (allowed by name):")
        print("\n".join(show(fn) for fn in builders))
    if excluded:
        print(f"Still over {args.max} lines in excluded files (being rewritten; not failing):")
        print("\n".join(show(fn) for fn in excluded))
    if offenders:
        print(f"Functions over {args.max} lines (split them by meaning, or name a layout builder build*):")
        print("\n".join(show(fn) for fn in offenders))
        return 1
    print(f"{files} files, {scanned} functions: none over {args.max} lines outside layout builders"
          + (f" and {len(excluded)} in excluded files" if excluded else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
