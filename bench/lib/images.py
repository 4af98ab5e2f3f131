"""PFM images and the error metric of the benchmarks, in plain Python (no numpy
on the build machines).

The metric is the one of bench/renderer/image_compare.cpp and the preview's
cross-validation tests: relative RMSE = sqrt(mean over pixels and channels of
(v - r)^2 / (r^2 + 0.01)), regularised so that black pixels do not dominate.
"""
from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from pathlib import Path

EPSILON = 1e-2


@dataclass
class Image:
    width: int
    height: int
    values: list[float]  # RGB, row after row, as stored in the file

    def mean(self) -> float:
        return sum(self.values) / len(self.values)


def read_pfm(path: Path) -> Image:
    data = Path(path).read_bytes()
    fields = data.split(b"\n", 3)
    if len(fields) < 4 or fields[0] != b"PF":
        raise ValueError(f"{path}: not an RGB PFM file")
    width, height = (int(v) for v in fields[1].split())
    scale = float(fields[2])
    count = width * height * 3
    order = "<" if scale < 0 else ">"
    values = list(struct.unpack(f"{order}{count}f", fields[3][: 4 * count]))
    return Image(width, height, values)


def average(images: list[Image]) -> Image:
    first = images[0]
    sums = [sum(v) / len(images) for v in zip(*(image.values for image in images))]
    return Image(first.width, first.height, sums)


def write_pfm(path: Path, image: Image) -> None:
    header = f"PF\n{image.width} {image.height}\n-1.0\n".encode()
    Path(path).write_bytes(header + struct.pack(f"<{len(image.values)}f", *image.values))


def relative_mse(image: Image, reference: Image) -> float:
    if (image.width, image.height) != (reference.width, reference.height):
        raise ValueError("image and reference differ in size")
    total = 0.0
    for v, r in zip(image.values, reference.values):
        total += (v - r) * (v - r) / (r * r + EPSILON)
    return total / len(image.values)


def relative_rmse(image: Image, reference: Image) -> float:
    return math.sqrt(relative_mse(image, reference))


def mean_ratio(image: Image, reference: Image) -> float:
    return image.mean() / reference.mean()


def corrected_rmse(image: Image, reference: Image, reference_mse: float) -> float:
    """Relative RMSE against the truth, estimated by removing the reference's
    own noise: an independent render and reference give
    E[measured^2] = error^2 + reference_mse."""
    return math.sqrt(max(0.0, relative_mse(image, reference) - reference_mse))


def half_difference_mse(half_a: Image, half_b: Image, reference: Image) -> float:
    """The mean squared (relative) noise of the average of two independent
    half references: Var(a - b) = 4 Var((a + b) / 2) for equal variances."""
    total = 0.0
    for a, b, r in zip(half_a.values, half_b.values, reference.values):
        total += (a - b) * (a - b) / (r * r + EPSILON)
    return total / len(reference.values) / 4.0
