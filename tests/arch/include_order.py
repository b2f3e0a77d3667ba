#!/usr/bin/env python3
"""Every #include "essi/..." in core/ follows core/LAYERS: a file includes headers of its own layer or of a
lower one (listed before it), never of a higher one. And the viewer's dependency runs one way: web/app/ and
web/render/ include nothing of web/platform/ (docs/architecture.md, "The platform interface"). Prints each
violation with its file and line; exits 1 if there is any, or if a folder or a public header has no layer."""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
CORE = os.path.join(ROOT, "core")
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]+"essi/([A-Za-z0-9_]+\.hpp)"', re.M)
PLATFORM_INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]+"(platform/[^"]+)"', re.M)


def read_layers():
    """[(layer, folders, headers)] in order, from core/LAYERS."""
    layers = []
    with open(os.path.join(CORE, "LAYERS"), encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            name, _, rest = line.partition(":")
            folders, _, headers = rest.partition("|")
            if not name or not folders.split():
                sys.exit(f"core/LAYERS:{n}: expected 'LAYER: FOLDERS... [| HEADERS...]'")
            layers.append((name.strip(), folders.split(), headers.split()))
    return layers


def platform_includes():
    """The includes of web/platform/ from web/app/ and web/render/ (none when there is no web/)."""
    problems, files = [], 0
    for folder in ("app", "render"):
        for dirpath, _, names in os.walk(os.path.join(ROOT, "web", folder)):
            for name in sorted(names):
                if not name.endswith((".cpp", ".hpp")):
                    continue
                files += 1
                path = os.path.join(dirpath, name)
                with open(path, encoding="utf-8") as f:
                    text = f.read()
                for m in PLATFORM_INCLUDE.finditer(text):
                    line = text.count("\n", 0, m.start()) + 1
                    problems.append(f"{os.path.relpath(path, ROOT)}:{line}: includes {m.group(1)} from web/{folder}/ "
                                    f"(web/platform/ includes the app, not the reverse: docs/architecture.md)")
    return problems, files


def main():
    layers = read_layers()
    rank_of_folder, rank_of_header, problems = {}, {}, []
    for rank, (_, folders, headers) in enumerate(layers):
        for folder in folders:
            rank_of_folder[folder] = rank
        for h in headers:
            rank_of_header[h] = rank
    sources = []
    for folder in sorted(os.listdir(CORE)):
        path = os.path.join(CORE, folder)
        if not os.path.isdir(path) or folder == "include":
            continue
        if folder not in rank_of_folder:
            problems.append(f"core/{folder}/: no layer in core/LAYERS")
            continue
        for dirpath, _, files in os.walk(path):
            for name in sorted(files):
                if name.endswith((".cpp", ".hpp")):
                    sources.append((rank_of_folder[folder], os.path.join(dirpath, name)))
                    stem = name[:-4]
                    if name.endswith(".cpp") and os.path.exists(os.path.join(CORE, "include", "essi", stem + ".hpp")):
                        rank_of_header.setdefault(stem + ".hpp", rank_of_folder[folder])
    for name in sorted(os.listdir(os.path.join(CORE, "include", "essi"))):
        if name not in rank_of_header:
            problems.append(f"core/include/essi/{name}: no layer (no {name[:-4]}.cpp; name it in core/LAYERS)")
        else:
            sources.append((rank_of_header[name], os.path.join(CORE, "include", "essi", name)))
    for rank, path in sources:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for m in INCLUDE.finditer(text):
            target = rank_of_header.get(m.group(1))
            if target is not None and target > rank:
                line = text.count("\n", 0, m.start()) + 1
                problems.append(f"{os.path.relpath(path, ROOT)}:{line}: includes essi/{m.group(1)} of layer "
                                f"'{layers[target][0]}' from layer '{layers[rank][0]}' (core/LAYERS: only its own "
                                f"layer and those before it)")
    web_problems, web_files = platform_includes()
    problems += web_problems
    for p in problems:
        print(p)
    print(f"include_order: {len(sources) + web_files} files, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
