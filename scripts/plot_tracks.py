#!/usr/bin/env python3
"""Top view (world x right, z forward) of a run's tracked objects as an SVG, standard library only.

  scripts/plot_tracks.py OUT/objects.jsonl OUT/topview.svg [--trajectory OUT/trajectory.txt]
                         [--gt SEQ/objects_gt.jsonl] [--dynamic-only]

Each track is a polyline in its own colour, labelled with its id and median speed; the wearer's
camera path (TUM trajectory) is drawn in black, ground-truth objects (simulated runs) dashed grey.
"""
import argparse
import json
import statistics

COLOURS = ["#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#46f0f0", "#f032e6",
           "#bcf60c", "#008080", "#9a6324", "#800000", "#808000", "#000075"]


def read_tracks(path, dynamic_only):
    tracks = {}
    with open(path) as f:
        for line in f:
            if not line.strip():
                continue
            for o in json.loads(line)["objects"]:
                if dynamic_only and not o["dynamic"]:
                    continue
                t = tracks.setdefault(o["id"], {"cls": o["class"], "xz": [], "speed": []})
                t["xz"].append((o["position_world"][0], o["position_world"][2]))
                if o["dynamic"]:
                    t["speed"].append(o["speed"])
    return tracks


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("objects")
    p.add_argument("svg")
    p.add_argument("--trajectory")
    p.add_argument("--gt")
    p.add_argument("--dynamic-only", action="store_true")
    a = p.parse_args()
    tracks = read_tracks(a.objects, a.dynamic_only)
    gt = read_tracks(a.gt, False) if a.gt else {}
    cam = []
    if a.trajectory:
        with open(a.trajectory) as f:
            for line in f:
                v = line.split()
                if len(v) == 8 and not line.startswith("#"):
                    cam.append((float(v[1]), float(v[3])))
    pts = [q for t in list(tracks.values()) + list(gt.values()) for q in t["xz"]] + cam
    if not pts:
        pts = [(0.0, 0.0)]
    x0, x1 = min(q[0] for q in pts) - 0.5, max(q[0] for q in pts) + 0.5
    z0, z1 = min(q[1] for q in pts) - 0.5, max(q[1] for q in pts) + 0.5
    scale = 700.0 / max(x1 - x0, z1 - z0)
    w, h = (x1 - x0) * scale + 40, (z1 - z0) * scale + 60

    def px(q):  # z forward = up on the page
        return 20 + (q[0] - x0) * scale, 40 + (z1 - q[1]) * scale

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0f}" height="{h:.0f}">',
           '<rect width="100%" height="100%" fill="white"/>',
           f'<text x="20" y="20" font-family="sans-serif" font-size="13">top view (world x right, '
           f'z up the page), 1 m = {scale:.0f} px; {len(tracks)} tracks</text>']

    def polyline(xz, colour, extra=""):
        if len(xz) < 2:
            return
        d = " ".join(f"{px(q)[0]:.1f},{px(q)[1]:.1f}" for q in xz)
        out.append(f'<polyline points="{d}" fill="none" stroke="{colour}" stroke-width="2" {extra}/>')

    for t in gt.values():
        polyline(t["xz"], "#999999", 'stroke-dasharray="6,4"')
    polyline(cam, "#000000")
    for k, (tid, t) in enumerate(sorted(tracks.items())):
        c = COLOURS[k % len(COLOURS)]
        polyline(t["xz"], c)
        x, y = px(t["xz"][-1])
        v = statistics.median(t["speed"]) if t["speed"] else 0.0
        out.append(f'<text x="{x + 4:.1f}" y="{y:.1f}" font-family="sans-serif" font-size="11" '
                   f'fill="{c}">{t["cls"]} {tid}: {v:.2f} m/s</text>')
    out.append("</svg>")
    with open(a.svg, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
