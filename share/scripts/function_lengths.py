#!/usr/bin/env python3
"""No function over 60 lines, counting lambdas: a brace-matching scan of C and C++ sources.

A function's body is a `{` after its parameter list's `)` (with qualifiers between: const,
noexcept, override, -> type, a constructor's initialiser list, ...) or a lambda's `]` or
`](...)`; strings, characters, comments and preprocessor lines are skipped. A function's
length runs from its signature's first line to its closing brace. A lambda, or a local
class's function, counts inside the function around it (that function's length includes
it); a lambda outside every function counts as a function of its own.

Usage: function_lengths.py [--limit N] [--allow FILE:NAME[=LINES]]... [--allow-file PATH]
                           [--root DIR] [--all] PATH...
PATH: files, or folders searched for *.c, *.h, *.cpp, *.hpp. Prints
`FILE:LINE: NAME is N lines (limit 60)` for each function over the limit and exits 1 if there
is one. An allowed function (FILE relative to --root, by default the current folder) may be
over the limit up to LINES (its length when it was listed); an allowance that no longer
applies (the function is gone or back within the limit) is an error too, so a list of
allowances can only shrink. --all prints every function with its length instead.
"""
import argparse
import pathlib
import re
import sys

SUFFIXES = (".c", ".h", ".cpp", ".hpp", ".cc", ".hh", ".cxx", ".hxx")
CONTROL = {"if", "for", "while", "switch", "catch", "constexpr", "requires", "sizeof", "alignof", "decltype",
           "return", "throw", "noexcept", "alignas", "static_assert"}
QUALIFIERS = {"const", "volatile", "noexcept", "override", "final", "mutable", "constexpr", "consteval", "try",
              "&", "&&", "throw"}
PARENTHESISED_QUALIFIERS = {"noexcept", "throw", "requires", "decltype", "alignas"}
STOPS = {";", "{", "}", ":"}


def blank(text):
    """The text with comments, string and character literals' contents and preprocessor lines
    replaced by spaces (newlines kept, so lines keep their numbers)."""
    out = list(text)
    i, n = 0, len(text)
    line_start = True

    def clear(a, b):
        for j in range(a, b):
            if out[j] != "\n":
                out[j] = " "

    def clear_quoted(i, quote):
        """Clears the literal opened at i up to its closing quote (or the line's end); returns past it."""
        j = i + 1
        while j < n and text[j] != quote and text[j] != "\n":
            j += 2 if text[j] == "\\" else 1
        clear(i + 1, min(j, n))
        return j + 1

    while i < n:
        c = text[i]
        if c == "\n":
            line_start = True
            i += 1
            continue
        if line_start and c in " \t":
            i += 1
            continue
        if line_start and c == "#":
            j = i
            while j < n and text[j] != "\n":
                if text.startswith("/*", j):  # a comment may continue past the line
                    end = text.find("*/", j + 2)
                    j = n if end < 0 else end + 2
                    continue
                if text[j] == "\\" and j + 1 < n and text[j + 1] == "\n":
                    j += 2
                    continue
                j += 1
            clear(i, j)
            i = j
            continue
        line_start = False
        if text.startswith("//", i):
            j = i
            while j < n and text[j] != "\n":
                j += 2 if text[j] == "\\" and j + 1 < n and text[j + 1] == "\n" else 1
            clear(i, j)
            i = j
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            j = n if end < 0 else end + 2
            clear(i, j)
            i = j
        elif c == '"':
            raw = re.search(r'(?:\b(?:u8|u|U|L)?)R$', text[max(0, i - 3):i])
            if raw:
                m = re.compile(r'"([^ ()\\\t\n]{0,16})\(').match(text, i)
                if m:
                    end = text.find(")" + m.group(1) + '"', m.end())
                    j = n if end < 0 else end + len(m.group(1)) + 2
                    clear(i + 1, j - 1)
                    i = j
                    continue
            i = clear_quoted(i, '"')
        elif c == "'":
            # A digit separator (1'000'000) is inside a number: the word before starts with a digit.
            k = i
            while k > 0 and (text[k - 1].isalnum() or text[k - 1] in "_'."):
                k -= 1
            if k < i and text[k].isdigit():
                i += 1
                continue
            i = clear_quoted(i, "'")
        else:
            i += 1
    return "".join(out)


TOKEN = re.compile(r"""\s+|(?P<word>[A-Za-z_][A-Za-z_0-9]*)|(?P<number>\.?[0-9](?:[A-Za-z0-9_.']|[eEpP][+-])*)
                       |(?P<string>"[^"\n]*"|'[^'\n]*')|(?P<punct>::|->|\.\.\.|&&|\|\||[-+*/%=!<>]=|.)""", re.X)


