"""What the documentation tests read from Markdown: the documents, their fenced blocks,
their headings as GitHub anchors, and their links (outside code)."""
import re
import unicodedata
from pathlib import Path

FENCE = re.compile(r"^(```+|~~~+)\s*(.*)$")


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
        fence, info, start, body = match.group(1), match.group(2).split(), i + 1, []
        i += 1
        while i < len(lines) and not lines[i].startswith(fence):
            body.append(lines[i])
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
            inside = match.group(1)
        elif inside is not None and line.startswith(inside):
            inside = None
        elif inside is None:
            yield number, line


def prose(text):
    """The lines outside fenced blocks, with inline code spans blanked; (number, line)."""
    return [(number, re.sub(r"(`+)(?:(?!\1).)+\1", lambda m: " " * len(m.group(0)), line))
            for number, line in outside_fences(text)]


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
