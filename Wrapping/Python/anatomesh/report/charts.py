"""The report's charts (matplotlib, no display needed): the quality histogram and the 12 leads."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .. import atomic  # noqa: E402

# The clinical layout: columns I-III, aVR-aVF, V1-V3, V4-V6.
LAYOUT = [["I", "aVR", "V1", "V4"], ["II", "aVL", "V2", "V5"], ["III", "aVF", "V3", "V6"]]


def _save(fig, path):
    """Saved under a temporary name and renamed: a failed write leaves no partial picture."""
    try:
        with atomic.replacing(path) as tmp:
            fig.savefig(tmp, dpi=100, format="png")
    finally:
        plt.close(fig)


def quality_histogram(quality, path, bar=10.0):
    """Counts of tetrahedra per quality Q (1 is the regular tetrahedron), log-log, with the bar."""
    q = np.asarray(quality, dtype=float)
    q = q[np.isfinite(q)]
    fig, ax = plt.subplots(figsize=(8, 4.2))
    top = max(float(q.max()) if q.size else 1.0, bar) * 1.05
    bins = np.geomspace(1.0, top, 60)
    ax.hist(np.clip(q, 1.0, None), bins=bins, color="#4c72b0")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axvline(bar, color="#c44e52", linestyle="--")
    ax.text(bar, ax.get_ylim()[1] * 0.5, " Q = %g" % bar, color="#c44e52", va="top")
    ax.set_xlabel("quality Q = (sqrt 6 / 12) longest edge / inradius (1: the regular tetrahedron)")
    ax.set_ylabel("tetrahedra")
    ax.set_title("%d tetrahedra: mean Q %.3f, worst %.2f, %d above %g" % (
        q.size, q.mean() if q.size else 0, q.max() if q.size else 0, int((q > bar).sum()), bar))
    fig.tight_layout()
    _save(fig, path)


def ecg_leads(time, leads, path, rate=75.0, strip=2500.0):
    """The 12 leads on standard ECG paper: 25 mm/s and 10 mm/mV, 1 mm squares (40 ms, 0.1 mV) and
    5 mm squares, in the clinical 3 x 4 layout. The simulated beat is repeated at 'rate' beats per
    minute (at rest between beats) over a 'strip' ms strip per lead, as an electrocardiograph prints."""
    t = np.asarray(time, dtype=float)
    values = {name: np.asarray(v, dtype=float) for name, v in leads.items()}
    lo = min([float(v.min()) for v in values.values()] + [-1.5])
    hi = max([float(v.max()) for v in values.values()] + [1.5])
    lo, hi = np.floor(lo * 2 - 1) / 2, np.ceil(hi * 2 + 1) / 2  # whole 5 mm squares, a margin of one
    period = max(60000.0 / rate, float(t[-1]) if t.size else 0.0)
    grid_t = np.arange(0.0, strip + 1e-9, 4.0)
    mm = 1 / 25.4  # inches
    panel_w, panel_h = strip * 0.025, (hi - lo) * 10.0  # mm
    fig, axes = plt.subplots(3, 4, figsize=(4 * panel_w * mm + 0.6, 3 * panel_h * mm + 0.7), squeeze=False)
    for r, row in enumerate(LAYOUT):
        for c, name in enumerate(row):
            ax = axes[r][c]
            for x in np.arange(0.0, strip + 1e-9, 40.0):
                ax.axvline(x, color="#f6caca" if x % 200 else "#e48a8a", linewidth=0.3 if x % 200 else 0.7)
            for y in np.arange(lo, hi + 1e-9, 0.1):
                major = abs(y * 2 - round(y * 2)) < 1e-6
                ax.axhline(y, color="#e48a8a" if major else "#f6caca", linewidth=0.7 if major else 0.3)
            if name in values and t.size:
                phase = np.mod(grid_t, period)
                ax.plot(grid_t, np.interp(phase, t, values[name], right=0.0), color="black", linewidth=0.8)
            ax.set_xlim(0, strip)
            ax.set_ylim(lo, hi)
            ax.set_aspect(400.0)  # 1 mV (10 mm) as long as 400 ms (10 mm at 25 mm/s)
            ax.set_xticks([])
            ax.set_yticks([])
            ax.text(20, hi - 0.15, name, fontsize=8, va="top")
    fig.suptitle("12-lead ECG, 25 mm/s, 10 mm/mV (the beat repeated at %g per minute)" % rate, fontsize=9)
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.93, wspace=0.02, hspace=0.04)
    _save(fig, path)
