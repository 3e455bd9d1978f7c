#!/usr/bin/env bash
# The man page and the bash completion the build writes from --help: every command is
# in both, groff reads the page without a warning, and the completion completes.
# Usage: cli_docs.sh SPHKERN MAN_PAGE COMPLETION
set -eu
sphkern=$1 man_page=$2 completion=$3
commands=$("$sphkern" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF {print $1}')
test "$(wc -w <<<"$commands")" -ge 13
for c in $commands; do
    grep -qx ".SS $c" "$man_page" || { echo "the man page lacks the command $c" >&2; exit 1; }
done
grep -q '^\\fB\\-\\-reproduce' "$man_page"
warnings=$(groff -man -Tutf8 -ww -z "$man_page" 2>&1)
test -z "$warnings" || { echo "groff: $warnings" >&2; exit 1; }
# Completion: commands after "sphkern", a command's options after "-".
source "$completion"
complete_words() { # complete_words WORD...: what _sphkern offers for the last word
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    _sphkern
    echo "${COMPREPLY[*]}"
}
test "$(complete_words sphkern stu)" = studies
test "$(complete_words sphkern run --rep)" = --reproduce
test "$(complete_words sphkern check --st)" = --strict
echo "man page and completion: $(wc -w <<<"$commands") commands"
