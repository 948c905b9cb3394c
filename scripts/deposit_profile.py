#!/usr/bin/env python3
"""The deposit of a granular run, read from the last VTK frame of run folders (frames/frame_*.vtu, written by
sphslope; appended raw binary, no third-party modules): the free-surface profile (highest soil particle edge in
bins two spacings wide), the toe where the deposit is at least 1, 2 and 5 spacings thick, the front (third-furthest
soil particle) and each profile's difference from the first folder's, the integral of |h - h_ref| over that of h_ref.

Usage: scripts/deposit_profile.py SPACING_M RUN_DIR [RUN_DIR ...]

With --toes, for runs at different spacings (each run's spacing from its report.json): the toe where the deposit
is at least 5, 10 and 20 mm thick, in bins 10 mm wide for every run, beside the report's front and the top:
       scripts/deposit_profile.py --toes RUN_DIR [RUN_DIR ...]

With --track, the N soil particles furthest downstream in the last frame followed back through every frame: their
mean position, height and x-velocity and how many of them carry no stress (the front's history):
       scripts/deposit_profile.py --track N RUN_DIR

With --region, for a WC-MPS run: the grains that start in the box X0 < x < X1, Y0 < y < Y1 [m] followed through
every frame: their mean viscosity [Pa s], mean p' (smoothed_pressure) [Pa] and mean displacement [mm]:
       scripts/deposit_profile.py --region X0 X1 Y0 Y1 RUN_DIR

With --unyielded, for a WC-MPS run: in every frame and in bins of x WIDTH [m] wide, the top of the material and the
lowest and highest grain whose viscosity is at least MU [Pa s] (unyielded: at or near the viscosity cap) [m], and
the grains above the highest unyielded one that are yielded (the shape of the unyielded zone, seed Fig. 14):
       scripts/deposit_profile.py --unyielded MU WIDTH RUN_DIR
"""
import json
import glob
import re
import struct
import sys

TYPES = {"Float64": "d", "Int64": "q", "UInt8": "B", "Int32": "i", "UInt32": "I"}
ARRAY = re.compile(rb'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" format="appended" '
                   rb'offset="(\d+)"')


