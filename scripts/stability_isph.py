"""The ISPH rows of the stability matrix (cases/stability/isph_*.json, docs/stability.md): their physical checks and
the text of their table cells. Imported by scripts/stability_matrix.py, which runs the cases; each check returns a
list of (passed, text)."""
import copy


def isph_block(report):
    return (report or {}).get("isph") or {}


def fmt(x, digits=3):
    if x is None:
        return "null"
    if abs(x) >= 1e5 or (abs(x) < 1e-3 and x != 0):
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"


def finished(result, report):
    """Exit 0, to the end time, the fluid's mass accounted for: the mass at the end plus the mass removed when it
    left the domain (through a wall) is the mass at the start, to 1e-12 relative."""
    isph = isph_block(report)
    mass = isph.get("fluid_mass_kg_per_m") or {}
    start, end = mass.get("start"), mass.get("end")
    removed = (isph.get("fluid_removed") or {}).get("mass_kg_per_m", 0.0)
    if end is not None:
        end += removed
    return [(result["status"] == 0, f"exit status {result['status']}"),
            (isph.get("status") == "ok" and isph.get("stopped_because") == "end_time",
             f"isph status {isph.get('status')}, stopped because {isph.get('stopped_because')}"),
            (start is not None and end is not None and abs(end - start) <= 1e-12 * start,
             f"fluid mass {fmt(start)} -> {fmt(end)} kg/m (with {fmt(removed)} kg/m removed)")]


def warns(report, key):
    return any(key in w for w in isph_block(report).get("warnings") or [])


def warning_check(report, key):
    found = [w for w in isph_block(report).get("warnings") or [] if key in w]
    return (bool(found), "report warns: " + (found[0] if found else f"no warning naming {key}"))


def past_walls(report):
    return (isph_block(report).get("fluid_past_walls") or {}).get("most")


def past_walls_reported(report):
    """The walls' count is consistent: the most at one step at least the count at the end, a first time exactly when
    there was one, and then the warning naming analyses.isph.tank."""
    past = isph_block(report).get("fluid_past_walls") or {}
    most, end = past.get("most"), past.get("end")
    ok = most is not None and end is not None and most >= end and ("first_at_s" in past) == (most > 0) and \
        warns(report, "analyses.isph.tank") == (most > 0)
    return (ok, f"particles past the walls reported consistently: most {most} at one step, {end} at the end" +
            (", with the first time and the warning" if most else ", no warning"))


def no_particle_past_walls(report):
    most = past_walls(report)
    return (most == 0, f"fluid particles past the walls at any step: {most} (0: the walls held the fluid)")


def still_water_checks(report):
    """Hydrostatics (the floor pressure between the two places P = 0 can sit, the top row's centres and the
    surface) and a fluid at rest (speed at the end below 5 % of sqrt(g H))."""
    tank = isph_block(report).get("still_tank") or {}
    ratio, speed = tank.get("floor_pressure_ratio"), tank.get("max_speed_end_ratio")
    return [(ratio is not None and 0.970 <= ratio <= 1.005,
             f"floor pressure {tank.get('floor_pressure_Pa', float('nan')):.0f} Pa = {fmt(ratio, 4)} rho0 g H "
             f"(0.970 to 1.005; 1 - dx/2H = {fmt(tank.get('expected_ratio'), 4)})"),
            (speed is not None and speed < 0.05,
             f"largest speed at the end {fmt(tank.get('max_speed_end_m_s'))} m/s = {fmt(100 * speed if speed is not None else None)} "
             f"% of sqrt(g H) (< 5 %)")]


def without_key_checks(stem, scene, report, key, reference_run, compare):
    """The same scene without analyses.isph.<key>, run beside it; compare(report, reference) gives the checks."""
    variant = copy.deepcopy(scene)
    del variant["analyses"]["isph"][key]
    reference = reference_run(stem, variant, 300, "run")
    if not reference or "isph" not in reference:
        return [(False, f"the reference run without {key} wrote no report")]
    return compare(isph_block(report), isph_block(reference))


def same_run(run, ref):
    return [(not any("analyses.isph.max_time_step_s" in w for w in ref.get("warnings") or []),
             "without the bound: no warning about it"),
            (run.get("steps") == ref.get("steps"), f"{run.get('steps')} steps, as without the bound ({ref.get('steps')})"),
            (run.get("front_x_m") == ref.get("front_x_m"),
             f"the same end state: front {fmt(run.get('front_x_m'), 6)} m (without the bound {fmt(ref.get('front_x_m'), 6)} m)")]


def larger_density_error(run, ref):
    checks = [past_walls_reported({"isph": ref})]
    for key in ("max_density_error", "mean_density_error"):
        a, b = run.get(key), ref.get(key)
        checks.append((a is not None and b is not None and a > b,
                       f"{key} {fmt(a)} above the default cfl 0.1's {fmt(b)}"))
    return checks


