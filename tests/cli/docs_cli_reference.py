#!/usr/bin/env python3
"""share/docs/cli.md against the program's own --help: every subcommand `sphkern --help`
lists has a section "## `sphkern NAME`" and a row in the table of commands, and its section
names every option and positional of `sphkern NAME --help`; every option in a section's
synopsis (its ```text blocks) exists; every section is a subcommand; the options of
`sphkern --help` are in "## Options of sphkern itself". A new command fails here until it is
documented.
Usage: docs_cli_reference.py SOURCE_DIR SPHKERN"""
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from markdown_docs import blocks, headings, slug  # noqa: E402

root, sphkern = Path(sys.argv[1]), sys.argv[2]
reference = root / "share" / "docs" / "cli.md"
OWN = "Options of sphkern itself"


def help_text(*words):
    return subprocess.run([sphkern, *words, "--help"], check=True, capture_output=True, text=True).stdout


def entries(text, title):
    """The first word of each entry under "Title:" in CLI11's help (two-space indented)."""
    match = re.search(rf"^{title}:\n((?:[ \t].*\n?|\n(?=[ \t]))+)", text, re.M)
    return [line.split()[0] for line in match.group(1).splitlines() if re.match(r"^  \S", line)] if match else []


def option_names(text):
    """Every name of every option but --help: "-o,--output" gives -o and --output."""
    return [n for e in entries(text, "Options") for n in e.split(",") if n.startswith("-") and n not in ("-h", "--help")]


def mentions(section, word):
    return re.search(rf"(?<![\w-]){re.escape(word)}(?![\w-])", section) is not None


text = reference.read_text()
lines = text.splitlines()
marks = headings(text)
sections = {}  # title -> text up to the next heading of level 1 or 2
for i, (level, title, number) in enumerate(marks):
    if level == 2:
        end = next((n for lv, _, n in marks[i + 1:] if lv <= 2), len(lines) + 1)
        sections[title.strip("`")] = "\n".join(lines[number:end - 1])

main = help_text()
commands = entries(main, "Subcommands")
assert commands, "sphkern --help lists no subcommands"
problems = []
for option in option_names(main):
    if not mentions(sections.get(OWN, ""), option):
        problems.append(f'cli.md: "## {OWN}" does not name {option} (sphkern --help has it)')
for command in commands:
    title = f"sphkern {command}"
    if title not in sections:
        problems.append(f"cli.md: no section \"## `{title}`\" for the command {command} that sphkern --help lists; "
                        f"add one with a ```text synopsis and every option of `{title} --help`")
        continue
    if f"](#{slug(title)})" not in text:
        problems.append(f"cli.md: the table of commands has no link (#{slug(title)}) to the section of {command}")
    section, own = sections[title], help_text(command)
    known = set(option_names(own)) | {"-h", "--help"}
    for word in option_names(own) + entries(own, "Positionals"):
        if not mentions(section, word):
            problems.append(f"cli.md: the section of {command} does not name {word} (`{title} --help` has it)")
    for info, _, body in blocks(section):
        if info[:1] == ["text"]:
            for word in re.findall(r"(?<![\w-])--?[A-Za-z][\w-]*", "\n".join(body)):
                if word not in known:
                    problems.append(f"cli.md: the synopsis of {command} shows {word}, which `{title} --help` does not have")
for title in sections:
    if title.startswith("sphkern ") and title.split()[1] not in commands:
        problems.append(f"cli.md: the section \"{title}\" is no command of sphkern --help")
if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(f"{len(problems)} differences between share/docs/cli.md and --help")
print(f"cli.md documents all {len(commands)} commands and their options as --help lists them")
