#!/usr/bin/env python3
"""The documentation's shape (README "User guide"; docs/house-rules.md, "Docs"):
- README.md at most 150 lines; every user page (docs/*.md but the generated
  BENCHMARKS.md) at most 400; design notes (docs/design/) have no limit;
- no heading repeated within one file (README, docs/, docs/design/);
- every page under docs/ is linked from the README, and every relative
  Markdown link in the README and docs/ names a file that exists and, with
  '#anchor', a heading of it;
- every citation of a doc section in the sources, tools, tests, scenes and
  docs (a page's path followed by a quoted section title) names a file that exists and a heading
  containing that text.
Usage: test_docs.py SOURCE_DIR (exit 1 listing every problem)."""
import pathlib
import re
import sys

README_MAX = 150
USER_PAGE_MAX = 400
GENERATED = {"BENCHMARKS.md"}  # assembled by tools/bench/benchmarks.py; not a user page
SECTIONS = None  # docs/benchmarks/sections, set in main()

FENCE = re.compile(r"^(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
CITATION = re.compile(r"(?<![\w/.])docs/([\w./-]+\.md)(?:,\s*|\s+\(?)[\"“]([^\"”]{3,200})[\"”]")
COMMENT_PREFIX = re.compile(r"^\s*(///?|#+|\*|<!--|-->)?\s?")


def prose_lines(text):
    """(line number, line) of the lines outside code fences."""
    inside = False
    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line.strip()):
            inside = not inside
            continue
        if not inside:
            yield number, line


def headings(text):
    """(line number, level, title) of every Markdown heading outside code fences."""
    for number, line in prose_lines(text):
        match = HEADING.match(line)
        if match:
            yield number, len(match.group(1)), match.group(2)


def slug(title):
    """GitHub's anchor for a heading: lower case, punctuation but '-' and '_' dropped, spaces to '-'."""
    title = title.lower().replace("`", "").replace("*", "")
    return re.sub(r"[^\w\- ]", "", title).replace(" ", "-")


def normalise(text):
    return re.sub(r"\s+", " ", re.sub(r"[`*]", "", text)).strip().lower()


def doc_files(root):
    return [root / "README.md"] + sorted((root / "docs").rglob("*.md"))


def check_sizes(root):
    readme = root / "README.md"
    lines = len(readme.read_text(encoding="utf-8").splitlines())
    if lines > README_MAX:
        yield f"README.md: {lines} lines, more than {README_MAX}"
    for page in sorted((root / "docs").glob("*.md")):
        if page.name in GENERATED:
            continue
        lines = len(page.read_text(encoding="utf-8").splitlines())
        if lines > USER_PAGE_MAX:
            yield f"{page.relative_to(root)}: {lines} lines, more than {USER_PAGE_MAX} for a user page " \
                  "(derivations and measurement history go to docs/design/)"


def check_headings(root):
    for path in doc_files(root):
        seen = {}
        for number, _, title in headings(path.read_text(encoding="utf-8")):
            key = normalise(title)
            if key in seen:
                yield f"{path.relative_to(root)}:{number}: heading \"{title}\" repeats line {seen[key]}"
            else:
                seen[key] = number


def check_links(root):
    readme = (root / "README.md").read_text(encoding="utf-8")
    linked = {(root / target.split("#")[0]).resolve() for target in LINK.findall(readme)}
    for page in sorted((root / "docs").glob("*.md")):
        if page.resolve() not in linked:
            yield f"{page.relative_to(root)}: not linked from README.md"
    anchors = {}
    for path in doc_files(root):
        if SECTIONS in path.resolve().parents:
            continue  # their links are relative to docs/BENCHMARKS.md, which is checked
        text = path.read_text(encoding="utf-8")
        for number, line in prose_lines(text):
            for target in LINK.findall(line):
                if re.match(r"[a-z]+:", target):
                    continue  # http:, https:, mailto:
                file_part, _, anchor = target.partition("#")
                destination = (path.parent / file_part).resolve() if file_part else path.resolve()
                where = f"{path.relative_to(root)}:{number}"
                if not destination.exists():
                    yield f"{where}: link to {target}: no such file"
                    continue
                if anchor and destination.suffix == ".md":
                    if destination not in anchors:
                        anchors[destination] = {slug(t) for _, _, t in headings(destination.read_text(encoding="utf-8"))}
                    if anchor not in anchors[destination]:
                        yield f"{where}: link to {target}: no heading with that anchor"


def flattened(text):
    """The text with each line's comment marker removed and the lines joined,
    so that a citation broken across comment lines reads as one."""
    return " ".join(COMMENT_PREFIX.sub("", line, count=1) for line in text.splitlines())


def check_citations(root):
    titles = {}
    places = [root / "src", root / "tools", root / "tests", root / "scenes", root / "examples", root / "docs"]
    suffixes = {".h", ".cpp", ".inl", ".py", ".sh", ".xml", ".md", ".txt", ".cmake"}
    for place in places:
        for path in sorted(place.rglob("*")):
            if path.suffix not in suffixes or not path.is_file() or "build" in path.parts:
                continue
            text = flattened(path.read_text(encoding="utf-8", errors="replace"))
            for match in CITATION.finditer(text):
                name, section = match.group(1), normalise(match.group(2))
                doc = root / "docs" / name
                where = f"{path.relative_to(root)}: docs/{name}, \"{match.group(2).strip()}\""
                if not doc.exists():
                    yield f"{where}: no such file"
                    continue
                if doc not in titles:
                    titles[doc] = [normalise(t) for _, _, t in headings(doc.read_text(encoding="utf-8"))]
                if not any(section in title for title in titles[doc]):
                    yield f"{where}: no heading of docs/{name} contains that text"
    # Plain file citations (without a section) must name a file that exists.
    for place in places[:-1]:
        for path in sorted(place.rglob("*")):
            if path.suffix not in suffixes or not path.is_file() or "build" in path.parts:
                continue
            for name in set(re.findall(r"(?<![\w/.])docs/([\w/-]+\.md)", path.read_text(encoding="utf-8", errors="replace"))):
                if not (root / "docs" / name).exists():
                    yield f"{path.relative_to(root)}: cites docs/{name}, which does not exist"


def main():
    global SECTIONS
    root = pathlib.Path(sys.argv[1])
    SECTIONS = (root / "docs" / "benchmarks" / "sections").resolve()
    problems = []
    for check in (check_sizes, check_headings, check_links, check_citations):
        problems += list(check(root))
    for problem in problems:
        print(problem)
    print(f"{len(problems)} problem(s) in the documentation")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
