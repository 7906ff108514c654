"""Every document carom's sources cite exists in a clone, and the front door stays short.

    /usr/bin/python3 tests/docs/check_citations.py REPOSITORY_ROOT

Checks, over the repository (build trees, .git and run outputs left out):

1. Sources (C++, Python, shell, TOML, CMake) and Markdown pages: every `NAME.md` they mention
   resolves. A path resolves beside the citing file or from the repository root; a bare file
   name (no folder) also resolves when exactly one file of that name exists in the repository.
   Names of files a run writes (report.md, table.md) are not documents and are skipped.
2. A citation of core/DESIGN.md or tests/VALIDATION.md followed by a quoted section name
   (`core/DESIGN.md, "Walls"`) or a section number (`DESIGN.md section 5`) names a heading that
   exists on that page.
3. Markdown links (`[text](path#anchor)`) to files in the repository resolve, and an anchor
   into a Markdown page matches one of its headings (GitHub's anchor rules).
4. README.md has at most 200 lines; it and the user guides (scenarios/guides/) carry no dates,
   issue numbers or "stop N" markers.

Prints each failure as FILE:LINE: message and exits 1 if there is any, else 0.
"""
import os
import re
import sys
import unicodedata

SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".py", ".sh", ".toml", ".in", ".cmake")
SOURCE_NAMES = ("CMakeLists.txt",)
SKIP_DIRS = {".git", "out", "__pycache__"}
OUTPUT_NAMES = {"report.md", "table.md"}  # files that runs and scripts write, not documents
README_MAX_LINES = 200
SELF = "tests/docs/check_citations.py"  # its own examples are not citations
DESIGN_PAGES = ("core/DESIGN.md", "tests/VALIDATION.md")

MD_TOKEN = re.compile(r"(?<![\w./-])((?:\.{1,2}/)*[\w][\w./-]*\.md)(?![\w])")
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
SECTION_AFTER = re.compile(r"""^[`'*]*(?:\s*,)?\s*(?:(?:section|sections|§)\s*(\d+)|"([^"]+)")""", re.I)
DATE = re.compile(r"\b20\d\d-\d\d-\d\d\b")
ISSUE = re.compile(r"\b(?:[Ii]ssue|[Ss]top) \d+\b")


def skipped_dir(name):
    return name in SKIP_DIRS or name.startswith("build") or name.endswith(".out")


