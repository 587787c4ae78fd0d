"""Does a render of lightmapped.glb match the solve's own render? Both EXRs from the same camera
and size: the solve's `--render direct` image, and the image of lightmapped.glb rendered in the
same mode, where every surface shows only its emissive texture (the lightmap) and reflects
nothing: what a plain glTF viewer shows.

Compared in 8 x 8 pixel blocks, leaving out blocks with a pixel brighter than the emissive
strength S (emitters: the file clips them there) and blocks darker than 2 % of it on average.
Per block, |lightmapped - reference| must stay within 5 standard errors of the reference
block's mean (its pixels' spread over their count: the pixels' noise and, conservatively, the
light's change across the block), plus half a step of the 8-bit sRGB encoding at the block's
level (what rounding can move a smooth region by), plus 1 % for the texels' averaging of the
light over their footprints.

Usage: lightmapped_render.py REFERENCE.exr LIGHTMAPPED.exr EMISSIVE_STRENGTH"""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench", "lib"))
from exr import read_exr  # noqa: E402

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])


def half_step(linear, strength):
    """Half an 8-bit step of the sRGB encoding of linear / strength, in linear units."""
    x = np.clip(linear / strength, 0.0, 1.0)
    s = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1.0 / 2.4) - 0.055)
    slope = np.where(s <= 0.04045, 1.0 / 12.92, 2.4 / 1.055 * np.power((s + 0.055) / 1.055, 1.4))
    return 0.5 / 255.0 * slope * strength


def main():
    reference = read_exr(sys.argv[1])[..., :3] @ LUMINANCE
    lightmapped = read_exr(sys.argv[2])[..., :3] @ LUMINANCE
    strength = float(sys.argv[3])
    if reference.shape != lightmapped.shape:
        sys.exit(f"images differ in size: {reference.shape} and {lightmapped.shape}")
    k = 8
    h, w = reference.shape[0] // k * k, reference.shape[1] // k * k
    blocks = lambda a: a[:h, :w].reshape(h // k, k, w // k, k).swapaxes(1, 2).reshape(h // k, w // k, k * k)
    ref, lit = blocks(reference), blocks(lightmapped)
    mean, other = ref.mean(axis=2), lit.mean(axis=2)
    error = ref.std(axis=2, ddof=1) / np.sqrt(k * k)
    kept = (ref.max(axis=2) < strength) & (mean > 0.02 * strength)
    bound = 5.0 * error + half_step(mean, strength) + 0.01 * mean
    bad = kept & (np.abs(other - mean) > bound)
    worst = np.max(np.abs(other - mean)[kept] / bound[kept])
    print(f"{kept.sum()} blocks compared of {kept.size}; worst |difference| / bound {worst:.3f}; "
          f"mean ratio {other[kept].sum() / mean[kept].sum():.4f}")
    if kept.sum() < 30:
        sys.exit("too few blocks to compare")
    if bad.any():
        for y, x in zip(*np.nonzero(bad)):
            print(f"block ({x}, {y}): reference {mean[y, x]:.5f} +- {error[y, x]:.5f}, lightmapped {other[y, x]:.5f}")
        sys.exit(f"{bad.sum()} blocks differ")


if __name__ == "__main__":
    main()