def tokens(text):
    """(text, kind, line) for each token of the blanked text."""
    found, line, pos = [], 1, 0
    for m in TOKEN.finditer(text):
        if m.lastgroup:
            line += text.count("\n", pos, m.start())
            pos = m.start()
            found.append((m.group(), m.lastgroup, line))
    return found


class Scan:
    def __init__(self, toks):
        self.t = toks
        self.match = {}
        stack = []
        for i, (s, _, _) in enumerate(toks):
            if s in "([{":
                stack.append(i)
            elif s in ")]}" and stack:
                j = stack.pop()
                self.match[i], self.match[j] = j, i

    def text(self, i):
        return self.t[i][0] if 0 <= i < len(self.t) else ""

    def opening(self, i):
        return self.match.get(i, -1)

    def angle_open(self, i):
        """The `<` matching the `>` at i, or -1."""
        depth = 0
        while i >= 0:
            s = self.text(i)
            if s == ">":
                depth += 1
            elif s == "<":
                depth -= 1
                if depth == 0:
                    return i
            elif s in (";", "{", "}"):
                return -1
            elif s in (")", "]"):
                i = self.opening(i)
                if i < 0:
                    return -1
            i -= 1
        return -1

    def is_lambda_introducer(self, close):
        """The `]` at close ends a lambda's capture list (not a subscript or an attribute)."""
        start = self.opening(close)
        if start < 0 or self.text(start + 1) == "[" or self.text(start - 1) == "[":
            return False
        before = self.t[start - 1] if start > 0 else ("", "punct", 0)
        return not (before[1] in ("word", "number", "string") and before[0] not in ("return", "co_return", "throw")
                    ) and before[0] not in (")", "]", "}")

    def tail_start(self, brace):
        """Walk back from a `{` over what may stand between a parameter list and a body:
        qualifiers, `noexcept(...)`, a trailing return type. Returns (index of the token
        before the tail, has_arrow, tail words)."""
        i, arrow, words = brace - 1, False, []
        while i >= 0:
            s, kind, _ = self.t[i]
            if s == ")":
                j = self.opening(i)
                if j > 0 and self.text(j - 1) in PARENTHESISED_QUALIFIERS:
                    words.append(self.text(j - 1))
                    i = j - 2
                    continue
                return i, arrow, words
            if s == "->":
                arrow = True
            elif s in STOPS or s in ("=", "(", "[", "]", "return", "else", "do") or kind in ("string", "number"):
                return i, arrow, words
            elif s not in ("::", "<", ">", ",", "*", "&", "&&", "...") and kind != "word":
                return i, arrow, words
            words.append(s)
            i -= 1
        return i, arrow, words

    def name_before(self, paren):
        """The function name ending just before the `(` at paren: (name, index of its first token)."""
        i = paren - 1
        if self.text(i) == ">":  # f<int>(...)
            k = self.angle_open(i)
            if k > 0 and self.t[k - 1][1] == "word" and self.text(k - 1) != "operator":
                i = k - 1
        k = i  # operator(), operator==, operator[]
        while k >= 0 and k > i - 3 and self.t[k][1] == "punct" and self.text(k) not in (";", "{", "}", "::", ","):
            k -= 1
        if k < i and self.text(k) == "operator":
            name = "operator" + "".join(self.text(x) for x in range(k + 1, i + 1))
            i = k - 1
        elif i >= 0 and self.t[i][1] == "word":
            if self.text(i - 1) == "operator":  # operator bool
                name, i = "operator " + self.text(i), i - 2
            else:
                name, i = self.text(i), i - 1
                if self.text(i) == "~":
                    name, i = "~" + name, i - 1
        else:
            return "", paren
        while self.text(i) == "::" and i > 0:
            prev = i - 1
            if self.text(prev) == ">":  # Outer<T>::name
                k = self.angle_open(prev)
                if k < 1:
                    break
                prev = k - 1
            if self.t[prev][1] != "word":
                break
            name = self.text(prev) + "::" + name
            i = prev - 1
        return name, i + 1

    def before_initialisers(self, close):
        """For `: a_(x), b_{y}` ending at close (the last initialiser's `)` or `}`), the `)` of
        the constructor's parameter list, or -1."""
        i = close
        while True:
            j = self.opening(i)
            if j < 1 or self.t[j - 1][1] != "word":
                return -1
            k = j - 1
            while self.text(k - 1) == "::" and self.t[k - 2][1] == "word":
                k -= 2
            if self.text(k - 1) == ">":  # Base<T>(x)
                a = self.angle_open(k - 1)
                if a > 0 and self.t[a - 1][1] == "word":
                    k = a - 1
            sep = self.text(k - 1)
            if sep == ",":
                i = k - 2
                if self.text(i) == "...":
                    i -= 1
                if self.text(i) not in (")", "}"):
                    return -1
                continue
            if sep == ":":
                before, _, _ = self.tail_start(k - 1)
                return before if self.text(before) == ")" else -1
            return -1

    def signature_start(self, i):
        """The first token of the declaration whose name starts at token i."""
        while i > 0:
            s = self.text(i - 1)
            if s in (";", "{", "}") or (s == ":" and self.text(i - 2) in ("public", "private", "protected")):
                break
            if s in (")", "]"):
                j = self.opening(i - 1)
                if j < 0:
                    break
                i = j
                continue
            i -= 1
        return i

    def body(self, brace):
        """(kind, name, first token) when the `{` at brace opens a function or lambda body, else None."""
        before, arrow, words = self.tail_start(brace)
        s = self.text(before)
        plain = all(w in QUALIFIERS for w in words)
        if not plain and not arrow:
            return None
        if s == "]" and self.is_lambda_introducer(before):
            return "lambda", self.lambda_name(self.opening(before)), self.opening(before)
        if s == "}" and plain:
            ctor = self.before_initialisers(before)
            if ctor < 0:
                return None
            before = ctor
            s = ")"
        if s != ")":
            return None
        paren = self.opening(before)
        if paren < 0:
            return None
        prev = self.text(paren - 1)
        if prev == "]" and self.is_lambda_introducer(paren - 1):
            start = self.opening(paren - 1)
            return "lambda", self.lambda_name(start), start
        if prev == ">":
            k = self.angle_open(paren - 1)
            if k > 0 and self.text(k - 1) == "]" and self.is_lambda_introducer(k - 1):
                start = self.opening(k - 1)
                return "lambda", self.lambda_name(start), start
        if prev in CONTROL:
            return None
        if plain:
            ctor = self.before_initialisers(before)
            if ctor >= 0:
                paren = self.opening(ctor)
        name, first = self.name_before(paren)
        if not name:
            return None
        return "function", name, self.signature_start(first)

    def lambda_name(self, start):
        if self.text(start - 1) == "=" and self.t[start - 2][1] == "word":
            return self.text(start - 2)
        return "lambda"


