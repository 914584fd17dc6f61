#!/usr/bin/python3
"""Charts pt-bench converge CSVs: relative MSE against seconds, log-log, one line per method.

usage: bench/plot_convergence.py CSV [CSV...]   (writes CSV's name with .png)
Runs under Debian's /usr/bin/python3, which has matplotlib (python3-matplotlib).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLES = ["o-", "s-", "^-", "v-", "D-", "*-"]


def plot(path):
    rows = list(csv.DictReader(open(path)))
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for i, m in enumerate(methods):
        pts = [(float(r["seconds"]), float(r["rel_mse"])) for r in rows if r["method"] == m]
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], STYLES[i % len(STYLES)], label=m, markersize=4)
    name = os.path.basename(path).replace("converge_", "").replace(".csv", "")
    ax.set_title(f"{name}: error against render time")
    ax.set_xlabel("seconds (2 threads)")
    ax.set_ylabel("relative MSE vs. reference")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = path[:-4] + ".png"
    fig.savefig(out, dpi=90)
    print("wrote", out)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for p in sys.argv[1:]:
        plot(p)
