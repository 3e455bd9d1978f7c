#!/usr/bin/env python3
"""Every relative link of README.md and share/docs/*.md points to a file or folder of the
repository that exists, and every #anchor to a heading of the Markdown file it names
(GitHub's anchors). Links to the web are not followed.
Usage: docs_links.py SOURCE_DIR"""
import sys
from pathlib import Path
from urllib.parse import unquote

sys.path.insert(0, str(Path(__file__).parent))
from markdown_docs import anchors, documents, links  # noqa: E402

root = Path(sys.argv[1]).resolve()
problems, checked = [], 0
for document in documents(root):
    text = document.read_text()
    for number, target in links(text):
        where = f"{document.relative_to(root)}:{number}: link {target}"
        if not target or "://" in target or target.startswith("mailto:"):
            if not target:
                problems.append(f"{where}: empty")
            continue
        checked += 1
        path, _, anchor = target.partition("#")
        file = (document.parent / unquote(path)).resolve() if path else document
        if root not in (file, *file.parents):
            problems.append(f"{where}: points outside the repository")
        elif not file.exists():
            problems.append(f"{where}: {file.relative_to(root)} does not exist")
        elif anchor and (file.suffix != ".md" or unquote(anchor) not in anchors(file.read_text())):
            problems.append(f"{where}: no heading of {file.relative_to(root)} has the anchor #{anchor}")
if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(f"{len(problems)} broken links")
print(f"{checked} relative links in {len(documents(root))} documents resolve")
