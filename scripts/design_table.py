#!/usr/bin/env python3
"""The table of docs/validation.md's "Recommended variations", from the design.json files
that scripts/design_study.sh leaves in DIR/sample<k>_<test>/, written between the report's
`<!-- generated:begin designs -->` and `<!-- generated:end -->` markers.

    python3 scripts/design_table.py DIR DOC
"""
import json
import pathlib
import re
import sys

GOAL_PP = 2.0  # standard schedules worse than this must be halved or brought near the floor
FLOOR_MARGIN_PP = 1.0


def minutes(times):
    return ", ".join(f"{t:g}" for t in times)


def depth(schedule):
    return f" at {schedule['depth_fraction']:.2f} H" if "depth_fraction" in schedule else ""


def goal(design, source):
    standard = design["standard"][source]["worst_error_pp"]
    designed = design["designed"][source]["worst_error_pp"]
    # The stricter of the floors: at the standard's depth and, when it differs, the designed one.
    floor = design["floor"]["reference"]["worst_error_pp"]
    if "depth_floor" in design:
        floor = min(floor, design["depth_floor"]["reference"]["worst_error_pp"])
    if standard <= GOAL_PP:
        return "no goal (standard within 2 pp)" if designed <= standard + 1e-9 else "worse"
    if designed <= standard / 2:
        return "halved"
    if designed <= floor + FLOOR_MARGIN_PP:
        return "within 1 pp of the floor"
    return "missed"


def floor_cell(design):
    cell = f"{design['floor']['reference']['worst_error_pp']:.2f}"
    if "depth_floor" in design:
        cell += (f" ({design['depth_floor']['reference']['worst_error_pp']:.2f}"
                 f"{depth(design['depth_floor'])})")
    return cell


def table(folder):
    rows = [
        "| sample | test | standard schedule (min) | designed schedule (min) | worst error, "
        "standard → designed: reference (pp) | DEM (pp) | floor (pp; at the designed depth) "
        "| goal (reference / DEM) |",
        "|---|---|---|---|---|---|---|---|",
    ]
    dem = None
    for path in sorted(pathlib.Path(folder).glob("sample*_*/design.json")):
        d = json.loads(path.read_text())
        sample = path.parent.name.split("_")[0]
        ref = (d["standard"]["reference"], d["designed"]["reference"])
        has_dem = "dem" in d["standard"]
        dem = d.get("dem", dem)
        dem_cell = (
            f"{d['standard']['dem']['worst_error_pp']:.2f} → {d['designed']['dem']['worst_error_pp']:.2f}"
            if has_dem else "-")
        rows.append(
            f"| {sample} | {d['test']} | {minutes(d['standard']['times_min'])}{depth(d['standard'])} "
            f"| {minutes(d['designed']['times_min'])}{depth(d['designed'])} "
            f"| {ref[0]['worst_error_pp']:.2f} → {ref[1]['worst_error_pp']:.2f} "
            f"(at {ref[0]['at_diameter_um']:.1f} → {ref[1]['at_diameter_um']:.1f} µm) "
            f"| {dem_cell} | {floor_cell(d)} "
            f"| {goal(d, 'reference')} / {goal(d, 'dem') if has_dem else '-'} |")
    if len(rows) == 2:
        raise SystemExit(f"design_table.py: no design.json under {folder}")
    note = ""
    if dem:
        note = (f"\n\nDEM: {dem['particles']} particles per run, the same run (same seed) read "
                "with both schedules.")
    return "\n".join(rows) + note


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    folder, doc = sys.argv[1], pathlib.Path(sys.argv[2])
    text = doc.read_text()
    pattern = re.compile(r"(<!-- generated:begin designs -->\n).*?(<!-- generated:end -->)", re.S)
    if not pattern.search(text):
        raise SystemExit(f"design_table.py: {doc} has no 'generated:begin designs' marker")
    doc.write_text(pattern.sub(lambda m: m.group(1) + table(folder) + "\n" + m.group(2), text))
    print(table(folder))


if __name__ == "__main__":
    main()
