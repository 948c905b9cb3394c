#!/usr/bin/env python3
"""The viscosity of a WC-MPS granular run drawn at a few times, one panel each (the counterpart of the paper's Fig. 14,
seed section 7-5): every grain a square of the run's spacing coloured by log10 of its viscosity, from 0.1 Pa s
(flowing) to the viscosity cap (unyielded), read from the VTK frames nearest the requested times.

Usage: scripts/unyielded_zone_figure.py RUN_DIR OUT.svg [TIME_S ...]   (times default: 0.05 0.1 0.2 0.4)

The spacing and the cap come from RUN_DIR/report.json (mps.particle_spacing_m, mps.viscosity_cap_Pa_s).
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from deposit_profile import frame_time, read_vtu, run_frames  # noqa: E402

MU_LOW = 0.1  # [Pa s], the low end of the colour scale
X_MAX, Y_MAX = 0.22, 0.065  # the drawn part of the tank [m]
SCALE = 2400.0  # pixels per metre
PANEL_H = Y_MAX * SCALE + 30


def colour(mu, cap):
    """Blue (flowing, MU_LOW or less) through white to red (the cap), linear in log10(mu)."""
    s = (math.log10(max(mu, MU_LOW)) - math.log10(MU_LOW)) / (math.log10(cap) - math.log10(MU_LOW))
    s = min(max(s, 0.0), 1.0)
    if s < 0.5:
        t = s / 0.5
        r, g, b = 40 + 215 * t, 90 + 165 * t, 200 + 55 * t
    else:
        t = (s - 0.5) / 0.5
        r, g, b = 255 - 45 * t, 255 - 215 * t, 255 - 215 * t
    return "#%02x%02x%02x" % (int(r), int(g), int(b))


def panel(frame, top, dx, cap):
    a = read_vtu(frame, ("Points", "kind", "viscosity"))
    out = ['<text x="10" y="%.0f" font-size="13">t = %.2f s</text>' % (top + 14, frame_time(frame))]
    base = top + PANEL_H - 6  # y = 0 (the floor) in pixels
    side = dx * SCALE
    for p, k, mu in zip(a["Points"], a["kind"], a["viscosity"]):
        if k != 0 or p[0] > X_MAX:
            continue
        out.append('<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s"/>' % (
            20 + (p[0] - dx / 2) * SCALE, base - (p[1] + dx / 2) * SCALE, side, side, colour(mu, cap)))
    out.append('<line x1="20" y1="%.1f" x2="%.1f" y2="%.1f" stroke="black"/>' % (base, 20 + X_MAX * SCALE, base))
    out.append('<line x1="20" y1="%.1f" x2="20" y2="%.1f" stroke="black"/>' % (base, base - Y_MAX * SCALE))
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    run, svg = sys.argv[1], sys.argv[2]
    times = [float(t) for t in sys.argv[3:]] or [0.05, 0.1, 0.2, 0.4]
    mps = json.load(open(os.path.join(run, "report.json")))["mps"]
    dx, cap = mps["particle_spacing_m"], mps.get("viscosity_cap_Pa_s", 200.0)
    frames = [(frame_time(f), f) for f in run_frames(run)]
    width = 40 + X_MAX * SCALE
    body = []
    for n, t in enumerate(times):
        nearest = min(frames, key=lambda tf: abs(tf[0] - t))[1]
        body += panel(nearest, n * PANEL_H, dx, cap)
    legend_top = len(times) * PANEL_H + 10
    for k in range(11):
        mu = MU_LOW * (cap / MU_LOW) ** (k / 10)
        body.append('<rect x="%.0f" y="%.0f" width="30" height="12" fill="%s"/>' % (20 + 30 * k, legend_top,
                                                                                   colour(mu, cap)))
    body.append('<text x="20" y="%.0f" font-size="12">viscosity (log scale): %g Pa s (flowing) to the cap, %g Pa s '
                '(unyielded); grains of %g mm; x to %g m, y to %g m</text>' % (
                    legend_top + 28, MU_LOW, cap, 1000 * dx, X_MAX, Y_MAX))
    height = legend_top + 40
    with open(svg, "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="%.0f" height="%.0f" font-family="sans-serif">\n' % (
            width, height))
        f.write('<rect width="100%" height="100%" fill="white"/>\n')
        f.write("\n".join(body))
        f.write("\n</svg>\n")
    print("unyielded_zone_figure: %s (%d panels)" % (svg, len(times)))


if __name__ == "__main__":
    main()
