#!/usr/bin/env python3
"""The same granular collapse computed by two methods, drawn on one figure: the deposits (free-surface profiles) of
the WC-MPS run and the SPH soil run read from the last VTK frame of each run folder, the initial column, and the
final run-out and height predicted by the 2-D scaling laws. Prints a table of both deposits.

Usage: scripts/side_by_side_figure.py SPACING_M MPS_RUN_DIR SPH_RUN_DIR OUT.svg [L0_M H0_M]

The scaling-law band: (L_inf - l0)/l0 = lambda a with lambda = 1.2 to 1.8 and a = h0/l0 (Lube et al. 2005 and
Lajeunesse et al. 2005 as quoted second-hand, whose quotes disagree), and the
height at the wall staying h0 for a below about 0.7.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from deposit_profile import profile, soil_points, toe  # noqa: E402


def deposit(run_dir, dx):
    pts = soil_points(run_dir)
    h, width = profile(pts, dx)
    xs = sorted((p[0] for p in pts), reverse=True)
    front = xs[-1]
    for k in range(len(xs) - 1):  # the farthest particle within 1.5 dx of the next one (strays excluded)
        if xs[k] - xs[k + 1] <= 1.5 * dx:
            front = xs[k]
            break
    wall = max((p[1] for p in pts if p[0] < 1.5 * dx), default=0.0) + dx / 2
    return {"h": h, "width": width, "front": front + dx / 2, "wall": wall, "toe2": toe(h, width, 2 * dx)}


def polyline(h, width, sx, sy):
    pts = []
    for b in range(0, max(h) + 1):
        y = h.get(b, 0.0)
        pts += ["%.1f,%.1f" % (sx(b * width), sy(y)), "%.1f,%.1f" % (sx((b + 1) * width), sy(y))]
    return " ".join(pts)


def main():
    if len(sys.argv) not in (5, 7):
        sys.exit(__doc__)
    dx = float(sys.argv[1])
    mps_dir, sph_dir, out = sys.argv[2], sys.argv[3], sys.argv[4]
    l0, h0 = (float(sys.argv[5]), float(sys.argv[6])) if len(sys.argv) == 7 else (0.1, 0.06)
    a = h0 / l0
    band = (l0 * (1 + 1.2 * a), l0 * (1 + 1.8 * a))
    mps, sph = deposit(mps_dir, dx), deposit(sph_dir, dx)
    keys = set(mps["h"]) | set(sph["h"])
    diff = sum(abs(mps["h"].get(k, 0.0) - sph["h"].get(k, 0.0)) for k in keys) / sum(sph["h"].values())
    print("| method | front (m) | toe, 2 dx thick (m) | height at the wall (m) | run-out (L - l0)/l0 |")
    print("|---|---|---|---|---|")
    for name, d in (("WC-MPS", mps), ("SPH soil", sph)):
        print("| %s | %.4f | %.4f | %.4f | %.2f |" % (name, d["front"], d["toe2"], d["wall"], (d["front"] - l0) / l0))
    print("| scaling laws (lambda 1.2 to 1.8) | %.3f to %.3f | | %.3f | %.2f to %.2f |" % (
        band[0], band[1], h0, 1.2 * a, 1.8 * a))
    print("profile difference |h_MPS - h_SPH| / h_SPH: %.1f %%" % (100 * diff))

    x_max = max(0.3, mps["front"], sph["front"]) * 1.05
    y_max = h0 * 1.25
    W, m, e = 900, 60, 1.5  # width [px], margin [px], vertical exaggeration
    k = (W - 2 * m) / x_max  # [px/m]
    H = int(2 * m + k * e * y_max) + 20

    def sx(x):
        return m + k * x

    def sy(y):
        return H - m - k * e * y  # vertical scale e x the horizontal

    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">' % (W, H),
         '<rect width="100%" height="100%" fill="white"/>',
         '<text x="%d" y="20" font-size="14">Dry granular collapse, a = %.2f (l0 = %.3g m, h0 = %.3g m), dx = %.4g m: '
         'final deposits</text>' % (m, a, l0, h0, dx),
         '<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="#eef" stroke="none"/>' % (
             sx(band[0]), sy(y_max * 0.95), sx(band[1]) - sx(band[0]), sy(0) - sy(y_max * 0.95)),
         '<text x="%.1f" y="%.1f" fill="#558">scaling laws: L&#8734;</text>' % (sx(band[0]), sy(y_max * 0.95) - 4),
         '<polyline points="%.1f,%.1f %.1f,%.1f %.1f,%.1f" fill="none" stroke="#999" stroke-dasharray="4 3"/>' % (
             sx(0), sy(h0), sx(l0), sy(h0), sx(l0), sy(0)),
         '<text x="%.1f" y="%.1f" fill="#777">initial column</text>' % (sx(l0) + 4, sy(h0) + 12),
         '<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="black"/>' % (sx(0), sy(0), sx(x_max), sy(0)),
         '<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="black"/>' % (sx(0), sy(0), sx(0), sy(y_max))]
    for name, d, colour in (("WC-MPS", mps, "#c33"), ("SPH soil", sph, "#36c")):
        s.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2"/>' % (polyline(d["h"], d["width"], sx, sy), colour))
    s.append('<text x="%.1f" y="%.1f" fill="#c33">WC-MPS: front %.3f m, height at the wall %.3f m</text>' % (
        sx(0.45 * x_max), sy(h0), mps["front"], mps["wall"]))
    s.append('<text x="%.1f" y="%.1f" fill="#36c">SPH soil: front %.3f m, height at the wall %.3f m</text>' % (
        sx(0.45 * x_max), sy(h0) + 16, sph["front"], sph["wall"]))
    for t in range(0, int(x_max / 0.05) + 1):
        x = 0.05 * t
        s.append('<text x="%.1f" y="%.1f" text-anchor="middle">%.2f</text>' % (sx(x), sy(0) + 16, x))
    s.append('<text x="%.1f" y="%.1f" text-anchor="middle">x (m); heights drawn 1.5 times the horizontal scale</text>' % (
        sx(x_max / 2), sy(0) + 34))
    for y in (0.0, h0 / 2, h0):
        s.append('<text x="%.1f" y="%.1f" text-anchor="end">%.3f</text>' % (sx(0) - 4, sy(y) + 4, y))
    s.append('</svg>')
    with open(out, "w") as f:
        f.write("\n".join(s) + "\n")
    print("figure: " + out)


if __name__ == "__main__":
    main()
