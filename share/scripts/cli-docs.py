#!/usr/bin/env python3
"""Writes sphkern's man page and bash completion from the program's own --help output,
so that both follow the command line as it is.
Usage: python3 share/scripts/cli-docs.py SPHKERN MAN_PAGE COMPLETION"""
import re
import subprocess
import sys

sphkern, man_file, completion_file = sys.argv[1:4]


def help_text(*words):
    return subprocess.run([sphkern, *words, "--help"], check=True, capture_output=True, text=True).stdout


def section(text, name):
    """The indented lines under "Name:" up to the next blank line."""
    match = re.search(rf"^{name}:\n((?:[ \t].*\n?)+)", text, re.M)
    return match.group(1).splitlines() if match else []


def entries(lines):
    """(names, description) of each entry: a line indented by two spaces starts one (names,
    then two or more spaces, then the description); deeper lines continue the description."""
    out = []
    for line in lines:
        if re.match(r"^  \S", line):
            parts = re.split(r"\s{2,}", line.strip(), maxsplit=1)
            out.append([parts[0], parts[1] if len(parts) > 1 else ""])
        elif out and line.strip():
            out[-1][1] += (" " if out[-1][1] else "") + line.strip()
    return out


def roff(text):
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return "\n".join(("\\&" + l if l.startswith((".", "'")) else l) for l in text.splitlines())


main = help_text()
version = subprocess.run([sphkern, "--version"], check=True, capture_output=True, text=True).stdout.split()[1]
commands = entries(section(main, "Subcommands"))
page = [f'.TH SPHKERN 1 "" "sphkern {version}" "User Commands"', ".SH NAME",
        "sphkern \\- accuracy and linear stability of SPH smoothing kernels on particle lattices",
        ".SH SYNOPSIS", ".B sphkern", "[\\fIOPTIONS\\fR] \\fICOMMAND\\fR [\\fIARGS\\fR]", ".SH DESCRIPTION",
        roff(main.splitlines()[0]), ".SH OPTIONS"]
for names, description in entries(section(main, "Options")):
    page += [".TP", f"\\fB{roff(names)}\\fR", roff(description)]
page.append(".SH COMMANDS")
options_of = {}
for name, description in commands:
    text = help_text(name)
    usage = re.search(r"^Usage: (.*)$", text, re.M)
    page += [".SS " + roff(name), roff(description)]
    if usage:
        page += [".PP", "\\fB" + roff("sphkern " + usage.group(1).split(" ", 1)[1]) + "\\fR"]
    options_of[name] = []
    for title in ("Positionals", "Options"):
        for names, desc in entries(section(text, title)):
            page += [".TP", f"\\fB{roff(names)}\\fR", roff(desc)]
            if title == "Options":
                options_of[name] += [n for n in names.split()[0].split(",") if n.startswith("-")]
page += [".SH EXIT STATUS",
         "0 success; 1 a kernel check failed (check), the numbers differ (run \\-\\-reproduce); 2 bad command-line "
         "arguments; 3 bad input; 4 a plugin that cannot be loaded or run; 5 results cannot be written; "
         "130 interrupted.",
         ".SH FILES", "The shipped kernels, lattices, studies and documents are installed under the prefix: "
         "\\fIlib/.../sphkern/plugins\\fR, \\fIshare/sphkern\\fR and \\fIshare/doc/sphkern\\fR (README.md, "
         "method.md, examples).",
         ".SH SEE ALSO", "The README of sphkern, share/docs/cli.md (every command and option, with examples), "
         "the guides in share/docs and share/docs/method.md, installed in \\fIshare/doc/sphkern\\fR."]
with open(man_file, "w") as f:
    f.write("\n".join(page) + "\n")

cases = "".join(f"        {name}) options=\"{' '.join(sorted(set(opts)))}\" ;;\n" for name, opts in options_of.items())
with open(completion_file, "w") as f:
    f.write(f"""# bash completion for sphkern {version}, written by share/scripts/cli-docs.py from sphkern --help.
_sphkern() {{
    local cur=${{COMP_WORDS[COMP_CWORD]}} options=""
    if ((COMP_CWORD == 1)); then
        COMPREPLY=($(compgen -W "{' '.join(name for name, _ in commands)} --help --version --log-level" -- "$cur"))
        return
    fi
    case ${{COMP_WORDS[1]}} in
{cases}    esac
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$options" -- "$cur"))
    else
        COMPREPLY=($(compgen -f -- "$cur"))
    fi
}}
complete -o filenames -F _sphkern sphkern
""")
