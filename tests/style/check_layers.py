#!/usr/bin/env python3
"""Core's folders depend on each other one way only: the map below, written down first.

Each folder of core/ may include the folders listed for it and no other; in particular only
core/scene (the scene's own loader, schema and checks) and core/run (where a Scene is taken
apart into each stage's setup) may include the scene; app/ and render/ see the engine only
through core/model and core/run. A new arrow is a design decision: make
it here, in the open, not by an #include.
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
low = {"model", "physics"}
allowed = {
    "model": set(),
    "stats": set(),
    "physics": {"model"},
    "lab": low,
    "sample": low,
    "fields": low,
    "engine": low,
    "instruments": low | {"fields"},
    "reference": low | {"fields", "instruments"},
    "observe": low | {"fields", "instruments", "reference"},
    "invert": low | {"fields", "instruments", "reference", "lab", "stats"},
    "design": low | {"fields", "instruments", "reference", "sample", "invert", "stats"},
    "scene": low | {"sample", "engine", "instruments", "fields"},
    "run": low | {"sample", "engine", "fields", "instruments", "reference", "observe", "scene",
                  "design", "stats"},
}
include = re.compile(r'#include "core/([a-z_]+)/')
problems = []
for folder in sorted(p for p in (root / "core").iterdir() if p.is_dir()):
    name = folder.name
    if name not in allowed:
        problems.append(f"core/{name}: a folder the layer map does not know; add it there")
        continue
    for f in sorted(folder.rglob("*")):
        if f.suffix not in {".h", ".cpp"}:
            continue
        for n, line in enumerate(f.read_text().splitlines(), 1):
            m = include.search(line)
            if m and m.group(1) != name and m.group(1) not in allowed[name]:
                problems.append(f"{f.relative_to(root)}:{n}: core/{name} includes core/"
                                f"{m.group(1)}, against the layer map")
# Outside core, the engine is seen through its public face (core/model's Snapshot and
# EngineStats, core/run's Simulation), never its internals.
for top in ("app", "render", "python"):
    for f in sorted((root / top).rglob("*")):
        if f.suffix in {".h", ".cpp"}:
            for n, line in enumerate(f.read_text().splitlines(), 1):
                if '#include "core/engine/' in line:
                    problems.append(f"{f.relative_to(root)}:{n}: {top}/ includes the engine's "
                                    "internals; use core/model or core/run")
print("\n".join(problems))
sys.exit(1 if problems else 0)
