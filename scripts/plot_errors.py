#!/usr/bin/env python3
"""Per-frame ATE error over time as an SVG, standard library only.

  scripts/plot_errors.py OUT.svg ERRORS.csv[=LABEL] [ERRORS.csv[=LABEL] ...] [--limit-m 0.05]

Each CSV comes from `dynanav eval --gt GT --est EST --errors ERRORS.csv` (stamp_s,ate_error_m).
Every run is a polyline in its own colour over seconds since the first stamp of all runs; a dashed
line marks --limit-m (issue 18: no burst above 5 cm); the legend gives each run's RMSE, maximum and
the frames above the limit.
"""
import argparse
import csv
import math
import sys

COLOURS = ["#4363d8", "#e6194b", "#3cb44b", "#f58231", "#911eb4", "#808000"]
WIDTH, HEIGHT, LEFT, RIGHT, TOP, BOTTOM = 900, 360, 60, 20, 20, 40


def read_errors(path):
    rows = []
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != ["stamp_s", "ate_error_m"]:
            sys.exit(f"{path}: not a 'dynanav eval --errors' CSV (header {reader.fieldnames})")
        for line, row in enumerate(reader, start=2):
            try:
                rows.append((float(row["stamp_s"]), float(row["ate_error_m"])))
            except (TypeError, ValueError):
                sys.exit(f"{path}:{line}: bad row {row}")
    if not rows:
        sys.exit(f"{path}: no rows")
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("svg")
    p.add_argument("runs", nargs="+", help="ERRORS.csv or ERRORS.csv=LABEL")
    p.add_argument("--limit-m", type=float, default=0.05)
    args = p.parse_args()
    runs = []
    for spec in args.runs:
        path, _, label = spec.partition("=")
        runs.append((label or path, read_errors(path)))
    t0 = min(r[0][0] for _, r in runs)
    t1 = max(r[-1][0] for _, r in runs)
    e_max = max(args.limit_m, max(e for _, r in runs for _, e in r)) * 1.1
    span = max(t1 - t0, 1e-9)

    def x(t):
        return LEFT + (t - t0) / span * (WIDTH - LEFT - RIGHT)

    def y(e):
        return HEIGHT - BOTTOM - e / e_max * (HEIGHT - TOP - BOTTOM)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>']
    step = 0.01 if e_max <= 0.08 else 0.02 if e_max <= 0.2 else 0.05
    k = 0
    while k * step <= e_max:
        yy = y(k * step)
        out.append(f'<line x1="{LEFT}" y1="{yy:.1f}" x2="{WIDTH - RIGHT}" y2="{yy:.1f}" '
                   f'stroke="#ddd"/><text x="{LEFT - 6}" y="{yy + 4:.1f}" text-anchor="end">'
                   f'{k * step * 100:.0f} cm</text>')
        k += 1
    for s in range(0, int(math.ceil(span)) + 1, max(1, int(math.ceil(span / 10)))):
        xx = x(t0 + s)
        out.append(f'<text x="{xx:.1f}" y="{HEIGHT - BOTTOM + 16}" text-anchor="middle">{s} s</text>')
    ly = y(args.limit_m)
    out.append(f'<line x1="{LEFT}" y1="{ly:.1f}" x2="{WIDTH - RIGHT}" y2="{ly:.1f}" '
               f'stroke="black" stroke-dasharray="6,4"/>')
    for i, (label, rows) in enumerate(runs):
        colour = COLOURS[i % len(COLOURS)]
        points = " ".join(f"{x(t):.1f},{y(e):.1f}" for t, e in rows)
        out.append(f'<polyline points="{points}" fill="none" stroke="{colour}" stroke-width="1.2"/>')
        errors = [e for _, e in rows]
        rmse = math.sqrt(sum(e * e for e in errors) / len(errors))
        above = sum(e > args.limit_m for e in errors)
        text = (f"{label}: RMSE {rmse * 100:.2f} cm, max {max(errors) * 100:.1f} cm, "
                f"{above} of {len(errors)} frames above {args.limit_m * 100:.0f} cm")
        out.append(f'<text x="{LEFT + 10}" y="{TOP + 14 + 16 * i}" fill="{colour}">'
                   f'{text.replace("&", "&amp;").replace("<", "&lt;")}</text>')
    out.append("</svg>")
    with open(args.svg, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
