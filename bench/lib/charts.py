"""matplotlib (Debian's python3-matplotlib) without a display; every chart is written as PNG and SVG."""

import os

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
except ImportError:  # a machine without python3-matplotlib still writes the CSV files
    plt = None

from common import ROOT, log, replacing  # noqa: E402

if plt:
    plt.rcParams.update({"figure.dpi": 110, "savefig.dpi": 110, "font.size": 9, "axes.grid": True,
                         "grid.alpha": 0.3, "legend.fontsize": 8, "svg.hashsalt": "radiosity",
                         "path.simplify": False})
MARKERS = "osD^v<>ph*"


class _Nothing:
    """Stands in for figures and axes when matplotlib is missing: every call does nothing."""

    def __getattr__(self, name):
        if name == "get_legend_handles_labels":  # unpacked into two
            return lambda *args, **kwargs: ([], [])
        return self

    def __call__(self, *args, **kwargs):
        return self

    def __getitem__(self, index):
        return self

    def __iter__(self):
        return iter([self] * 3)


def figure(width=6.4, height=4.4, ncols=1, nrows=1):
    if plt is None:  # axes shaped as plt.subplots(squeeze=False) gives them, so they unpack alike
        return _Nothing(), [[_Nothing() for _ in range(ncols)] for _ in range(nrows)]
    return plt.subplots(nrows, ncols, figsize=(width, height), squeeze=False)


def save(fig, output, name, note=None, bottom=0.0):
    """output/name.png and .svg; `note`: a line under the chart saying how it was made;
    `bottom`: the share of the height kept free below the axes (for a figure legend)."""
    if plt is None:
        log("python3-matplotlib is missing: no chart", name)
        return
    if note:
        fig.text(0.01, 0.005, note, fontsize=6.5, color="0.35", ha="left", va="bottom")
    fig.tight_layout(rect=(0, max(bottom, 0.03 if note else 0.0), 1, 1))
    for ext in ("png", "svg"):
        with replacing(os.path.join(output, "%s.%s" % (name, ext))) as tmp:
            fig.savefig(tmp, format=ext, metadata={"Date": None} if ext == "svg" else None)
    plt.close(fig)
    path = os.path.join(output, name + ".png")
    log("wrote", os.path.relpath(path, ROOT) if os.path.abspath(path).startswith(ROOT) else path)


def pareto(points):
    """The points (x, y, ...) no other point beats on both x and y (lower is better), by x."""
    front, best = [], float("inf")
    for p in sorted(points, key=lambda p: (p[0], p[1])):
        if p[1] < best:
            front.append(p)
            best = p[1]
    return front
