#!/usr/bin/env python3
"""Every file the sources and docs cite exists, and none cites a note outside the repository.

A comment or a page that sends the reader to a file that is not there is a broken promise:
this check fails on any path under the repository's top folders that does not exist, on any
bare header or source name (`something.h`) that no file in the repository carries, and on any
citation of DESIGN.md (the design note the project grew from; what it fixed is in docs/).
"""
import pathlib
import re
import subprocess
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
tops = "core|app|render|bench|tests|docs|scripts|scenes|python|packaging"
path_re = re.compile(r"(?<![\w/.-])((?:%s)/[A-Za-z0-9_./-]*[A-Za-z0-9_])" % tops)
bare_re = re.compile(r"(?<![\w/.<-])([a-z][a-z0-9_]*\.(?:h|cpp))\b")
placeholder = re.compile(r"NN|<|>|\*|\.\.\.|XXXX")

tracked = subprocess.run(["git", "-C", str(root), "ls-files"], capture_output=True, text=True,
                         check=True).stdout.split()
scanned = [root / t for t in tracked
           if pathlib.Path(t).suffix in {".h", ".cpp", ".md", ".py", ".sh", ".txt", ".cmake"}]
names = {pathlib.Path(t).name for t in tracked}
problems = []
for f in scanned:
    rel = f.relative_to(root)
    if rel.parts[0] == "tests" and rel.name == "check_citations.py":
        continue
    for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
        if "DESIGN.md" in line:
            problems.append(f"{rel}:{n}: cites DESIGN.md, which is not in the repository")
        for m in path_re.finditer(line):
            cited = m.group(1).rstrip(".")
            following = line[m.end():m.end() + 1]
            if placeholder.search(cited) or (following and following in "$%{<[*"):
                continue  # a template (scenes/sample$k.toml), not a file
            target = root / cited
            # A folder, a file, or a file named without its extension (a program's source).
            if not (target.exists() or list(target.parent.glob(target.name + ".*"))):
                problems.append(f"{rel}:{n}: cites {cited}, which does not exist")
        for m in bare_re.finditer(line):
            if m.group(1) not in names:
                problems.append(f"{rel}:{n}: cites {m.group(1)}, which no file is called")
print("\n".join(problems))
sys.exit(1 if problems else 0)