def read_vtu(path, wanted=("Points", "kind")):
    raw = open(path, "rb").read()
    head, _, data = raw.partition(b'<AppendedData encoding="raw">')
    data = data[data.index(b"_") + 1:]
    arrays = {}
    for m in ARRAY.finditer(head):
        kind, name, comps, offset = m.group(1).decode(), m.group(2).decode(), int(m.group(3)), int(m.group(4))
        if name not in wanted:
            continue
        size = struct.unpack_from("<Q", data, offset)[0]
        code = TYPES[kind]
        count = size // struct.calcsize(code)
        values = struct.unpack_from("<%d%s" % (count, code), data, offset + 8)
        arrays[name] = [values[i * comps:(i + 1) * comps] for i in range(count // comps)] if comps > 1 else values
    return arrays


def soil_points(run_dir):
    frames = sorted(glob.glob(run_dir + "/frames/frame_*.vtu"))
    if not frames:
        sys.exit("deposit_profile: no frames/frame_*.vtu in " + run_dir)
    a = read_vtu(frames[-1])
    return [p for p, k in zip(a["Points"], a["kind"]) if k == 0]


def profile(points, dx, width=None):
    width = width or 2 * dx
    h = {}
    for p in points:
        b = int(p[0] // width)
        h[b] = max(h.get(b, 0.0), p[1] + dx / 2)
    return h, width


def toe(h, width, thickness):
    b = 0
    while h.get(b, 0.0) >= thickness:
        b += 1
    return b * width


def toes_at_thickness(runs, width=0.01, thicknesses=(0.005, 0.01, 0.02)):
    """Toes at fixed thicknesses [m] in bins of one width [m] for every run, whatever its spacing."""
    print("| run | dx (mm) | report front (m) | " + " | ".join("toe, %g mm thick (m)" % (1000 * t) for t in thicknesses)
          + " | top (m) |")
    print("|---|---|---|" + "---|" * len(thicknesses) + "---|")
    for run in runs:
        sph = json.load(open(run + "/report.json"))["sph"]
        dx = sph["particle_spacing_m"]
        pts = soil_points(run)
        h, _ = profile(pts, dx, width)
        print("| %s | %g | %.3f | %s | %.4f |" % (
            run, 1000 * dx, sph["deposit"]["final_length_m"],
            " | ".join("%.3f" % toe(h, width, t) for t in thicknesses), max(p[1] for p in pts) + dx / 2))


def frame_time(path):
    """The simulated time of a frame [s], from its ASCII TimeValue."""
    head = open(path, "rb").read(2000)
    m = re.search(rb'Name="TimeValue"[^>]*>\s*([-+0-9.eE]+)', head)
    return float(m.group(1)) if m else float("nan")


def run_frames(run):
    """The run's VTK frames in order; exits with a message when it has none."""
    frames = sorted(glob.glob(run + "/frames/frame_*.vtu"))
    if not frames:
        sys.exit("deposit_profile: no frames/frame_*.vtu in " + run)
    return frames


def followed(frames, ids, fields):
    """For every frame: its time [s], its arrays `fields` (with "id") and the rows of the particles `ids` in them."""
    for frame in frames:
        a = read_vtu(frame, fields)
        at = {pid: k for k, pid in enumerate(a["id"])}
        yield frame_time(frame), a, [at[i] for i in ids]


def track_front(run, count):
    """The `count` furthest soil particles of the last frame, by id, through every frame of the run."""
    frames = run_frames(run)
    last = read_vtu(frames[-1], ("Points", "kind", "id"))
    soil = sorted((p[0], i) for p, k, i in zip(last["Points"], last["kind"], last["id"]) if k == 0)
    ids = [i for _, i in soil[-count:]]
    fields = ("Points", "id", "velocity", "stress_xx", "stress_yy")
    print("| t (s) | mean x (m) | mean y (mm) | mean vx (m/s) | mean sigma_yy (Pa) | without stress |")
    print("|---|---|---|---|---|---|")
    for t, a, rows in followed(frames, ids, fields):
        n = len(rows)
        free = sum(1 for k in rows if abs(a["stress_xx"][k]) + abs(a["stress_yy"][k]) < 1.0)
        print("| %.3f | %.3f | %.1f | %.3f | %.1f | %d of %d |" % (
            t, sum(a["Points"][k][0] for k in rows) / n, 1000 * sum(a["Points"][k][1] for k in rows) / n,
            sum(a["velocity"][k][0] for k in rows) / n, sum(a["stress_yy"][k] for k in rows) / n, free, n))


def track_region(run, box):
    """The moving particles (kind 0) inside `box` (x0, x1, y0, y1) [m] in the first frame, by id, through every frame."""
    x0, x1, y0, y1 = box
    frames = run_frames(run)
    first = read_vtu(frames[0], ("Points", "kind", "id"))
    ids = [i for p, k, i in zip(first["Points"], first["kind"], first["id"])
           if k == 0 and x0 < p[0] < x1 and y0 < p[1] < y1]
    if not ids:
        sys.exit("deposit_profile: no moving particle starts in the box %g < x < %g, %g < y < %g m" % box)
    fields = ("id", "displacement", "viscosity", "smoothed_pressure")
    print("%d grains start in %g < x < %g m, %g < y < %g m" % ((len(ids),) + tuple(box)))
    print("| t (s) | mean viscosity (Pa s) | mean p' (Pa) | mean displacement x (mm) | mean displacement y (mm) |")
    print("|---|---|---|---|---|")
    for t, a, rows in followed(frames, ids, fields):
        n = len(rows)
        print("| %.2f | %.1f | %.0f | %.1f | %.1f |" % (
            t, sum(a["viscosity"][k] for k in rows) / n,
            sum(a["smoothed_pressure"][k] for k in rows) / n,
            1000 * sum(a["displacement"][k][0] for k in rows) / n, 1000 * sum(a["displacement"][k][1] for k in rows) / n))


def unyielded_zone(run, mu_min, width):
    """Per frame and x bin: the material's top, the unyielded grains' (viscosity >= mu_min) lowest and highest centre
    and how many yielded grains lie above the highest unyielded one [m]."""
    for frame in run_frames(run):
        a = read_vtu(frame, ("Points", "kind", "viscosity"))
        bins = {}
        for p, k, mu in zip(a["Points"], a["kind"], a["viscosity"]):
            if k == 0:
                bins.setdefault(int(p[0] // width), []).append((p[1], mu))
        print("t = %.2f s: x bin (m): top of the material / unyielded from .. to (m) / yielded grains above it" %
              frame_time(frame))
        cells = []
        for b in sorted(bins):
            ys = bins[b]
            top = max(y for y, _ in ys)
            rigid = [y for y, mu in ys if mu >= mu_min]
            if rigid:
                above = sum(1 for y, mu in ys if y > max(rigid) and mu < mu_min)
                cells.append("%.3f: %.3f / %.3f..%.3f / %d" % (b * width, top, min(rigid), max(rigid), above))
            else:
                cells.append("%.3f: %.3f / none" % (b * width, top))
        print("  " + "; ".join(cells))


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "--unyielded":
        unyielded_zone(sys.argv[4], float(sys.argv[2]), float(sys.argv[3]))
        return
    if len(sys.argv) == 7 and sys.argv[1] == "--region":
        track_region(sys.argv[6], tuple(float(v) for v in sys.argv[2:6]))
        return
    if len(sys.argv) == 4 and sys.argv[1] == "--track":
        track_front(sys.argv[3], int(sys.argv[2]))
        return
    if len(sys.argv) >= 3 and sys.argv[1] == "--toes":
        toes_at_thickness(sys.argv[2:])
        return
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    dx = float(sys.argv[1])
    runs = sys.argv[2:]
    ref = None
    print("| run | toe, 1 dx thick (m) | toe, 2 dx (m) | toe, 5 dx (m) | front (m) | height (m) | profile difference |")
    print("|---|---|---|---|---|---|---|")
    for run in runs:
        pts = soil_points(run)
        h, width = profile(pts, dx)
        if ref is None:
            ref = h
        keys = set(h) | set(ref)
        diff = sum(abs(h.get(k, 0.0) - ref.get(k, 0.0)) for k in keys) / sum(ref.values())
        xs = sorted((p[0] for p in pts), reverse=True)
        print("| %s | %.3f | %.3f | %.3f | %.3f | %.4f | %.1f %% |" % (
            run, toe(h, width, dx), toe(h, width, 2 * dx), toe(h, width, 5 * dx), xs[2] + dx / 2,
            max(p[1] for p in pts) + dx / 2, 100 * diff))


if __name__ == "__main__":
    main()
