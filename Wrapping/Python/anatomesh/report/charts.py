"""The report's charts (matplotlib, no display needed): the quality histogram and the 12 leads."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# The clinical layout: columns I-III, aVR-aVF, V1-V3, V4-V6.
LAYOUT = [["I", "aVR", "V1", "V4"], ["II", "aVL", "V2", "V5"], ["III", "aVF", "V3", "V6"]]


def _save(fig, path):
    """Saved under a temporary name and renamed: a failed write leaves no partial picture."""
    tmp = path + ".tmp%d.png" % os.getpid()
    try:
        fig.savefig(tmp, dpi=100)
        os.replace(tmp, path)
    finally:
        plt.close(fig)
        if os.path.exists(tmp):
            os.remove(tmp)


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


def ecg_leads(time, leads, path):
    """The 12 leads in the clinical 3 x 4 layout, all on one mV scale, time in ms."""
    t = np.asarray(time, dtype=float)
    values = [np.asarray(v, dtype=float) for v in leads.values()]
    lo = min(float(v.min()) for v in values) if values else -1.0
    hi = max(float(v.max()) for v in values) if values else 1.0
    pad = 0.05 * (hi - lo if hi > lo else 1.0)
    fig, axes = plt.subplots(3, 4, figsize=(12, 6.5), sharex=True, sharey=True)
    for r, row in enumerate(LAYOUT):
        for c, name in enumerate(row):
            ax = axes[r][c]
            if name in leads:
                ax.plot(t, leads[name], color="black", linewidth=1.0)
            ax.axhline(0.0, color="#bbbbbb", linewidth=0.6)
            ax.set_title(name, loc="left", fontsize=10)
            ax.grid(True, color="#f2c4c4", linewidth=0.5)
            if r == 2:
                ax.set_xlabel("ms")
            if c == 0:
                ax.set_ylabel("mV")
    axes[0][0].set_ylim(lo - pad, hi + pad)
    fig.suptitle("12-lead ECG (one shared scale: %.3g to %.3g mV)" % (lo, hi))
    fig.tight_layout()
    _save(fig, path)
