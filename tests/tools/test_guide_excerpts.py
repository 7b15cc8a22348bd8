#!/usr/bin/python3
"""The C++ excerpts of docs/plugins.md's "Writing a transient integrator" are
lines of examples/transient-first-bounce/transient_first_bounce.cpp, in order
and contiguous (leading spaces aside), so they compile whenever the example does
(sdk.out_of_tree_transient_integrator builds it).

usage: test_guide_excerpts.py SOURCE_DIR
"""
import re
import sys
from pathlib import Path

GUIDE = "docs/plugins.md"
SECTION = "## Writing a transient integrator"
EXAMPLE = "examples/transient-first-bounce/transient_first_bounce.cpp"


def main():
    root = Path(sys.argv[1])
    guide = (root / GUIDE).read_text()
    if SECTION not in guide:
        print(f"{GUIDE}: no section \"{SECTION}\"", file=sys.stderr)
        return 1
    section = guide.split(SECTION, 1)[1].split("\n## ", 1)[0]
    source = [line.strip() for line in (root / EXAMPLE).read_text().splitlines()]
    blocks = re.findall(r"```cpp\n(.*?)```", section, re.S)
    if not blocks:
        print(f"{GUIDE}: \"{SECTION}\" has no C++ excerpt", file=sys.stderr)
        return 1
    failures = 0
    for block in blocks:
        lines = [line.strip() for line in block.splitlines()]
        found = any(source[i:i + len(lines)] == lines for i in range(len(source) - len(lines) + 1))
        if not found:
            failures += 1
            print(f"{GUIDE}: this excerpt is not a run of lines of {EXAMPLE}:\n{block}", file=sys.stderr)
    print(f"{len(blocks) - failures} of {len(blocks)} excerpts found in {EXAMPLE}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
