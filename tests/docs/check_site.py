#!/usr/bin/env python3
"""Checks a built MkDocs site for broken links: every relative href and src in every page must
name a file of the site, and every #fragment an id in the page it points to.

    tests/docs/check_site.py SITE_DIR

Links with a scheme (https:, mailto:) are listed, not followed: the guide is checked offline.
Exit status 1 with one line per broken link, naming the page and the link.
"""
import html.parser
import pathlib
import sys
import urllib.parse


class PageLinks(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.links, self.ids = [], set()

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name == "id" or (tag == "a" and name == "name"):
                self.ids.add(value)
            if name in ("href", "src") and value is not None:
                self.links.append(value)


def parse(path, cache={}):
    if path not in cache:
        parser = PageLinks()
        parser.feed(path.read_text(encoding="utf-8", errors="replace"))
        cache[path] = parser
    return cache[path]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    site = pathlib.Path(sys.argv[1]).resolve()
    pages = sorted(p for p in site.rglob("*.html") if "search" not in p.relative_to(site).parts)
    if not pages:
        sys.exit(f"{site}: no HTML pages (was the site built?)")
    broken, external, checked = [], set(), 0
    for page in pages:
        for link in parse(page).links:
            parts = urllib.parse.urlsplit(link)
            if parts.scheme or link.startswith("//"):
                external.add(link)
                continue
            checked += 1
            path = urllib.parse.unquote(parts.path)
            if not path:
                target = page
            elif path.startswith("/"):  # from the site's root (the 404 page's links)
                target = (site / path.lstrip("/")).resolve()
            else:
                target = (page.parent / path).resolve()
            if target.is_dir():
                target = target / "index.html"
            where = page.relative_to(site)
            if site not in target.parents and target != site:
                broken.append(f"{where}: {link}: points outside the site")
                continue
            if not target.is_file():
                broken.append(f"{where}: {link}: no such file in the site")
                continue
            if parts.fragment and target.suffix == ".html" and parts.fragment not in parse(target).ids:
                broken.append(f"{where}: {link}: no id '{parts.fragment}' in {target.relative_to(site)}")
    for line in broken:
        print(line)
    print(f"{len(pages)} pages, {checked} links checked, {len(broken)} broken, "
          f"{len(external)} external not followed", file=sys.stderr)
    sys.exit(1 if broken else 0)


if __name__ == "__main__":
    main()