def functions(text):
    """(name, first line, last line) of each function body outside every other function's."""
    toks = tokens(blank(text))
    scan = Scan(toks)
    found, inside_until = [], -1
    for i, (s, _, _) in enumerate(toks):
        if s != "{" or i <= inside_until:
            continue
        close = scan.opening(i)
        if close < 0:
            continue
        kind = scan.body(i)
        if kind is None:
            continue
        _, name, first = kind
        found.append((name, toks[first][2], toks[close][2]))
        inside_until = close
    return found


def sources(paths):
    for p in paths:
        p = pathlib.Path(p)
        if p.is_dir():
            yield from sorted(f for f in p.rglob("*") if f.suffix in SUFFIXES and f.is_file())
        else:
            yield p


def read_allowances(entries, files):
    allowed = {}
    for entry in entries:
        key, _, lines = entry.partition("=")
        allowed[key.strip()] = int(lines) if lines.strip() else None
    for f in files:
        for raw in pathlib.Path(f).read_text().splitlines():
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            fields = line.split()
            allowed[fields[0]] = int(fields[1]) if len(fields) > 1 else None
    return allowed


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("paths", nargs="+")
    parser.add_argument("--limit", type=int, default=60)
    parser.add_argument("--allow", action="append", default=[], metavar="FILE:NAME[=LINES]")
    parser.add_argument("--allow-file", action="append", default=[], metavar="PATH",
                        help="lines `FILE:NAME LINES` (# starts a comment)")
    parser.add_argument("--root", default=".", help="FILE names are relative to this folder")
    parser.add_argument("--all", action="store_true", help="print every function and its length")
    args = parser.parse_args(argv)
    allowed = read_allowances(args.allow, args.allow_file)
    root = pathlib.Path(args.root).resolve()
    used, failures = set(), 0
    for path in sources(args.paths):
        try:
            shown = str(path.resolve().relative_to(root))
        except ValueError:
            shown = str(path)
        for name, first, last in functions(path.read_text(errors="replace")):
            length = last - first + 1
            if args.all:
                print(f"{shown}:{first}: {name} is {length} lines")
                continue
            if length <= args.limit:
                continue
            key = f"{shown}:{name}"
            if key in allowed:
                used.add(key)
                ceiling = allowed[key]
                if ceiling is None or length <= ceiling:
                    continue
                print(f"{shown}:{first}: {name} is {length} lines (limit {args.limit}; allowed {ceiling}, "
                      "the length it had when allowed)")
            else:
                print(f"{shown}:{first}: {name} is {length} lines (limit {args.limit})")
            failures += 1
    if not args.all:
        for key in sorted(set(allowed) - used):
            print(f"{key}: allowed over {args.limit} lines but no longer is (or is gone): remove its allowance")
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
