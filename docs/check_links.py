#!/usr/bin/env python3
"""Check the relative links of README.md and docs/**/*.md.

Every [text](target) and ![alt](target) whose target is not a URL must name a file or
folder of the repository, relative to the page; a #fragment must be a heading of the
target page (GitHub's slugs). Links inside code spans and code blocks are ignored.
Usage: python3 docs/check_links.py   (exit 1 and one line per broken link)
"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
pages = [root / "README.md"] + sorted((root / "docs").rglob("*.md"))


def strip_code(text):
    text = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    text = re.sub(r"^(    |\t).*$", "", text, flags=re.M)  # indented code blocks
    return re.sub(r"`[^`\n]*`", "", text)


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)  # GitHub keeps letters, digits, _, - and spaces
    return s.replace(" ", "-")


def anchors(page):
    seen, out = {}, set()
    text = re.sub(r"^```.*?^```", "", page.read_text(encoding="utf-8"), flags=re.S | re.M)
    for line in text.splitlines():
        m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        base = slug(m.group(1).replace("`", ""))
        n = seen.get(base, 0)
        out.add(base if n == 0 else f"{base}-{n}")
        seen[base] = n + 1
    return out


link = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
html = re.compile(r"<(?:img|a)\s[^>]*?(?:src|href)=\"([^\"]+)\"")
broken = checked = 0
for page in pages:
    text = strip_code(page.read_text(encoding="utf-8"))
    for target in link.findall(text) + html.findall(text):
        if re.match(r"[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
            continue
        checked += 1
        path, _, fragment = target.partition("#")
        file = (page.parent / path).resolve() if path else page
        where = page.relative_to(root)
        if not file.exists():
            print(f"{where}: {target}: no such file")
            broken += 1
        elif fragment and file.suffix == ".md" and fragment not in anchors(file):
            print(f"{where}: {target}: no heading #{fragment} in {file.relative_to(root)}")
            broken += 1
print(f"{checked} relative links in {len(pages)} pages, {broken} broken", file=sys.stderr)
sys.exit(1 if broken else 0)
