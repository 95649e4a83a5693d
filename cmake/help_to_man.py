#!/usr/bin/python3
"""Render a program's --help text as a man page (section 1), at build time.

The help text is the one reference users already see, so the man page is made from it
rather than written twice: the usage lines become the SYNOPSIS, the rest is kept as
preformatted text (its aligned option columns survive), and --version, when the program
has it, names the version in the header.

usage: help_to_man.py PROGRAM NAME "one-line summary" OUTPUT.1
"""
import subprocess
import sys


def roff_escape(line):
    # Backslashes are roff escapes; a leading '.' or "'" would be read as a request.
    line = line.replace("\\", "\\e").replace("-", "\\-")
    if line.startswith((".", "'")):
        line = "\\&" + line
    return line


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    program, name, summary, output = sys.argv[1:]
    help_text = subprocess.run([program, "--help"], check=True, capture_output=True,
                               text=True).stdout
    version = subprocess.run([program, "--version"], capture_output=True, text=True)
    version_line = version.stdout.strip().splitlines()[0] if version.returncode == 0 and version.stdout.strip() else name

    lines = help_text.rstrip().splitlines()
    # The usage block: the first lines, up to the first blank line.
    usage_end = lines.index("") if "" in lines else len(lines)
    usage, body = lines[:usage_end], lines[usage_end + 1:]

    page = [f'.TH {name.upper()} 1 "" "{roff_escape(version_line)}" "User Commands"',
            ".SH NAME", f"{name} \\- {roff_escape(summary)}", ".SH SYNOPSIS", ".nf"]
    page += [roff_escape(line.replace("usage: ", "", 1).strip()) for line in usage]
    page += [".fi", ".SH DESCRIPTION", ".nf"]
    page += [roff_escape(line) for line in body]
    page += [".fi", ".SH SEE ALSO",
             "The README of Moebius Registration for VTK and ParaView, in "
             "/usr/share/doc/mobius\\-registration or the source tree."]
    with open(output, "w", encoding="utf-8") as out:
        out.write("\n".join(page) + "\n")


if __name__ == "__main__":
    main()
