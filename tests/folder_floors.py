#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The source folders point one way (docs/architecture.md, "Floors"): a file includes
its own floor and those below it, never one above. Lists every include that climbs and
fails if there is one."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Each folder and the project folders its files may include.
FLOORS = {
    "core": ["core"],
    "app/render": ["core", "app/render"],
    "app/edit": ["core", "app/render", "app/edit"],
    "app/tools": ["core", "app/render", "app/edit", "app/tools"],
    "app/editor": ["core", "app/render", "app/edit", "app/tools", "app/editor", "app/cli"],
    "app/cli": ["core", "app/cli"],
    "app/python": ["core"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"((?:core|app)/[^"]+)"', re.M)

climbs = []
checked = 0
for folder, allowed in FLOORS.items():
    files = [p for p in (ROOT / folder).rglob("*") if p.suffix in (".h", ".cpp")]
    if not files:
        climbs.append(f"{folder}: no sources (the floors are out of date)")
    for path in files:
        checked += 1
        for target in INCLUDE.findall(path.read_text(encoding="utf-8")):
            if not any(target.startswith(a + "/") for a in allowed):
                climbs.append(f"{path.relative_to(ROOT)} includes {target}")
if climbs:
    print("includes that climb a floor:\n  " + "\n  ".join(climbs))
    sys.exit(1)
print(f"{checked} files, no include climbs a floor")
