"""Log-log plots of error against time, drawn by gnuplot (Debian's gnuplot-nox),
written as small PNGs for docs/img/."""
from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path


def available() -> bool:
    return shutil.which("gnuplot") is not None


def loglog(output: Path, title: str, series: dict[str, list[tuple[float, float]]],
           xlabel: str = "CPU seconds", ylabel: str = "relative RMSE") -> bool:
    """Draws each series (label -> [(x, y)], points joined in order) on
    log-log axes. Returns False, drawing nothing, when gnuplot is missing."""
    if not available():
        return False
    output.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        plots = []
        for index, (label, points) in enumerate(series.items()):
            points = [(x, y) for x, y in points if x > 0 and y > 0]
            if not points:
                continue
            data = Path(tmp) / f"series{index}.dat"
            data.write_text("".join(f"{x:.6g} {y:.6g}\n" for x, y in points))
            plots.append(f"'{data}' using 1:2 with linespoints title '{label}'")
        if not plots:
            return False
        script = "\n".join([
            "set terminal pngcairo enhanced size 640,420 font ',9'",
            f"set output '{output}'",
            f"set title '{title}'",
            "set logscale xy",
            f"set xlabel '{xlabel}'",
            f"set ylabel '{ylabel}'",
            "set key bottom left",
            "set format x '10^{%L}'",
            "set format y '10^{%L}'",
            "set grid",
            "plot " + ", ".join(plots),
        ])
        subprocess.run(["gnuplot"], input=script.encode(), check=True)
    return True
