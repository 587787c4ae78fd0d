#!/usr/bin/env python3
"""Writes docs/reference/commands.md from the program's own --help.

    scripts/command_reference.py build/radiosity > docs/reference/commands.md
    scripts/command_reference.py build/radiosity --check docs/reference/commands.md

The page is generated, never edited by hand; --check exits 1 with a diff when the committed
page is not what --help prints now (the CTest test docs_commands_reference_current).
"""
import difflib
import re
import subprocess
import sys


def help_text(program, *args):
    # argv[0] is "radiosity" whatever the build directory, so the page does not name it
    run = subprocess.run(["radiosity", *args, "--help"], executable=program, capture_output=True, text=True,
                         timeout=60)
    if run.returncode != 0:
        sys.exit(f"{program} {' '.join(args)} --help: exit status {run.returncode}: {run.stderr.strip()}")
    return run.stdout.rstrip() + "\n"


def subcommands(top_help):
    """The names under the top-level help's SUBCOMMANDS heading."""
    names, inside = [], False
    for line in top_help.splitlines():
        if line.strip().upper().startswith("SUBCOMMAND"):
            inside = True
            continue
        if inside:
            match = re.match(r"^\s+([a-z][a-z0-9-]*)\s", line + " ")
            if match:
                names.append(match.group(1))
            elif line.strip() and not line.startswith(" "):
                break
    if not names:
        sys.exit("no subcommands found in the top-level --help")
    return names


def page(program):
    top = help_text(program)
    parts = [
        "# Command reference\n",
        "What `radiosity --help` and each command's `--help` print, word for word. This page is",
        "generated from the program (`scripts/command_reference.py`), and a test fails when it",
        "falls out of date. The guide's pages explain what the options do.\n",
        "## radiosity\n",
        "```text\n" + top + "```\n",
    ]
    for name in subcommands(top):
        parts.append(f"## radiosity {name}\n")
        parts.append("```text\n" + help_text(program, name) + "```\n")
    return "\n".join(parts)


def main():
    if len(sys.argv) == 2:
        sys.stdout.write(page(sys.argv[1]))
        return
    if len(sys.argv) == 4 and sys.argv[2] == "--check":
        current = page(sys.argv[1])
        with open(sys.argv[3], encoding="utf-8") as f:
            committed = f.read()
        if current != committed:
            sys.stdout.writelines(difflib.unified_diff(committed.splitlines(True), current.splitlines(True),
                                                       sys.argv[3], "--help now"))
            print(f"\n{sys.argv[3]} is out of date: regenerate it with\n"
                  f"  scripts/command_reference.py build/radiosity > {sys.argv[3]}")
            sys.exit(1)
        return
    sys.exit(__doc__)


if __name__ == "__main__":
    main()
