#!/usr/bin/env python3
"""Checks the documentation: README.md's length, every path and link in README.md
and docs/**/*.md, and that no file cites the project's specification as if it
were in the repository.

usage: scripts/docs/check_docs.py [--only readme-length|links|citations]

  readme-length  README.md has at most 300 lines
  links          every markdown link [text](target) resolves (a file or folder
                 relative to the page, and a #anchor to a heading of the target
                 page), and every repository path written as code (`rtl/foo.sv`,
                 in a code span or a code block, starting with rtl/ hls/ models/
                 tb/ tests/ scripts/ docs/ cmake/ .ci/ or ../shared/) exists; a
                 placeholder such as rtl/<core>.sv must match at least one file.
                 Paths under build*/ are outputs and are not checked. Papers are
                 named by their alias (docs/papers.md maps aliases to files):
                 a paper's file name appears only in docs/papers.md and
                 docs/data/papers.json.
  citations      no file of the repository cites DESIGN.md or ACCEPTANCE.md
                 (the project's specification, outside the repository; also by
                 the bare name, "ACCEPTANCE 004") other than by a path that
                 leads outside it (../shared/spec/...).
                 KNOWN lists the citations in code comments the lead removes:
                 a citation not listed there fails.

Exit status: 0 all good, 1 a check failed (each problem named), 2 bad usage.
"""
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAX_README_LINES = 300

# Citations of the specification allowed, path -> number of lines citing it (none).
KNOWN = {}
# Files exempt: this checker.
EXEMPT = {"scripts/docs/check_docs.py"}
# DESIGN.md, ACCEPTANCE.md, or the bare name ("ACCEPTANCE 004", "ACCEPTANCE's bound").
SPEC = re.compile(r"(\S*?)\b(DESIGN|ACCEPTANCE)\b(\.md)?")
PAPER_FILE = re.compile(r"\b\d{3}_[0-9a-f]{16}\.txt")
PAPER_PAGES = {"docs/papers.md"}

LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
CODE_SPAN = re.compile(r"(`+)(.+?)\1", re.S)
FENCE = re.compile(r"^(```|~~~)")
REPO_PATH = re.compile(r"(?<![\w./$-])(?:\.\./shared/|\.ci/|(?:rtl|hls|models|tb|tests|scripts|docs|cmake)/)"
                       r"[\w./<>*+-]*")


def documents():
    out = [os.path.join(ROOT, "README.md")]
    out += sorted(glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))
    return out


def rel(path):
    return os.path.relpath(path, ROOT)


def check_readme_length(problems):
    with open(os.path.join(ROOT, "README.md")) as f:
        n = len(f.read().splitlines())
    if n > MAX_README_LINES:
        problems.append("README.md has %d lines, more than %d: move a topic to docs/"
                        % (n, MAX_README_LINES))


def slug(heading):
    """GitHub's anchor of a heading."""
    text = re.sub(r"[`*_]|<[^>]+>", lambda m: "_" if m.group(0) == "_" else "", heading.strip())
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    return re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")


def anchors(path):
    seen, out = {}, set()
    in_fence = False
    with open(path) as f:
        for line in f:
            if FENCE.match(line):
                in_fence = not in_fence
                continue
            m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m and not in_fence:
                s = slug(m.group(1))
                n = seen.get(s, 0)
                seen[s] = n + 1
                out.add(s if n == 0 else "%s-%d" % (s, n))
    return out


def code_texts(text):
    """(line number, text) of every code span and code block of a markdown page."""
    out = []
    lines = text.splitlines()
    in_fence, prose = False, []
    for i, line in enumerate(lines, 1):
        if FENCE.match(line.strip()):
            in_fence = not in_fence
            continue
        if in_fence or (line.startswith("    ") and (i == 1 or not lines[i - 2].strip()
                                                     or lines[i - 2].startswith("    "))):
            out.append((i, line))
        else:
            prose.append((i, line))
    # Code spans may not cross paragraphs; joining lines keeps their line of start.
    offsets, buf = [], ""
    for i, line in prose:
        offsets.append((len(buf), i))
        buf += line + "\n"
    for m in CODE_SPAN.finditer(buf):
        start = m.start()
        line_no = max(i for off, i in offsets if off <= start)
        out.append((line_no, m.group(2)))
    return out


