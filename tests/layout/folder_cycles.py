#!/usr/bin/env python3
"""The host folders depend on one another in one direction: no chain of #include lines leads
from a folder back to itself (host/<a>/x includes "b/...", host/<b>/y includes "c/...", ...).
Prints each cycle's folders and the include lines that make it, and exits 1 if there is one.
Usage: folder_cycles.py HOST_DIR"""
import os
import re
import sys


def include_edges(host):
    edges = {}  # (from folder, to folder) -> first "file: line" that makes it
    for folder in sorted(os.listdir(host)):
        path = os.path.join(host, folder)
        if not os.path.isdir(path):
            continue
        for name in sorted(os.listdir(path)):
            if not os.path.isfile(os.path.join(path, name)):
                continue
            with open(os.path.join(path, name), errors="replace") as f:
                for line in f:
                    m = re.match(r'\s*#\s*include\s+"([A-Za-z0-9_]+)/', line)
                    if m and m.group(1) != folder and os.path.isdir(os.path.join(host, m.group(1))):
                        edges.setdefault((folder, m.group(1)), f"host/{folder}/{name}: {line.strip()}")
    return edges


def cycles(folders, edges):
    """Strongly connected components of more than one folder (Tarjan)."""
    after = {f: sorted(b for (a, b) in edges if a == f) for f in folders}
    index, low, stack, on, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in after[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for f in folders:
        if f not in index:
            visit(f)
    return found


def main():
    host = sys.argv[1]
    folders = sorted(f for f in os.listdir(host) if os.path.isdir(os.path.join(host, f)))
    edges = include_edges(host)
    bad = cycles(folders, edges)
    for component in bad:
        print("include cycle between " + ", ".join(component) + ":")
        for (a, b), where in sorted(edges.items()):
            if a in component and b in component:
                print(f"  {a} -> {b}  ({where})")
    if not bad:
        print(f"no include cycle among {len(folders)} folders ({len(edges)} folder-to-folder dependencies)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
