#!/usr/bin/python3
"""Replace one generated section of a Markdown file (e.g. docs/BENCHMARKS.md)
with standard input, leaving the rest alone, so several benchmark scripts can
each regenerate their own part of one document.

  some_benchmark | tools/bench/replace_doc_section.py docs/BENCHMARKS.md NAME

The section is everything between the lines `<!-- begin NAME -->` and
`<!-- end NAME -->`; if the file has no such section it is appended.
"""
import os
import sys


def replace_section(text, name, body):
    begin, end = f"<!-- begin {name} -->", f"<!-- end {name} -->"
    block = f"{begin}\n{body.rstrip()}\n{end}\n"
    if begin in text and end in text:
        head, rest = text.split(begin, 1)
        _, tail = rest.split(end, 1)
        return head + block + ("\n" + tail.lstrip("\n") if tail.strip() else "")
    return (text.rstrip() + "\n\n" if text.strip() else "") + block


def main(argv):
    if len(argv) != 3:
        sys.exit("usage: replace_doc_section.py FILE NAME < section.md")
    path, name = argv[1], argv[2]
    text = open(path).read() if os.path.exists(path) else ""
    new = replace_section(text, name, sys.stdin.read())
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(new)
    os.replace(tmp, path)


if __name__ == "__main__":
    main(sys.argv)
