#!/usr/bin/env python3
"""Checks the links of the built guide (docs/guide/book/).

Every relative `href` and `src` in every HTML page of the guide must name an existing file,
and every `#fragment` must name an `id` (or `<a name>`) in the page it points to. External
links (http:, https:, mailto:, and other schemes) are skipped. Links into `api/` (the rustdoc
output copied into book/api/ after `mdbook build`) are checked like any other; the pages under
book/api/ themselves are rustdoc's and are not checked.

Usage: python3 docs/guide/check_links.py [BOOK_DIR]     (default: the book/ next to this file)

Exits with 1, listing every broken link as `page: link (reason)`, or prints how many links it
checked and exits with 0. Standard library only.
"""

import os
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlsplit


class _Page(HTMLParser):
    """Collects the links (href/src) and the anchors (id/name) of one HTML page."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.links = []
        self.anchors = set()
        self.base = None

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value is None:
                continue
            if tag == "base" and name == "href":
                self.base = value  # mdBook's 404 page: links resolve against site-url
            elif name in ("href", "src"):
                self.links.append(value)
            elif name == "id" or (name == "name" and tag == "a"):
                self.anchors.add(value)

    handle_startendtag = handle_starttag


def _parse(path):
    page = _Page()
    with open(path, encoding="utf-8", errors="replace") as f:
        page.feed(f.read())
    page.close()
    return page


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    book = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(here, "book"))
    if not os.path.isdir(book):
        print(f"no built book at {book}: run `mdbook build docs/guide` first", file=sys.stderr)
        return 2
    api = os.path.join(book, "api")
    pages = []
    for root, dirs, files in os.walk(book):
        if os.path.abspath(root) == book and "api" in dirs:
            dirs.remove("api")  # rustdoc's own pages
        dirs.sort()
        pages.extend(os.path.join(root, f) for f in sorted(files) if f.endswith(".html"))

    cache = {}

    def anchors_of(path):
        if path not in cache:
            cache[path] = _parse(path).anchors
        return cache[path]

    broken = []
    checked = 0
    for page in pages:
        parsed = _parse(page)
        cache[page] = parsed.anchors
        for link in parsed.links:
            parts = urlsplit(link)
            if parts.scheme or parts.netloc or link.startswith("//"):
                continue  # external (http, https, mailto, data, javascript, …)
            if not parts.path and not parts.fragment:
                continue  # "" or "?query": the page itself
            checked += 1
            rel = os.path.relpath(page, book)
            # A <base href="/…"> (mdBook's site-url, "/" by default) stands for the book's
            # root where the book is served; other absolute paths are errors.
            based = parsed.base is not None and urlsplit(parsed.base).path.startswith("/")
            if not based and parts.path.startswith("/"):
                broken.append((rel, link, "absolute path: links must be relative"))
                continue
            if based:
                base_dir = os.path.join(book, urlsplit(parsed.base).path.lstrip("/"))
                # (a bare "#fragment" is taken as the page's own, as mdBook means it)
                path = parts.path.lstrip("/")
            else:
                base_dir = os.path.dirname(page)
                path = parts.path
            target = page
            if path:
                target = os.path.normpath(os.path.join(base_dir, unquote(path)))
                if os.path.isdir(target):
                    target = os.path.join(target, "index.html")
                if os.path.relpath(target, book).startswith(".."):
                    broken.append((rel, link, "points outside the book"))
                    continue
                if not os.path.isfile(target):
                    reason = "no such file"
                    if target.startswith(api + os.sep) and not os.path.isdir(api):
                        reason += " (book/api/ is missing: copy target/doc there first)"
                    broken.append((rel, link, reason))
                    continue
            fragment = unquote(parts.fragment)
            if fragment and target.endswith((".html", ".htm")):
                if fragment not in anchors_of(target):
                    broken.append((rel, link, f"no id {fragment!r} in {os.path.relpath(target, book)}"))

    if broken:
        print(f"{len(broken)} broken link(s) in {len(pages)} page(s):")
        for rel, link, reason in broken:
            print(f"  {rel}: {link} ({reason})")
        return 1
    print(f"{checked} links checked in {len(pages)} pages of {book}: all resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
