#!/usr/bin/env python3
"""Figure and table of the granular-collapse series (called by scripts/collapse-series).

Reads the study.json of one `sphslope study` per aspect ratio and writes an SVG with two panels, the normalised
run-out (d - L0)/L0 and the normalised final height h_f/H0 against a = H0/L0, SPH (one marker per spacing) against
the true-2-D laws of Nguyen, Bui & Fukagawa (2015), arXiv:1512.05180, aluminium rods:
  (d - d0)/d0 = 3.25 a^0.96 (fitted for 0.65 < a < 1.5), 3.80 a^0.73 (a > 1.5);
  h_f/h0 = 1 (a < 0.65), 1/(1.42 a^(2/3)) above,
with the +-10 % band of the acceptance criterion (issue 14). Prints a Markdown table of the runs on stdout, then
the acceptance of each column at its finest spacing (d and h_f within 10 %, at least 20 particles across); exits
with 1 when a column misses it.
Usage: collapse_series_figure.py OUT.svg STUDY_FOLDER...
"""
import html
import json
import math
import os
import sys


def runout_law(a):
    return 3.25 * a ** 0.96 if a < 1.5 else 3.80 * a ** 0.73


def height_law(a):
    return 1.0 if a < 0.65 else 1.0 / (1.42 * a ** (2.0 / 3.0))


def load(folder):
    study = json.load(open(os.path.join(folder, "study.json")))
    p = study["parameters"]
    rows = []
    for run in study["runs"]:
        if run.get("status") != "ok" or run.get("values") is None or None in run["values"]:
            rows.append({"dx": run["particle_spacing_m"], "failed": run.get("errors") or run.get("status")})
            continue
        rows.append({"dx": run["particle_spacing_m"], "d": run["values"][0], "h": run["values"][1],
                     "steps": run["steps"], "wall": run["wall_seconds"], "stopped": run["stopped_because"]})
    return {"a": p["aspect_ratio"], "L0": p["initial_length_m"], "H0": p["initial_height_m"], "runs": rows}


class Panel:
    """One log-log (run-out) or log-linear (height) panel of the figure."""

    def __init__(self, x0, y0, w, h, xlim, ylim, ylog):
        self.x0, self.y0, self.w, self.h, self.xlim, self.ylim, self.ylog = x0, y0, w, h, xlim, ylim, ylog

    def px(self, a):
        lo, hi = (math.log10(v) for v in self.xlim)
        return self.x0 + (math.log10(a) - lo) / (hi - lo) * self.w

    def py(self, v):
        if self.ylog:
            lo, hi = (math.log10(t) for t in self.ylim)
            f = (math.log10(v) - lo) / (hi - lo)
        else:
            f = (v - self.ylim[0]) / (self.ylim[1] - self.ylim[0])
        return self.y0 + self.h - f * self.h


def polyline(panel, f, a_lo, a_hi, style):
    pts = []
    n = 60
    for k in range(n + 1):
        a = a_lo * (a_hi / a_lo) ** (k / n)
        pts.append(f"{panel.px(a):.1f},{panel.py(f(a)):.1f}")
    return f'<polyline points="{" ".join(pts)}" fill="none" {style}/>'


def band(panel, f, a_lo, a_hi, offset):
    """The +-10 % band of the criterion, on d = L0 (1 + f) (offset 1) or on h_f = H0 f (offset 0)."""
    up, down = [], []
    n = 60
    for k in range(n + 1):
        a = a_lo * (a_hi / a_lo) ** (k / n)
        up.append(f"{panel.px(a):.1f},{panel.py(1.1 * (f(a) + offset) - offset):.1f}")
        down.append(f"{panel.px(a):.1f},{panel.py(0.9 * (f(a) + offset) - offset):.1f}")
    return f'<polygon points="{" ".join(up + down[::-1])}" fill="#cfe3f7" stroke="none"/>'


