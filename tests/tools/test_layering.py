#!/usr/bin/env python3
"""The core's folders form layers (docs/house-rules.md, "Where things go"): a file may include its
own folder and the folders before it in LAYERS, never one after it; the core
includes neither femto_view (view/, analysis/) nor any plugin or integrator.
Usage: test_layering.py SOURCE_DIR (exit 1 naming each include that breaks it)."""
import pathlib
import re
import sys

# Folders of src/core/femto in order; folders on one rank may not include each other.
LAYERS = [["base"], ["math"], ["core"], ["image"], ["time"], ["render"], ["scattering", "lights"],
          ["transport"], ["loop"], ["film"], ["xml"]]
RANK = {folder: rank for rank, folders in enumerate(LAYERS) for folder in folders}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]femto/([a-z_]+)/', re.M)


def violations(source_dir):
    core = source_dir / "src" / "core" / "femto"
    for path in sorted(core.rglob("*")):
        if path.suffix not in (".h", ".cpp", ".inl"):
            continue
        folder = path.relative_to(core).parts[0]
        if folder not in RANK:
            yield f"{path}: folder '{folder}' has no place in the layering (add it to LAYERS and docs/house-rules.md)"
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        for match in INCLUDE.finditer(text):
            target = match.group(1)
            line = text.count("\n", 0, match.start()) + 1
            if target not in RANK:
                yield f"{path}:{line}: the core includes femto/{target}/, which is not part of the core"
            elif target != folder and RANK[target] >= RANK[folder]:
                yield f"{path}:{line}: {folder}/ includes femto/{target}/, a layer at or above its own"
    for path in sorted((source_dir / "src" / "core").rglob("*")):
        if path.suffix in (".h", ".cpp") and re.search(r'#\s*include\s*[<"](transient_beams|plugins|integrators)/',
                                                       path.read_text(encoding="utf-8", errors="replace")):
            yield f"{path}: the core includes a plugin or integrator header"


def main():
    found = list(violations(pathlib.Path(sys.argv[1])))
    for v in found:
        print(v)
    print(f"{len(found)} include(s) against the layering")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