def repository_files(root):
    files = []
    for folder, dirs, names in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not skipped_dir(d))
        for name in sorted(names):
            files.append(os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/"))
    return files


def slug(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"<[^>]+>", "", heading).strip().lower()
    kept = []
    for ch in text:
        if ch in (" ", "-", "_") or ch.isalnum() or unicodedata.category(ch).startswith("L"):
            kept.append(ch)
    return "".join(kept).replace(" ", "-")


def headings(path):
    """(anchor slugs, heading texts) of a Markdown file, code blocks left out."""
    anchors, texts, seen, fenced = set(), [], {}, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.lstrip().startswith(("```", "~~~")):
                fenced = not fenced
                continue
            if fenced:
                continue
            m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
            if not m:
                continue
            text = m.group(2)
            base = slug(text)
            count = seen.get(base, 0)
            seen[base] = count + 1
            anchors.add(base if count == 0 else f"{base}-{count}")
            texts.append(text)
    return anchors, texts


class Checker:
    def __init__(self, root):
        self.root = root
        self.files = repository_files(root)
        self.file_set = set(self.files)
        self.dirs = {os.path.dirname(f) for f in self.files}
        for f in self.files:
            parts = f.split("/")
            for k in range(1, len(parts)):
                self.dirs.add("/".join(parts[:k]))
        self.by_name = {}
        for f in self.files:
            self.by_name.setdefault(os.path.basename(f), []).append(f)
        self.heading_cache = {}
        self.failures = []

    def fail(self, where, line, message):
        self.failures.append(f"{where}:{line}: {message}")

    def headings_of(self, rel):
        if rel not in self.heading_cache:
            self.heading_cache[rel] = headings(os.path.join(self.root, rel))
        return self.heading_cache[rel]

    def normal(self, path):
        return os.path.normpath(path).replace(os.sep, "/")

    def resolve(self, citing, target):
        """The repository path `target` (as written in `citing`) names, or None."""
        here = os.path.dirname(citing)
        for candidate in (self.normal(os.path.join(here, target)), self.normal(target)):
            if candidate in self.file_set or candidate in self.dirs:
                return candidate
        if "/" not in target.rstrip("/"):
            matches = self.by_name.get(target, [])
            if len(matches) == 1:
                return matches[0]
        return None

    def check_section(self, where, number, page, after):
        m = SECTION_AFTER.match(after)
        if not m:
            return
        _, texts = self.headings_of(page)
        if m.group(1):
            wanted = m.group(1)
            if not any(re.match(rf"^{wanted}\.\s", t) for t in texts):
                self.fail(where, number, f"{page} has no section {wanted}")
        else:
            wanted = m.group(2).strip().lower()
            names = {re.sub(r"^\d+\.\s*", "", t).strip().lower() for t in texts}
            if wanted not in names:
                self.fail(where, number, f'{page} has no section "{m.group(2)}"')

    def check_tokens(self, rel, number, line, link_spans=()):
        for m in MD_TOKEN.finditer(line):
            if any(a <= m.start() < b for a, b in link_spans):
                continue
            token = m.group(1)
            name = os.path.basename(token)
            if name in OUTPUT_NAMES:
                continue
            before = line[:m.start()].split()
            if before and "://" in before[-1] and not line[m.start() - 1].isspace():
                continue  # part of a web address
            found = self.resolve(rel, token)
            if found is None:
                self.fail(rel, number, f"cites {token}, which is not in the repository")
            elif found in DESIGN_PAGES:
                self.check_section(rel, number, found, line[m.end():])

    def check_links(self, rel, number, line):
        spans = []
        for m in LINK.finditer(line):
            spans.append((m.start(), m.end()))
            target = m.group(1)
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                continue
            path, _, anchor = target.partition("#")
            page = rel
            if path:  # Markdown links are relative to the page's folder
                page = self.normal(os.path.join(os.path.dirname(rel), path))
                if page not in self.file_set and page not in self.dirs:
                    self.fail(rel, number, f"links to {path}, which is not in the repository")
                    continue
            if anchor and page.endswith(".md") and page in self.file_set:
                anchors, _ = self.headings_of(page)
                if anchor not in anchors:
                    self.fail(rel, number, f"links to #{anchor}, which is no heading of {page}")
        return spans

    def check_source(self, rel):
        with open(os.path.join(self.root, rel), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                self.check_tokens(rel, number, line)

    def check_markdown(self, rel):
        with open(os.path.join(self.root, rel), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                spans = self.check_links(rel, number, line)
                self.check_tokens(rel, number, line, spans)

    def check_front_door(self):
        readme = "README.md"
        if readme not in self.file_set:
            self.fail(readme, 0, "missing")
            return
        with open(os.path.join(self.root, readme), encoding="utf-8") as f:
            lines = f.read().splitlines()
        if len(lines) > README_MAX_LINES:
            self.fail(readme, len(lines), f"{len(lines)} lines; the front door has at most {README_MAX_LINES}")
        pages = [readme] + [f for f in self.files if f.startswith("scenarios/guides/") and f.endswith(".md")]
        for page in pages:
            with open(os.path.join(self.root, page), encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    for pattern, what in ((DATE, "a date"), (ISSUE, "an issue or stop number")):
                        m = pattern.search(line)
                        if m:
                            self.fail(page, number, f"{what} ({m.group(0)}) in a user page")

    def run(self):
        for rel in self.files:
            base = os.path.basename(rel)
            if rel == SELF:
                continue
            if rel.endswith(".md"):
                self.check_markdown(rel)
            elif rel.endswith(SOURCE_SUFFIXES) or base in SOURCE_NAMES:
                self.check_source(rel)
        self.check_front_door()
        return self.failures


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    root = os.path.abspath(sys.argv[1])
    failures = Checker(root).run()
    for failure in failures:
        print(failure)
    if failures:
        print(f"{len(failures)} citation problem(s)")
        return 1
    print("every cited document exists")
    return 0


if __name__ == "__main__":
    sys.exit(main())