def axes(panel, title, ylabel, yticks):
    out = [f'<rect x="{panel.x0}" y="{panel.y0}" width="{panel.w}" height="{panel.h}" fill="none" stroke="#333"/>',
           f'<text x="{panel.x0 + panel.w / 2}" y="{panel.y0 - 10}" font-size="14" text-anchor="middle">{title}</text>',
           f'<text x="{panel.x0 + panel.w / 2}" y="{panel.y0 + panel.h + 36}" font-size="13" '
           f'text-anchor="middle">aspect ratio a = H0/L0 (-)</text>',
           f'<text x="{panel.x0 - 48}" y="{panel.y0 + panel.h / 2}" font-size="13" text-anchor="middle" '
           f'transform="rotate(-90 {panel.x0 - 48} {panel.y0 + panel.h / 2})">{ylabel}</text>']
    for a in (0.5, 1, 2, 3, 4):
        x = panel.px(a)
        out.append(f'<line x1="{x:.1f}" y1="{panel.y0}" x2="{x:.1f}" y2="{panel.y0 + panel.h}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{panel.y0 + panel.h + 16}" font-size="12" text-anchor="middle">{a:g}</text>')
    for v in yticks:
        y = panel.py(v)
        out.append(f'<line x1="{panel.x0}" y1="{y:.1f}" x2="{panel.x0 + panel.w}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{panel.x0 - 6}" y="{y + 4:.1f}" font-size="12" text-anchor="end">{v:g}</text>')
    return out


MARKERS = ["circle", "square", "diamond", "triangle"]
COLOURS = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd"]


def marker(kind, x, y, colour):
    if kind == "circle":
        return f'<circle cx="{x:.1f}" cy="{y:.1f}" r="5" fill="{colour}"/>'
    if kind == "square":
        return f'<rect x="{x - 4.5:.1f}" y="{y - 4.5:.1f}" width="9" height="9" fill="{colour}"/>'
    if kind == "diamond":
        return f'<polygon points="{x:.1f},{y - 6:.1f} {x + 6:.1f},{y:.1f} {x:.1f},{y + 6:.1f} {x - 6:.1f},{y:.1f}" ' \
               f'fill="{colour}"/>'
    return f'<polygon points="{x:.1f},{y - 6:.1f} {x + 6:.1f},{y + 5:.1f} {x - 6:.1f},{y + 5:.1f}" fill="{colour}"/>'