def finished_without(stem, scene, key, reference_run):
    """The same scene without analyses.isph.<key> (at its default), run beside it: its isph block and checks that
    it finished."""
    variant = copy.deepcopy(scene)
    del variant["analyses"]["isph"][key]
    reference = reference_run(stem, variant, 300, "run")
    return isph_block(reference), [(c[0], f"without {key}: " + c[1]) for c in finished({"status": 0}, reference)]


def isph_checks(stem, scene, result, report, check_refused, reference_run):
    """The checks of the ISPH rows."""
    if stem == "isph_cfl_beyond_limit":
        return check_refused(result, ["analyses.isph.cfl", "(0, 0.5]", "0.8"])
    checks = finished(result, report)
    isph = isph_block(report)
    if stem == "isph_surface_beta_low_dam_break":
        # it blew up at t = 0.180 s before decisions D21 and D23 (docs/isph.md); it runs to its end since
        end_time = scene["analyses"]["isph"]["end_time_s"]
        simulated = isph.get("simulated_time_s")
        removed = (isph.get("fluid_removed") or {}).get("particles")
        checks += [(simulated is not None and abs(simulated - end_time) <= 1e-9 * end_time,
                    f"simulated {fmt(simulated)} s of {fmt(end_time)} s"),
                   (removed == 0, f"fluid particles removed through a wall: {removed}"),
                   no_particle_past_walls(report), warning_check(report, "analyses.isph.surface_beta")]
    elif stem == "isph_max_time_step_above_limits":
        # max_time_step_s far above the CFL limit at rest, C sqrt(dx/g) (C = 0.1, the default cfl): it never applies
        bound = 0.1 * (scene["analyses"]["isph"]["particle_spacing_m"] / 9.81) ** 0.5
        largest = isph.get("largest_time_step_s")
        checks.append((largest is not None and largest <= bound * (1 + 1e-9),
                       f"largest time step {fmt(largest)} s <= C sqrt(dx/g) = {fmt(bound)} s"))
        checks.append(warning_check(report, "analyses.isph.max_time_step_s"))
        checks.append(("isph: warning: analyses.isph.max_time_step_s" in result["output"],
                       "the warning is printed on stderr"))
        checks += without_key_checks(stem, scene, report, "max_time_step_s", reference_run, same_run)
    elif stem == "isph_explicit_large_step":
        error = isph.get("front_error") or {}
        checks.append((error.get("rms_relative_error") is not None and error.get("points") == 14,
                       f"front error against the table's {error.get('points')} points (14) reported: "
                       f"{fmt(error.get('rms_relative_error'))} "
                       f"({fmt(error.get('rms_relative_error_shifted'))} with dT = {error.get('shift_T')})"))
        checks.append(past_walls_reported(report))
        checks += without_key_checks(stem, scene, report, "cfl", reference_run, larger_density_error)
    elif stem in ("isph_surface_beta_low", "isph_surface_beta_high"):
        checks.append(warning_check(report, "analyses.isph.surface_beta"))
        checks += still_water_checks(report)
        checks.append(no_particle_past_walls(report))
        if stem == "isph_surface_beta_low":
            middle, middle_checks = finished_without(stem, scene, "surface_beta", reference_run)
            checks += middle_checks
            checks.append((not any("analyses.isph.surface_beta" in w for w in middle.get("warnings") or []),
                           "at the default surface_beta: no warning about it"))
    elif stem == "isph_splash_wall":
        # before the wall clearance (docs/isph.md D23) two particles went past a wall at t = 0.56 s at this spacing
        contacts = isph.get("wall_contacts")
        checks += [past_walls_reported(report), no_particle_past_walls(report),
                   (contacts is not None and contacts > 0, f"the particles the clearance put back are counted: "
                                                           f"{contacts} wall contacts")]
    return checks


def result_text(report):
    isph = isph_block(report)
    text = (f"front {fmt(isph.get('front_x_m'))} m; density error max {fmt(isph.get('max_density_error'))}, "
            f"mean {fmt(isph.get('mean_density_error'))}; largest dt {fmt(isph.get('largest_time_step_s'))} s; "
            f"past the walls {past_walls(report)}")
    tank = isph.get("still_tank")
    if tank:
        text += (f"; floor {fmt(tank.get('floor_pressure_ratio'), 4)} rho0 g H, speed at the end "
                 f"{fmt(tank.get('max_speed_end_m_s'))} m/s")
    error = isph.get("front_error")
    if error:
        text += f"; front error {fmt(error.get('rms_relative_error'))} (shifted {fmt(error.get('rms_relative_error_shifted'))})"
    return text


def outcome_text(report):
    warnings = isph_block(report).get("warnings") or []
    return "finished" + (" with warning: " + " / ".join(warnings) if warnings else "")