def trim(token):
    """A path token without the punctuation around it."""
    while token and (token[-1] in ".,;:)'\"`" or (token[-1] == ">" and token.count(">") > token.count("<"))):
        token = token[:-1]
    return token


def exists(path_from_root):
    pattern = re.sub(r"<[^>]*>", "*", path_from_root)
    full = os.path.normpath(os.path.join(ROOT, pattern))
    if "*" in pattern:
        return bool(glob.glob(full))
    return os.path.exists(full)


def check_links(problems):
    for path in documents():
        r = rel(path)
        with open(path) as f:
            text = f.read()
        base = os.path.dirname(path)
        # Markdown links (outside code).
        stripped = re.sub(r"```.*?```", "", text, flags=re.S)
        stripped = CODE_SPAN.sub("", stripped)
        for m in LINK.finditer(stripped):
            target = m.group(1)
            if re.match(r"^[a-z]+:", target):
                continue
            file_part, _, anchor = target.partition("#")
            dest = os.path.normpath(os.path.join(base, file_part)) if file_part else path
            if not os.path.exists(dest):
                problems.append("%s: link to %s: no such file" % (r, target))
                continue
            if anchor:
                if not dest.endswith(".md"):
                    problems.append("%s: link to %s: an anchor into a file that is not markdown"
                                    % (r, target))
                elif anchor not in anchors(dest):
                    problems.append("%s: link to %s: %s has no heading with that anchor"
                                    % (r, target, rel(dest)))
        # Repository paths written as code.
        for line_no, code in code_texts(text):
            for m in REPO_PATH.finditer(code):
                token = trim(m.group(0))
                if not exists(token):
                    problems.append("%s:%d: `%s` does not exist in the repository" % (r, line_no, token))
        # Papers by alias.
        if r not in PAPER_PAGES:
            for m in PAPER_FILE.finditer(text):
                problems.append("%s: names the paper file %s; name the paper by its alias "
                                "(docs/papers.md)" % (r, m.group(0)))


def repository_files():
    try:
        out = subprocess.run(["git", "-C", ROOT, "ls-files", "--cached", "--others",
                              "--exclude-standard"], capture_output=True, text=True, check=True)
        return [l for l in out.stdout.splitlines() if l]
    except (OSError, subprocess.CalledProcessError):
        skip = ("build", ".venv", ".git")
        return [rel(p) for p in glob.glob(os.path.join(ROOT, "**", "*"), recursive=True)
                if os.path.isfile(p) and not rel(p).startswith(skip)]


def check_citations(problems):
    found = {}
    for f in repository_files():
        full = os.path.join(ROOT, f)
        if not os.path.isfile(full):
            continue
        try:
            with open(full, encoding="utf-8") as fh:
                lines = fh.read().splitlines()
        except (UnicodeDecodeError, OSError):
            continue
        for i, line in enumerate(lines, 1):
            for m in SPEC.finditer(line):
                where = m.group(1)
                if where.lstrip("`(\"'").startswith("../shared/spec/"):
                    continue
                if f in EXEMPT:
                    continue
                found.setdefault(f, []).append((i, line.strip()))
    for f, hits in sorted(found.items()):
        if f in KNOWN and len(hits) <= KNOWN[f]:
            continue
        for i, line in hits:
            problems.append("%s:%d cites the specification as if it were in the repository "
                            "(it is not; say what the code does instead): %s" % (f, i, line[:100]))
    gone = [f for f in KNOWN if f not in found]
    for f in gone:
        sys.stdout.write("check_docs: note: %s no longer cites the specification; remove it from "
                         "KNOWN in scripts/docs/check_docs.py\n" % f)


CHECKS = {"readme-length": check_readme_length, "links": check_links,
          "citations": check_citations}


def main(argv):
    only = None
    args = list(argv[1:])
    while args:
        a = args.pop(0)
        if a == "--only" and args:
            only = args.pop(0)
            if only not in CHECKS:
                sys.stderr.write("check_docs: unknown check '%s' (one of %s)\n"
                                 % (only, ", ".join(CHECKS)))
                return 2
        elif a in ("-h", "--help"):
            sys.stdout.write(__doc__)
            return 0
        else:
            sys.stderr.write("check_docs: unknown argument '%s'\n" % a)
            return 2
    problems = []
    for name, fn in CHECKS.items():
        if only in (None, name):
            fn(problems)
    for p in problems:
        sys.stderr.write("check_docs: %s\n" % p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
