"""Image error against a reference made of two independent halves (bench/render_modes,
bench/mitsuba_compare)."""

import math

import numpy as np


def image_errors(image, half1, half2):
    """(relative RMSE, RMSE over mean, the reference's relative noise), over all pixels and
    channels, each less the reference's own noise (the halves differ by twice it:
    mean((P1 - P2)^2) / 4 estimates its variance, which inflates the squared error by just that
    much):
        relative RMSE     sqrt(mean( (x - P)^2 / (P + g)^2 )), g = 1 % of the image mean;
        RMSE over mean    sqrt(mean( (x - P)^2 )) / mean(P)."""
    image = np.asarray(image, dtype=np.float64)[..., :3]
    half1 = np.asarray(half1, dtype=np.float64)[..., :3]
    half2 = np.asarray(half2, dtype=np.float64)[..., :3]
    p = 0.5 * (half1 + half2)
    guard = 0.01 * np.mean(p)
    noise = (half1 - half2) ** 2 / 4.0
    relative = np.mean(((image - p) ** 2 - noise) / (p + guard) ** 2)
    over_mean = (np.mean((image - p) ** 2) - np.mean(noise)) / np.mean(p) ** 2
    reference = np.mean(noise / (p + guard) ** 2)
    return math.sqrt(max(relative, 0.0)), math.sqrt(max(over_mean, 0.0)), math.sqrt(reference)