def figure(cases, path):
    spacings = sorted({r["dx"] for c in cases for r in c["runs"]}, reverse=True)
    left = Panel(80, 60, 380, 360, (0.4, 5.0), (1.0, 20.0), True)
    right = Panel(580, 60, 380, 360, (0.4, 5.0), (0.0, 1.1), False)
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="1000" height="540" viewBox="0 0 1000 540" '
           'font-family="sans-serif">', '<rect width="100%" height="100%" fill="white"/>',
           '<text x="500" y="24" font-size="16" text-anchor="middle">Granular column collapse series (aluminium '
           'bars, Bui et al. 2008): SPH against the true-2-D laws</text>']
    settings = os.environ.get("SPH_SETTINGS", "").strip()
    step = "analyses.sph " + settings if settings not in ("", "{}") else "the scenes' own settings"
    out.append(f'<text x="80" y="532" font-size="12">SPH step and settings: {html.escape(step)}</text>')
    out.append(band(left, runout_law, 0.4, 5.0, 1.0))
    out.append(band(right, height_law, 0.4, 5.0, 0.0))
    out += axes(left, "run-out", "(d - L0)/L0 (-)", (1, 2, 5, 10, 20))
    out += axes(right, "final height", "h_f/H0 (-)", (0, 0.2, 0.4, 0.6, 0.8, 1.0))
    solid = 'stroke="#1f4e79" stroke-width="2"'
    dashed = 'stroke="#1f4e79" stroke-width="2" stroke-dasharray="6,4"'
    out.append(polyline(left, runout_law, 0.4, 0.65, dashed))  # extrapolated below the fitted range
    out.append(polyline(left, runout_law, 0.65, 1.5, solid))
    out.append(polyline(left, runout_law, 1.5, 5.0, solid))
    out.append(polyline(right, height_law, 0.4, 5.0, solid))
    for c in cases:
        for r in c["runs"]:
            if "d" not in r:
                continue
            k = spacings.index(r["dx"]) % len(MARKERS)
            out.append(marker(MARKERS[k], left.px(c["a"]), left.py((r["d"] - c["L0"]) / c["L0"]), COLOURS[k]))
            out.append(marker(MARKERS[k], right.px(c["a"]), right.py(r["h"] / c["H0"]), COLOURS[k]))
    y = 470
    out.append(f'<line x1="80" y1="{y}" x2="110" y2="{y}" {solid}/>')
    out.append(f'<text x="116" y="{y + 4}" font-size="12">Nguyen, Bui &amp; Fukagawa (2015), true-2-D aluminium rods '
               f'(dashed: extrapolated below a = 0.65); shaded: d and h_f within 10 %</text>')
    for k, dx in enumerate(spacings):
        x = 80 + 230 * k
        out.append(marker(MARKERS[k % len(MARKERS)], x + 15, y + 30, COLOURS[k % len(COLOURS)]))
        out.append(f'<text x="{x + 28}" y="{y + 34}" font-size="12">SPH, dx = {dx * 1000:g} mm</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def table(cases):
    print("| a | dx (mm) | particles across L0 | steps | wall (s) | d (m) | law | error | h_f (m) | law | error |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for c in sorted(cases, key=lambda c: c["a"]):
        d_law = c["L0"] * (1 + runout_law(c["a"]))
        h_law = c["H0"] * height_law(c["a"])
        for r in c["runs"]:
            across = round(c["L0"] / r["dx"])
            if "d" not in r:
                print(f"| {c['a']:g} | {r['dx'] * 1000:g} | {across} | failed: {r['failed']} |||||||")
                continue
            print(f"| {c['a']:g} | {r['dx'] * 1000:g} | {across} | {r['steps']} | {r['wall']:.0f} | {r['d']:.3f} | "
                  f"{d_law:.3f} | {100 * (r['d'] - d_law) / d_law:+.1f} % | {r['h']:.4f} | {h_law:.4f} | "
                  f"{100 * (r['h'] - h_law) / h_law:+.1f} % |")


def acceptance(cases, tolerance=0.10, least_across=20):
    """Each column's finest run against the laws; returns the list of columns that miss."""
    missed = []
    print(f"\nacceptance: d and h_f within {100 * tolerance:g} % at the finest spacing (>= {least_across} across)")
    for c in sorted(cases, key=lambda c: c["a"]):
        r = min(c["runs"], key=lambda r: r["dx"])
        across = round(c["L0"] / r["dx"])
        if "d" not in r:
            verdict = f"missed: the run failed ({r['failed']})"
        else:
            d_err = (r["d"] - c["L0"] * (1 + runout_law(c["a"]))) / (c["L0"] * (1 + runout_law(c["a"])))
            h_err = (r["h"] - c["H0"] * height_law(c["a"])) / (c["H0"] * height_law(c["a"]))
            ok = abs(d_err) <= tolerance and abs(h_err) <= tolerance and across >= least_across
            verdict = f"{'met' if ok else 'missed'}: d {100 * d_err:+.1f} %, h_f {100 * h_err:+.1f} %"
        print(f"- a = {c['a']:g} at {across} across: {verdict}")
        if not verdict.startswith("met"):
            missed.append(c["a"])
    return missed


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: collapse_series_figure.py OUT.svg STUDY_FOLDER...")
    cases = [load(f) for f in sys.argv[2:]]
    figure(cases, sys.argv[1])
    table(cases)
    missed = acceptance(cases)
    print(f"\nfigure: {sys.argv[1]}", file=sys.stderr)
    if missed:
        sys.exit("collapse_series_figure: the acceptance is missed at a = " + ", ".join(f"{a:g}" for a in missed))


if __name__ == "__main__":
    main()
