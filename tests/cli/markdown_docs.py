"""What the documentation tests read from Markdown: the documents, their fenced blocks,
their headings as GitHub anchors, and their links (outside code)."""
import re
import unicodedata
from pathlib import Path

FENCE = re.compile(r"^( *)(```+|~~~+)\s*(.*)$")  # indented inside a list item too


def documents(root):
    """README.md and every Markdown file of share/docs."""
    return [root / "README.md", *sorted((root / "share" / "docs").glob("*.md"))]


def blocks(text):
    """(info words, first line number, lines) of every fenced block."""
    out, lines, i = [], text.splitlines(), 0
    while i < len(lines):
        match = FENCE.match(lines[i])
        if not match:
            i += 1
            continue
        indent, fence, info, start, body = match.group(1), match.group(2), match.group(3).split(), i + 1, []
        i += 1
        while i < len(lines) and not lines[i].startswith(indent + fence):
            body.append(lines[i].removeprefix(indent))
            i += 1
        out.append((info, start + 1, body))
        i += 1
    return out


def outside_fences(text):
    """(number, line) of every line outside fenced blocks."""
    inside = None
    for number, line in enumerate(text.splitlines(), 1):
        match = FENCE.match(line)
        if inside is None and match:
            inside = match.group(1) + match.group(2)
        elif inside is not None and line.startswith(inside):
            inside = None
        elif inside is None:
            yield number, line


def prose(text):
    """The lines outside fenced blocks, with inline code spans blanked (a span may go on over
    line breaks, not over a blank line); (number, line)."""
    kept = dict(outside_fences(text))
    whole = "\n".join(kept.get(n, "") for n in range(1, len(text.splitlines()) + 1))
    blanked = re.sub(r"(`+)(?:(?!\1)(?!\n[ \t]*\n)[^`]|(?!\1)`)+\1",
                     lambda m: re.sub(r"[^\n]", " ", m.group(0)), whole).split("\n")
    return [(number, blanked[number - 1]) for number in kept]


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)
    text = re.sub(r"<[^>]+>", "", text).strip().lower()
    kept = "".join(c for c in text if c in " -_" or unicodedata.category(c)[0] in "LN")
    return kept.replace(" ", "-")


def anchors(text):
    """Every heading's anchor, the second of two equal ones with -1 appended, as GitHub does."""
    seen, out = {}, set()
    for _, title, _ in headings(text):
        base = slug(title)
        name = base if base not in seen else f"{base}-{seen[base]}"
        seen[base] = seen.get(base, 0) + 1
        out.add(name)
    return out


def headings(text):
    """(level, title as written, line number) of every heading outside fenced blocks."""
    out = []
    for number, line in outside_fences(text):
        heading = re.match(r"^(#{1,6})\s+(.*?)\s*$", line)
        if heading:
            out.append((len(heading.group(1)), heading.group(2), number))
    return out


LINK = re.compile(r"!?\[(?:[^\]\\]|\\.)*\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")


def links(text):
    """(line number, target) of every inline link and image outside code."""
    return [(number, m.group(1)) for number, line in prose(text) for m in LINK.finditer(line)]


FIGURE = re.compile(r"(?<![\w.])-?(?:\d+\.\d+(?:e[-+]?\d+)?|\d+e[-+]?\d+)(?![\w]|\.\d)")
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def digits(figure):
    """The significant digits a figure is written with (0.130: 3; 6.4e-04: 2)."""
    mantissa = re.split(r"e", figure.lstrip("-"))[0].replace(".", "").lstrip("0")
    return len(mantissa)


def unchecked_figures(text, printed, typed):
    """(line, figure) of every figure of two or more significant digits in the prose and tables
    that no command of the document printed (rounded as written, sign aside) and that is not
    typed on one of its command lines. Inline code is not prose: a value in `code` is a setting."""
    values = {}
    for number in NUMBER.findall(printed):
        try:
            value = abs(float(number))
        except ValueError:
            continue
        for n in range(1, 8):
            values.setdefault(n, set()).add(float(f"{value:.{n}g}"))
    missing, made_by_script = [], False
    for line, content in prose(text):
        # A table after <!-- table: python3 share/scripts/... --> is the script's: docs_table.py
        # runs it again and compares every row.
        made_by_script = made_by_script and content.startswith("|") or "<!-- table: python3 share/scripts/" in content
        if made_by_script:
            continue
        for figure in FIGURE.findall(content):
            n = digits(figure)
            if n < 2 or figure.lstrip("-") in typed:
                continue
            if abs(float(figure)) not in values.get(n, set()):
                missing.append((line, figure))
    return missing
